#include "dualhex/topology/complex_builder.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace dualhex {
namespace {

// Welding compares points exactly, so the hash need only spread them over the table and
// the cache: the coordinates' products with three odd constants (independent multiplies)
// and one mix, instead of LatticePointHash's three chained mixes (add_vertex's hot path).
std::uint64_t point_hash(const LatticePoint& p) {
    return detail::mix64(static_cast<std::uint64_t>(p.x) * 0xd6e8feb86659fd93ULL +
                         static_cast<std::uint64_t>(p.y) * 0xa0761d6478bd642fULL +
                         static_cast<std::uint64_t>(p.z) * 0xe7037ed1a0b428dbULL);
}

// An odd 64-bit constant (2^64 / golden ratio) for the face loops' multiply-xor hash.
constexpr std::uint64_t kLoopHashFactor = 0x9e3779b97f4a7c15ULL;

}  // namespace

void ComplexBuilder::reserve(std::size_t n_vertices, std::size_t n_faces, std::size_t n_cells, std::size_t n_welded) {
    positions_.reserve(n_vertices);
    vertex_table_.reserve(n_welded);
    face_offsets_.reserve(n_faces + 1);
    face_loops_.reserve(4 * n_faces);
    face_table_.reserve(n_vertices, [&](std::int32_t f) {
        return face_loops_[face_offsets_[static_cast<std::size_t>(f)]].index();
    });
    cell_offsets_.reserve(n_cells + 1);
    cell_halffaces_.reserve(6 * n_cells);
}

void ComplexBuilder::grow_vertex_cache() {
    // At least twice the current size (growth is called once positions reach half of it).
    const std::size_t wanted = std::bit_ceil(std::max(kVertexCacheMin, 4 * positions_.size()));
    vertex_cache_.assign(std::min(wanted, kVertexCacheSize), CachedVertex{});
}

VertexHandle ComplexBuilder::add_vertex(const LatticePoint& p) {
    if (vertex_cache_.size() < kVertexCacheSize && positions_.size() >= vertex_cache_.size() / 2) grow_vertex_cache();
    const std::uint64_t hash = point_hash(p);
    CachedVertex& cached = vertex_cache_[(hash >> 20) & (vertex_cache_.size() - 1)];
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
    const std::size_t nv = positions_.size();
    for (VertexHandle v : loop)
        if (!v.valid() || v.index() >= nv)
            throw std::invalid_argument("ComplexBuilder::add_face: unknown vertex " + std::to_string(v.idx));

    // Both walks of the loop from its smallest vertex; the canonical one (hashed) heads
    // towards the smaller neighbour, so all rotations and both directions hash alike.
    const std::size_t n = loop.size();
    std::size_t start = 0;
    for (std::size_t i = 1; i < n; ++i)
        if (loop[i] < loop[start]) start = i;
    const VertexHandle* const data = loop.data();
    // k-th vertex of the forward (given direction) / backward walk from `start`.
    const auto fwd = [&](std::size_t k) { const std::size_t i = start + k; return data[i >= n ? i - n : i]; };
    const auto bwd = [&](std::size_t k) { return data[k <= start ? start - k : start + n - k]; };
    const bool canon_forward = n < 3 || fwd(1) <= bwd(1);
    // The hash only makes the tag that filters candidates before the exact comparison (the
    // home slot comes from the smallest vertex), so one multiply per vertex and a final mix
    // are enough: a full mix64 per vertex was a quarter of add_face's time.
    std::uint64_t hash = n;
    if (canon_forward)
        for (std::size_t k = 0; k < n; ++k) hash = (hash ^ static_cast<std::uint64_t>(fwd(k).idx)) * kLoopHashFactor;
    else
        for (std::size_t k = 0; k < n; ++k) hash = (hash ^ static_cast<std::uint64_t>(bwd(k).idx)) * kLoopHashFactor;
    hash = detail::mix64(hash);

    // The stored loop is the given one rotated to start at its smallest vertex; a later
    // equal loop matches it walking forward (side 0) or backward (side 1).
    const auto stored = [&](std::int32_t face, std::size_t& size) {
        const std::uint32_t begin = face_offsets_[static_cast<std::size_t>(face)];
        size = face_offsets_[static_cast<std::size_t>(face) + 1] - begin;
        return face_loops_.data() + begin;
    };
    const auto matches_forward = [&](std::int32_t face) {
        std::size_t size = 0;
        const VertexHandle* s = stored(face, size);
        if (size != n) return false;
        for (std::size_t k = 0; k < n; ++k)
            if (s[k] != fwd(k)) return false;
        return true;
    };
    const auto matches_backward = [&](std::int32_t face) {
        std::size_t size = 0;
        const VertexHandle* s = stored(face, size);
        if (size != n) return false;
        for (std::size_t k = 0; k < n; ++k)
            if (s[k] != bwd(k)) return false;
        return true;
    };
    const auto first_vertex = [&](std::int32_t face) {
        return face_loops_[face_offsets_[static_cast<std::size_t>(face)]].index();
    };
    const auto id = static_cast<std::int32_t>(n_faces());
    const auto [found, inserted] =
        face_table_.insert(data[start].index(), static_cast<std::uint32_t>(hash >> 32), id,
                           [&](std::int32_t f) { return matches_forward(f) || matches_backward(f); }, first_vertex);
    if (inserted) {
        for (std::size_t k = 0; k < n; ++k) face_loops_.push_back(fwd(k));
        face_offsets_.push_back(static_cast<std::uint32_t>(face_loops_.size()));
        return HalfFaceHandle(FaceHandle(found), 0);
    }
    return HalfFaceHandle(FaceHandle(found), matches_forward(found) ? 0 : 1);
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

ComplexBuilder::Parts ComplexBuilder::take_parts() && {
    return {std::move(positions_), std::move(face_offsets_), std::move(face_loops_), std::move(cell_offsets_),
            std::move(cell_halffaces_)};
}

}  // namespace dualhex
