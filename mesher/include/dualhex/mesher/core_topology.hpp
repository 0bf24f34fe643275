#pragma once
// Topology-controlled core growth: the hexes of a candidate selection, added one at a time
// from a seed so that the selection's topology changes only where asked.
//
// Input : cells (M, 8) VTK hexes of a conforming mesh (vertex ids), the candidate flags
//         (M), a score per hex (M; deeper inside = larger: grown first), the number of
//         face-connected parts to seed (the input surface's components) and the number of
//         handles the result may have (sum over the input's components of (2 - chi) / 2);
//         optionally fill flags (M): hexes that may be grown through but are not wanted
//         for themselves (inside the surface, too close to it for the rule).
// Output: flags (M), a subset of candidates + fill.
//
// Why: a hex c added to a set S whose boundary is a closed 2-manifold keeps S's topology
// and manifoldness iff c meets S exactly in a closed disk made of c's faces (every corner
// and edge of c that S touches lies on a face c shares with S): a "simple" hex. The
// intersection is then a union of faces of a cube with Euler characteristic 1. Growing only
// by simple hexes from one seed per part gives balls; a hex that meets S in two opposite
// faces (the only way a union of a cube's faces is two disjoint disks) adds one handle, and
// is taken, deepest first, only while handles are still allowed. Thin bridges where the
// rule's selection opened tunnels the surface does not have are left out — unless fill
// hexes are given: then candidates are grown first (deepest first), fill hexes only when
// no candidate is simple, so the growth runs around a tunnel's rim through the fill, closes
// the tunnel with a disk of fill hexes, and the candidate hexes a cut would have left out
// (the bridge, a thin ear beyond it, a part joined by a thin neck) become simple and join.
// Then the fill is peeled again, shallowest first: a fill hex goes iff it meets the
// complement (every hex not in the set, and the outside of the mesh) in a closed disk of
// its faces — the same test on the other side, so the boundary stays a closed 2-manifold
// and neither side's topology changes. What stays of the fill is what the topology needs:
// the disks that close tunnels, the necks that join parts.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace dualhex::mesher {

[[nodiscard]] std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells,
                                                        std::size_t vertex_count, const std::vector<char>& candidate,
                                                        const std::vector<double>& score, std::size_t parts,
                                                        std::size_t handles);

/// The same, growing through `fill` (M flags, disjoint from candidate) and peeling what of
/// it the topology does not need (see above). An empty `fill` is the function above.
[[nodiscard]] std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells,
                                                        std::size_t vertex_count, const std::vector<char>& candidate,
                                                        const std::vector<char>& fill,
                                                        const std::vector<double>& score, std::size_t parts,
                                                        std::size_t handles);

/// The same test, one hex at a time, on a selection that changes (core_cleanup.hpp): whether
/// hex c may join (c not in) or leave (c in) the selection without changing its boundary's
/// topology and manifoldness — c meets the other side in a closed disk of its faces (for
/// leaving, a face of c that no other hex has is met by the outside of the mesh).
class SelectionFlips {
public:
    SelectionFlips(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count, std::vector<char> in);
    ~SelectionFlips();
    SelectionFlips(const SelectionFlips&) = delete;
    SelectionFlips& operator=(const SelectionFlips&) = delete;
    [[nodiscard]] bool simple(int c) const;  ///< flipping c keeps the topology
    void flip(int c);
    [[nodiscard]] const std::vector<char>& in() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace dualhex::mesher
