#pragma once
// The mesher layer in one include: the pipeline and each of its stages.
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/extract.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/mesh_report.hpp"
#include "dualhex/mesher/project.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "dualhex/mesher/smooth.hpp"
#include "dualhex/mesher/untangle.hpp"
