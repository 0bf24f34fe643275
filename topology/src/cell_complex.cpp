#include "dualhex/topology/cell_complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "edge_derivation.hpp"

namespace dualhex {
namespace {

void check_offsets(const std::vector<std::uint32_t>& offsets, std::size_t n_items, const char* what) {
    if (offsets.empty() || offsets.front() != 0 || offsets.back() != n_items)
        throw std::invalid_argument(std::string("CellComplex: bad ") + what + " offsets");
    for (std::size_t i = 1; i < offsets.size(); ++i)
        if (offsets[i] < offsets[i - 1]) throw std::invalid_argument(std::string("CellComplex: decreasing ") + what + " offsets");
}

// The first position in `ids` whose id is not below `n` (a negative id counts as huge), or
// ids.size(). A branch-free maximum first (vectorised: a fraction of an instruction per
// id), the scan for the position only when some id is out of range.
template <class H>
std::size_t first_out_of_range(const std::vector<H>& ids, std::size_t n) {
    std::uint32_t most = 0;
    for (const H& h : ids) most = std::max(most, static_cast<std::uint32_t>(h.idx));
    if (most < n) return ids.size();
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (static_cast<std::uint32_t>(ids[i].idx) >= n) return i;
    return ids.size();
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
    for (std::size_t f = 0; f < n_faces(); ++f)
        if (face_offsets_[f] == face_offsets_[f + 1])
            throw std::invalid_argument("CellComplex: face " + std::to_string(f) + " has an empty loop");
    if (const std::size_t i = first_out_of_range(face_loops_, positions_.size()); i < face_loops_.size())
        throw std::invalid_argument("CellComplex: face vertex out of range: " + std::to_string(face_loops_[i].idx));
    if (const std::size_t i = first_out_of_range(cell_halffaces_, 2 * n_faces()); i < cell_halffaces_.size())
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
