#pragma once
// Core cleanup before the pad (issue 12): removes the core hexes that stick out and adds the
// hexes that fill one-hex notches, so that the pad does not have to cover spikes, ridges and
// grooves one hex wide (mesher/README.md, "Core cleanup").
//
// Input : cells (M, 8) VTK hexes of a conforming mesh (vertex ids; for the pipeline the whole
//         clipped dual), the selection `in` (M flags, the core), `flippable` (M flags: core
//         hexes that may leave, other hexes that may join: for the pipeline, those deep
//         enough inside the surface, select_core.hpp clean_core_selection).
// Output: CoreCleanup — the cleaned selection and what changed.
//
// A hex is exposed when, of its 6 faces, the ones on the other side (for a core hex: faces
// on the core boundary; for a hex outside the core: faces shared with the core) are 4 or
// more, or 3 with two opposite ones among them (a ridge or a groove one hex wide). The
// three-face corner (three mutually adjacent faces) is the staircase's ordinary convex or
// concave corner and stays. An exposed flippable core hex leaves the core, an exposed
// flippable hex outside joins it, each only if the flip is simple (core_topology.hpp SelectionFlips:
// the hex meets the other side in a closed disk of its faces), so components, Euler
// characteristics and manifoldness of the core boundary are unchanged; an exposed hex whose
// flip is not simple is refused (counted). Only hexes exposed in the given selection are
// candidates (and flip only while still exposed), and hexes that flips leave with 5 or 6
// faces on the other side (spikes): following every hex a flip exposes would erode a plate
// one hex thick from its rim down to one hex. Each hex flips at most once (so the loop ends
// and never oscillates between a spike and its notch); each sweep adds first, then removes,
// each in index order (a hex beside a fillable notch is then not removed as a one-hex
// wall), and sweeps are repeated until no hex flips (a fixed point): the result depends on
// the input only.
#include <array>
#include <cstddef>
#include <vector>

namespace dualhex::mesher {

struct CoreCleanup {
    std::vector<char> in;  ///< (M) the cleaned selection
    std::size_t removed = 0, added = 0;
    std::size_t refused = 0;  ///< exposed hexes left as they are: the flip would change the topology
    std::size_t sweeps = 0;
};

[[nodiscard]] CoreCleanup clean_core(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                                     const std::vector<char>& in, const std::vector<char>& flippable);

/// Whether a hex with `other` (bit f: face f in geometry::kHexFaces order lies on the other
/// side) is exposed, as defined above.
[[nodiscard]] bool exposed_faces(unsigned other);

}  // namespace dualhex::mesher
