#pragma once
// Topology-controlled core growth: the hexes of a candidate selection, added one at a time
// from a seed so that the selection's topology changes only where asked.
//
// Input : cells (M, 8) VTK hexes of a conforming mesh (vertex ids), the candidate flags
//         (M), a score per hex (M; deeper inside = larger: grown first), the number of
//         face-connected parts to seed (the input surface's components) and the number of
//         handles the result may have (sum over the input's components of (2 - chi) / 2).
// Output: flags (M), a subset of the candidates.
//
// Why: a hex c added to a set S whose boundary is a closed 2-manifold keeps S's topology
// and manifoldness iff c meets S exactly in a closed disk made of c's faces (every corner
// and edge of c that S touches lies on a face c shares with S): a "simple" hex. The
// intersection is then a union of faces of a cube with Euler characteristic 1. Growing only
// by simple hexes from one seed per part gives balls; a hex that meets S in two opposite
// faces (the only way a union of a cube's faces is two disjoint disks) adds one handle, and
// is taken, deepest first, only while handles are still allowed. Thin bridges where the
// rule's selection opened tunnels the surface does not have are left out.
#include <array>
#include <cstddef>
#include <vector>

namespace dualhex::mesher {

[[nodiscard]] std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells,
                                                        std::size_t vertex_count, const std::vector<char>& candidate,
                                                        const std::vector<double>& score, std::size_t parts,
                                                        std::size_t handles);

}  // namespace dualhex::mesher
