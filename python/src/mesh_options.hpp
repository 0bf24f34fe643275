#pragma once
// Keyword arguments of dualhex.mesh() mapped onto mesher::MeshPipelineOptions, in one
// table (mesh_options.cpp, kOptions): adding an option of the pipeline is one line there.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "dualhex/mesher/mesh_pipeline.hpp"

namespace dualhex::python {

namespace py = pybind11;

/// Sets the options named in `kwargs` (with the GIL held). TypeError for an unknown
/// keyword (listing the known ones) or a value of the wrong type, ValueError for a bad
/// value (e.g. balance="medium"); the pipeline itself checks ranges (ValueError too).
void apply_mesh_options(const py::dict& kwargs, mesher::MeshPipelineOptions& options);

/// The keywords apply_mesh_options accepts, in table order.
[[nodiscard]] std::vector<std::string> mesh_option_names();

/// The options as a dict (the defaults when given default options).
[[nodiscard]] py::dict mesh_options_dict(const mesher::MeshPipelineOptions& options);

}  // namespace dualhex::python
