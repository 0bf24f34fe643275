#include "dualhex/topology/cell_complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "edge_derivation.hpp"

namespace dualhex {
namespace {

void check_offsets(const std::vector<std::uint32_t>& offsets, std::size_t n_items, const char* what) {
    if (offsets.empty() || offsets.front() != 0 || offsets.back() != n_items)
        throw std::invalid_argument(std::string("CellComplex: bad ") + what + " offsets");
    for (std::size_t i = 1; i < offsets.size(); ++i)
        if (offsets[i] < offsets[i - 1]) throw std::invalid_argument(std::string("CellComplex: decreasing ") + what + " offsets");
}

// The first i < n with bad(i), or n: in parallel, the same index as a serial scan (so the
// error names the same entity for any thread count).
template <class Bad>
std::size_t first_bad(std::size_t n, const Bad& bad) {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 1 << 16), n,
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
            for (std::size_t i = r.begin(); i != r.end() && i < found; ++i)
                if (bad(i)) return i;
            return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
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
    if (const std::size_t f = first_bad(n_faces(), [&](std::size_t f) { return face_offsets_[f] == face_offsets_[f + 1]; });
        f < n_faces())
        throw std::invalid_argument("CellComplex: face " + std::to_string(f) + " has an empty loop");
    if (const std::size_t i = first_bad(face_loops_.size(), [&](std::size_t i) {
            const VertexHandle v = face_loops_[i];
            return !v.valid() || v.index() >= positions_.size();
        });
        i < face_loops_.size())
        throw std::invalid_argument("CellComplex: face vertex out of range: " + std::to_string(face_loops_[i].idx));
    if (const std::size_t i = first_bad(cell_halffaces_.size(), [&](std::size_t i) {
            const HalfFaceHandle h = cell_halffaces_[i];
            return !h.valid() || h.face().index() >= n_faces();
        });
        i < cell_halffaces_.size())
        throw std::invalid_argument("CellComplex: cell half-face out of range: " + std::to_string(cell_halffaces_[i].idx));
    derive_edges();
}

void CellComplex::derive_edges() {
    detail::DerivedEdges edges = detail::derive_edges(positions_.size(), face_offsets_, face_loops_);
    face_edges_ = std::move(edges.face_edges);
    edge_vertices_ = std::move(edges.edge_vertices);
}

std::vector<VertexHandle> CellComplex::halfface_vertices(HalfFaceHandle h) const {
    const auto loop = face_vertices(h.face());
    std::vector<VertexHandle> out(loop.begin(), loop.end());
    if (h.side() == 1 && out.size() > 1) std::reverse(out.begin() + 1, out.end());
    return out;
}

}  // namespace dualhex
