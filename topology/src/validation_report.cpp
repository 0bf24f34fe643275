#include <algorithm>

#include "dualhex/topology/validation.hpp"

namespace dualhex {

const char* to_string(ViolationKind kind) {
    static constexpr const char* kNames[] = {
        "FaceTooFewVertices", "FaceRepeatedVertex", "CellRepeatedFace", "CellOpenEdge",
        "CellNonManifoldEdge", "CellInconsistentOrientation", "CellNonManifoldVertex",
        "CellDisconnected", "CellNotSphere", "FaceUnused", "FaceOvershared", "FaceSameOrientation",
        "DuplicateCell", "VertexValence", "VertexLinkNotOctahedron", "EdgeCellCount",
        "EdgeCellsNotCycle", "DualCellNotCube"};
    static_assert(std::size(kNames) == kViolationKinds);
    const auto i = static_cast<std::size_t>(kind);
    return i < kViolationKinds ? kNames[i] : "?";
}

void ValidationReport::add(Violation v) {
    ++per_kind[static_cast<std::size_t>(v.kind)];
    violations.push_back(std::move(v));
}

bool ValidationReport::has(ViolationKind k, VertexHandle h) const {
    return std::any_of(violations.begin(), violations.end(), [&](const Violation& v) { return v.kind == k && v.vertex == h; });
}
bool ValidationReport::has(ViolationKind k, EdgeHandle h) const {
    return std::any_of(violations.begin(), violations.end(), [&](const Violation& v) { return v.kind == k && v.edge == h; });
}
bool ValidationReport::has(ViolationKind k, FaceHandle h) const {
    return std::any_of(violations.begin(), violations.end(), [&](const Violation& v) { return v.kind == k && v.face == h; });
}
bool ValidationReport::has(ViolationKind k, CellHandle h) const {
    return std::any_of(violations.begin(), violations.end(), [&](const Violation& v) { return v.kind == k && v.cell == h; });
}

void ValidationReport::print(std::ostream& os, const CellComplex& k, std::size_t max_listed) const {
    os << (ok() ? "valid" : "INVALID") << ": " << violations.size() << " violation(s); checked " << checked_faces
       << " faces, " << checked_cells << " cells, " << checked_vertices << " interior vertices, " << checked_edges
       << " interior edges\n";
    for (std::size_t i = 0; i < kViolationKinds; ++i)
        if (per_kind[i]) os << "  " << to_string(static_cast<ViolationKind>(i)) << ": " << per_kind[i] << '\n';
    const std::size_t n = std::min(max_listed, violations.size());
    for (std::size_t i = 0; i < n; ++i) {
        const Violation& v = violations[i];
        os << "  [" << to_string(v.kind) << "]";
        if (v.vertex.valid()) os << " vertex " << v.vertex.idx << ' ' << k.position(v.vertex);
        if (v.edge.valid()) {
            const auto [a, b] = k.edge_vertices(v.edge);
            os << " edge " << v.edge.idx << ' ' << k.position(a) << '-' << k.position(b);
        }
        if (v.face.valid()) {
            os << " face " << v.face.idx << " [";
            for (VertexHandle u : k.face_vertices(v.face)) os << ' ' << k.position(u);
            os << " ]";
        }
        if (v.cell.valid()) os << " cell " << v.cell.idx;
        os << ": " << v.message << '\n';
    }
    if (n < violations.size()) os << "  ... " << violations.size() - n << " more\n";
}

}  // namespace dualhex
