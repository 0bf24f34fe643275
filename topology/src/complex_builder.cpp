#include "dualhex/topology/complex_builder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dualhex {
namespace {

std::uint64_t point_hash(const LatticePoint& p) { return LatticePointHash{}(p); }

}  // namespace

void ComplexBuilder::reserve(std::size_t n_vertices, std::size_t n_faces, std::size_t n_cells) {
    positions_.reserve(n_vertices);
    vertex_table_.reserve(n_vertices);
    face_offsets_.reserve(n_faces + 1);
    face_loops_.reserve(4 * n_faces);
    face_table_.reserve(n_faces);
    cell_offsets_.reserve(n_cells + 1);
    cell_halffaces_.reserve(6 * n_cells);
}

VertexHandle ComplexBuilder::add_vertex(const LatticePoint& p) {
    const std::uint64_t hash = point_hash(p);
    CachedVertex& cached = vertex_cache_[(hash >> 20) & (kVertexCacheSize - 1)];
    if (cached.id >= 0 && cached.p == p) return VertexHandle(cached.id);
    const auto id = static_cast<std::int32_t>(positions_.size());
    const auto [found, inserted] = vertex_table_.insert(
        hash, id, [&](std::int32_t v) { return positions_[static_cast<std::size_t>(v)] == p; });
    if (inserted) positions_.push_back(p);
    cached = {p, found};
    return VertexHandle(found);
}

VertexHandle ComplexBuilder::find_vertex(const LatticePoint& p) const {
    return VertexHandle(vertex_table_.find(point_hash(p), [&](std::int32_t v) { return positions_[static_cast<std::size_t>(v)] == p; }));
}

HalfFaceHandle ComplexBuilder::add_face(std::span<const VertexHandle> loop) {
    if (loop.empty()) throw std::invalid_argument("ComplexBuilder::add_face: empty loop");
    for (VertexHandle v : loop)
        if (!v.valid() || v.index() >= positions_.size())
            throw std::invalid_argument("ComplexBuilder::add_face: unknown vertex " + std::to_string(v.idx));

    // Both walks of the loop from its smallest vertex; the canonical one (hashed) heads
    // towards the smaller neighbour, so all rotations and both directions hash alike.
    const std::size_t n = loop.size();
    const auto start = static_cast<std::size_t>(std::min_element(loop.begin(), loop.end()) - loop.begin());
    forward_.resize(n);
    backward_.resize(n);
    for (std::size_t k = 0, i = start, j = start; k < n; ++k) {
        forward_[k] = loop[i];
        backward_[k] = loop[j];
        i = i + 1 == n ? 0 : i + 1;
        j = j == 0 ? n - 1 : j - 1;
    }
    const std::vector<VertexHandle>& canon = n < 3 || forward_[1] <= backward_[1] ? forward_ : backward_;
    std::uint64_t hash = detail::mix64(n);
    for (VertexHandle v : canon) hash = detail::mix64(hash ^ static_cast<std::uint64_t>(v.idx));

    // The stored loop is the given one rotated to start at its smallest vertex; a later
    // equal loop matches it walking forward (side 0) or backward (side 1).
    auto matches = [&](std::int32_t face, const std::vector<VertexHandle>& walk) {
        const std::uint32_t begin = face_offsets_[static_cast<std::size_t>(face)];
        return face_offsets_[static_cast<std::size_t>(face) + 1] - begin == n &&
               std::equal(walk.begin(), walk.end(), face_loops_.begin() + begin);
    };
    const auto id = static_cast<std::int32_t>(n_faces());
    const auto [found, inserted] =
        face_table_.insert(hash, id, [&](std::int32_t f) { return matches(f, forward_) || matches(f, backward_); });
    if (inserted) {
        face_loops_.insert(face_loops_.end(), forward_.begin(), forward_.end());
        face_offsets_.push_back(static_cast<std::uint32_t>(face_loops_.size()));
        return HalfFaceHandle(FaceHandle(found), 0);
    }
    return HalfFaceHandle(FaceHandle(found), matches(found, forward_) ? 0 : 1);
}

CellHandle ComplexBuilder::add_cell(std::span<const HalfFaceHandle> halffaces) {
    for (HalfFaceHandle h : halffaces)
        if (!h.valid() || h.face().index() >= n_faces())
            throw std::invalid_argument("ComplexBuilder::add_cell: unknown half-face " + std::to_string(h.idx));
    const CellHandle c(n_cells());
    cell_halffaces_.insert(cell_halffaces_.end(), halffaces.begin(), halffaces.end());
    cell_offsets_.push_back(static_cast<std::uint32_t>(cell_halffaces_.size()));
    return c;
}

CellHandle ComplexBuilder::add_cell_from_loops(const std::vector<std::vector<LatticePoint>>& loops) {
    cell_scratch_.clear();
    for (const auto& loop : loops) {
        scratch_.clear();
        for (const LatticePoint& p : loop) scratch_.push_back(add_vertex(p));
        cell_scratch_.push_back(add_face(scratch_));
    }
    return add_cell(cell_scratch_);
}

CellComplex ComplexBuilder::build() const& {
    return CellComplex(positions_, face_offsets_, face_loops_, cell_offsets_, cell_halffaces_);
}

CellComplex ComplexBuilder::build() && {
    return CellComplex(std::move(positions_), std::move(face_offsets_), std::move(face_loops_), std::move(cell_offsets_),
                       std::move(cell_halffaces_));
}

}  // namespace dualhex
