#pragma once
// The select-core stage's options and result (select_core.hpp), without the clipped dual's
// headers, so that the pipeline's header can carry them.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

struct CoreOptions {
    double margin = 0.1;  ///< corners at >= margin * (mean edge of the hex) inside the surface
};

struct CoreSelection {
    geometry::HexMesh mesh;                ///< the core (may be empty)
    std::size_t selected_by_rule = 0;      ///< hexes with score > 0
    std::size_t repair_added = 0, repair_removed = 0;
    bool repair_manifold = false;          ///< the repaired selection's boundary is a manifold
    std::size_t repair_remaining_defects = 0;  ///< non-manifold edges + vertices left
    std::vector<std::size_t> kept_components;     ///< hexes per kept component, decreasing
    std::vector<std::size_t> dropped_components;  ///< hexes per dropped component, decreasing
};

}  // namespace dualhex::mesher
