#pragma once
// A configuration installed in the 4x4x4-leaf cube around its application point P = 0
// (non-periodic): octant cubes [-2,0] / [0,2] per axis; bit b of the mask is the octant
// (b&1 ? +x : -x, b&2 ? +y : -y, b&4 ? +z : -z) (grid's configuration convention; this is
// the torus's window around its application point (2,2,2)). The rule's context reaches
// two octant cubes beyond the cube: those are extended outward (each copies the status of
// the nearest octant cube of the configuration). Only the leaves inside the cube are
// built; the checks (3)-(4) apply to the vertices strictly inside it, i.e. those whose
// incident leaves all lie inside (ValidationOptions::interior_filter).
#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {

[[nodiscard]] ConfigurationComplex build_cube_window(std::uint8_t mask, const TransitionRule& rule,
                                                     const ElementLibrary& library);
[[nodiscard]] ConfigurationReport check_cube_window(std::uint8_t mask, const TransitionRule& rule,
                                                    const ElementLibrary& library);

}  // namespace dualhex
