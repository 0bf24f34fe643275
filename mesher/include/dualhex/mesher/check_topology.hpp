#pragma once
// Stage "check": does the finished hex mesh have the input surface's topology?
//
// Input : the final HexMesh (points (N, 3), hexes (M, 8) VTK order) and the input surface.
// Output: TopologyCheck — exact, on vertex ids (geometry/hex_topology.hpp): the mesh
//         boundary is a closed, consistently oriented 2-manifold without face defects
//         (`manifold`), its components and per-component Euler characteristic, the
//         input's, and `matches` = manifold and the same multiset of Euler
//         characteristics (so the same number of components). On a mismatch or a
//         defect, `problems` names it with locations (vertex ids and coordinates; for a
//         topology mismatch, each boundary component's quad count and bounding box).
// It never changes the mesh; the CLI turns !matches into exit 1 unless told to accept.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::mesher {

struct TopologyCheck {
    bool manifold = false;
    std::size_t non_manifold_edges = 0, non_manifold_vertices = 0, misoriented_edges = 0, face_defects = 0;
    std::size_t hex_components = 0;            ///< face-connected
    std::vector<std::int64_t> euler;           ///< per boundary component, decreasing
    std::vector<std::int64_t> input_euler;     ///< per input surface component, decreasing
    bool matches = false;
    std::vector<std::string> problems;         ///< empty iff matches
    [[nodiscard]] std::size_t components() const { return euler.size(); }
    [[nodiscard]] std::size_t input_components() const { return input_euler.size(); }
};

[[nodiscard]] TopologyCheck check_topology(const geometry::HexMesh& mesh, const geometry::TriangleSurface& input);

}  // namespace dualhex::mesher
