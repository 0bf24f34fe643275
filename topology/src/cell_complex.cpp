#include "dualhex/topology/cell_complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "dualhex/topology/id_hash_table.hpp"

namespace dualhex {
namespace {

void check_offsets(const std::vector<std::uint32_t>& offsets, std::size_t n_items, const char* what) {
    if (offsets.empty() || offsets.front() != 0 || offsets.back() != n_items)
        throw std::invalid_argument(std::string("CellComplex: bad ") + what + " offsets");
    for (std::size_t i = 1; i < offsets.size(); ++i)
        if (offsets[i] < offsets[i - 1]) throw std::invalid_argument(std::string("CellComplex: decreasing ") + what + " offsets");
}

}  // namespace

CellComplex::CellComplex(std::vector<LatticePoint> positions, std::vector<std::uint32_t> face_offsets,
                         std::vector<VertexHandle> face_loops, std::vector<std::uint32_t> cell_offsets,
                         std::vector<HalfFaceHandle> cell_halffaces)
    : positions_(std::move(positions)),
      face_offsets_(std::move(face_offsets)),
      face_loops_(std::move(face_loops)),
      cell_offsets_(std::move(cell_offsets)),
      cell_halffaces_(std::move(cell_halffaces)) {
    check_offsets(face_offsets_, face_loops_.size(), "face");
    check_offsets(cell_offsets_, cell_halffaces_.size(), "cell");
    for (std::size_t f = 0; f + 1 < face_offsets_.size(); ++f)
        if (face_offsets_[f] == face_offsets_[f + 1])
            throw std::invalid_argument("CellComplex: face " + std::to_string(f) + " has an empty loop");
    for (VertexHandle v : face_loops_)
        if (!v.valid() || v.index() >= positions_.size())
            throw std::invalid_argument("CellComplex: face vertex out of range: " + std::to_string(v.idx));
    for (HalfFaceHandle h : cell_halffaces_)
        if (!h.valid() || h.face().index() >= n_faces())
            throw std::invalid_argument("CellComplex: cell half-face out of range: " + std::to_string(h.idx));
    derive_edges();
}

void CellComplex::derive_edges() {
    // One edge per unordered consecutive pair, welded through a flat hash table keyed on
    // the packed (min, max) vertex pair.
    face_edges_.assign(face_loops_.size(), EdgeHandle{});
    edge_vertices_.clear();
    detail::IdHashTable table(face_loops_.size() / 2 + 1);
    for (std::size_t f = 0; f < n_faces(); ++f) {
        const std::uint32_t begin = face_offsets_[f], n = face_offsets_[f + 1] - begin;
        for (std::uint32_t i = 0; i < n; ++i) {
            VertexHandle a = face_loops_[begin + i], b = face_loops_[begin + (i + 1) % n];
            if (b < a) std::swap(a, b);
            const std::uint64_t key = (static_cast<std::uint64_t>(a.idx) << 32) | static_cast<std::uint32_t>(b.idx);
            const auto id = static_cast<std::int32_t>(edge_vertices_.size());
            const auto [found, inserted] = table.insert(detail::mix64(key), id, [&](std::int32_t e) {
                return edge_vertices_[static_cast<std::size_t>(e)] == std::array<VertexHandle, 2>{a, b};
            });
            if (inserted) edge_vertices_.push_back({a, b});
            face_edges_[begin + i] = EdgeHandle(found);
        }
    }
}

std::vector<VertexHandle> CellComplex::halfface_vertices(HalfFaceHandle h) const {
    const auto loop = face_vertices(h.face());
    std::vector<VertexHandle> out(loop.begin(), loop.end());
    if (h.side() == 1 && out.size() > 1) std::reverse(out.begin() + 1, out.end());
    return out;
}

}  // namespace dualhex
