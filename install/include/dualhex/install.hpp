#pragma once
// The install layer in one include: install() and its options, result and errors; the
// leaves' contexts; the installation's post-check; loading the element library.
#include "dualhex/install/install.hpp"
#include "dualhex/install/leaf_contexts.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/install/verify_installation.hpp"
