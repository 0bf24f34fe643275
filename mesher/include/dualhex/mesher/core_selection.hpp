#pragma once
// The select-core stage's options and result (select_core.hpp), without the clipped dual's
// headers, so that the pipeline's header can carry them.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

struct CoreOptions {
    double margin = 0.1;  ///< corners at >= margin * (mean edge of the hex) inside the surface
    /// Fill hexes (grown through to close tunnels and join thin parts, core_topology.hpp):
    /// all corners at >= fill_margin * (mean edge) inside the surface; < 0: no fill.
    double fill_margin = 0.02;
    /// Core cleanup before the pad (core_cleanup.hpp): notches filled with hexes whose
    /// corners are at >= cleanup_margin * (mean edge) inside; exposed core hexes whose
    /// deepest corner is < cleanup_remove_depth * (mean edge) inside removed. Off by
    /// default, and removal 0 when on: removal halves the inverted pad hexes right after the
    /// pad but leaves more flat hexes and hexes below 0.5 at the end on the CAD models, and
    /// fills alone left 46 instead of 38 inverted hexes in the 15-model benchmark
    /// (cgal_armadillo 12 instead of 1; mesher/README.md).
    bool cleanup = false;
    double cleanup_margin = 0.05;
    double cleanup_remove_depth = 0;
};

/// What the core stage decided about one dual hex (for the distance diagnostic).
enum class CoreFate : std::uint8_t {
    Outside,      ///< a corner outside the surface
    Thin,         ///< inside, but a corner closer than margin * h: the rule left it out
    RepairOut,    ///< the rule took it, the manifold repair removed it
    DroppedPart,  ///< in a face-connected part beyond the input's number of components
    Cut,          ///< the topology-controlled regrowth left it out
    Core,         ///< in the core
    FillCore,     ///< in the core as fill (closes a tunnel or joins a part)
    CleanedOut,   ///< the core cleanup removed it (it stuck out of the core)
    CleanedIn,    ///< the core cleanup added it (it filled a notch)
};
inline constexpr std::size_t kCoreFates = 9;
[[nodiscard]] const char* core_fate_name(CoreFate fate);

struct CoreSelection {
    geometry::HexMesh mesh;                ///< the core (may be empty)
    std::vector<std::uint32_t> dual_hex;   ///< (core hexes): the dual hex each core hex is
    std::size_t selected_by_rule = 0;      ///< hexes with score > 0
    std::size_t repair_added = 0, repair_removed = 0;
    bool repair_manifold = false;          ///< the repaired selection's boundary is a manifold
    std::size_t repair_remaining_defects = 0;  ///< non-manifold edges + vertices left
    std::vector<std::size_t> kept_components;     ///< hexes per kept component, decreasing
    std::vector<std::size_t> dropped_components;  ///< hexes per dropped component, decreasing
    /// Euler characteristic per boundary component of the rule's kept parts (before any
    /// regrowth): 2 - chi = twice the handles the regrowth must open or close.
    std::vector<std::int64_t> rule_euler;
    bool topology_controlled = false;  ///< the rule's selection had the wrong topology; regrown (core_topology.hpp)
    std::size_t topology_dropped = 0;  ///< hexes of the rule's selection the regrowth left out
    std::size_t topology_fill = 0;     ///< fill hexes the regrowth kept (closing tunnels, joining parts)
    std::size_t topology_rejoined = 0; ///< rule hexes of dropped parts the regrowth joined again
    /// The core cleanup (core_cleanup.hpp): hexes removed and added, exposed hexes refused
    /// (their flip would change the topology), sweeps to the fixed point; reverted: the
    /// cleaned core's boundary topology differed from the core's before (never expected).
    std::size_t cleanup_removed = 0, cleanup_added = 0, cleanup_refused = 0, cleanup_sweeps = 0;
    bool cleanup_reverted = false;
    /// Per dual hex: its fate and its centroid (the distance diagnostic reads them).
    std::vector<CoreFate> fate;
    std::vector<Eigen::Vector3d> dual_centroid;
    /// Interior edges of the core (not on its boundary) with != 4 hexes: valence -> count.
    /// The pad leaves them as they are (the schemes' valences).
    std::map<int, std::size_t> singular_edge_valences;
};

/// Thrown by the pipeline when no dual hex qualifies for the core: the surface is too thin
/// for the octree's resolution (a larger max depth or a smaller thickness factor may help).
class EmptyCoreError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace dualhex::mesher
