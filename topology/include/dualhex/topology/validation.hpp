#pragma once
// validate(): the checks of DESIGN.md section 4, items 1-4, collecting every violation.
//   (1) faces are simple polygons with >= 3 distinct vertices; each cell's half-faces form
//       a closed, connected, consistently oriented 2-manifold with V - E + F = 2;
//   (2) conforming: each face in 1 (boundary) or 2 cells, used with opposite sides;
//       no two cells with the same half-faces;
//   (3) interior vertices: 6 edges, octahedral link; interior edges: 4 cells in one cycle;
//   (4) the dual cell of each interior vertex is a combinatorial cube, checked on the dual.
// "Interior" is in the sense of Incidence (not on a boundary face). ValidationOptions can
// restrict (3) and (4) to vertices accepted by a filter (edges: both endpoints accepted),
// for windows where only some vertices are fully decided.
#include <array>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"

namespace dualhex {

enum class ViolationKind : int {
    // (1) faces
    FaceTooFewVertices,   // fewer than 3 distinct vertices
    FaceRepeatedVertex,   // a vertex appears twice in the loop: not a simple polygon
    // (1) cells
    CellRepeatedFace,     // the same face listed twice in one cell
    CellOpenEdge,         // an edge used by only one of the cell's half-faces
    CellNonManifoldEdge,  // an edge used by more than two of the cell's half-faces
    CellInconsistentOrientation,  // an edge walked twice in the same direction
    CellNonManifoldVertex,        // the faces around a vertex of the cell are not one cycle
    CellDisconnected,             // the cell's faces fall into several components
    CellNotSphere,                // V - E + F != 2
    // (2) conformity
    FaceUnused,           // a face in no cell
    FaceOvershared,       // a face in more than 2 cells
    FaceSameOrientation,  // a face in 2 cells that both use the same side
    DuplicateCell,        // two cells with identical half-face sets
    // (3) interior valences
    VertexValence,            // interior vertex with != 6 incident edges
    VertexLinkNotOctahedron,  // interior vertex whose link is not an octahedron
    EdgeCellCount,            // interior edge with != 4 incident cells
    EdgeCellsNotCycle,        // the cells around an interior edge do not form one cycle
    // (4) dual
    DualCellNotCube,  // the dual cell of an interior vertex is not a combinatorial cube
    Count
};
inline constexpr std::size_t kViolationKinds = static_cast<std::size_t>(ViolationKind::Count);

/// Stable short name, e.g. "VertexValence".
[[nodiscard]] const char* to_string(ViolationKind kind);

/// One violation; handles not relevant to the kind are invalid (-1).
struct Violation {
    ViolationKind kind{};
    VertexHandle vertex;
    EdgeHandle edge;
    FaceHandle face;
    CellHandle cell;
    std::string message;
};

struct ValidationOptions {
    /// Which vertices get the interior checks (3), (4); empty = all interior vertices.
    /// An interior edge is checked iff both its endpoints are accepted. On a large complex
    /// it is called from several threads at once (validate runs in parallel): it must only read.
    std::function<bool(VertexHandle)> interior_filter;
    /// Skip (3) and (4) entirely (e.g. for a single atomic element).
    bool check_interior = true;
};

struct ValidationReport {
    std::vector<Violation> violations;
    std::size_t checked_faces = 0, checked_cells = 0, checked_vertices = 0, checked_edges = 0;
    std::array<std::size_t, kViolationKinds> per_kind{};

    [[nodiscard]] bool ok() const { return violations.empty(); }
    [[nodiscard]] std::size_t count(ViolationKind k) const { return per_kind[static_cast<std::size_t>(k)]; }
    /// True iff a violation of kind `k` names this entity.
    [[nodiscard]] bool has(ViolationKind k, VertexHandle v) const;
    [[nodiscard]] bool has(ViolationKind k, EdgeHandle e) const;
    [[nodiscard]] bool has(ViolationKind k, FaceHandle f) const;
    [[nodiscard]] bool has(ViolationKind k, CellHandle c) const;

    void add(Violation v);
    /// Summary line, per-kind counts, then up to `max_listed` violations with entity ids
    /// and lattice positions.
    void print(std::ostream& os, const CellComplex& complex, std::size_t max_listed = 50) const;
};

[[nodiscard]] ValidationReport validate(const CellComplex& complex, const ValidationOptions& options = {});

}  // namespace dualhex
