#include "dualhex/topology/cell_complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>


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
    // Bucket every face side by its smaller endpoint (a counting sort), then dedupe the few
    // larger endpoints within each bucket. Cache-friendly, unlike one big hash table, and
    // it numbers edges by their smaller endpoint, deterministically.
    const std::size_t n_corners = face_loops_.size();
    std::vector<std::uint32_t> bucket(positions_.size() + 1, 0);
    std::vector<VertexHandle> other(n_corners);
    std::vector<std::uint32_t> corner_of(n_corners);
    auto side = [&](std::size_t f, std::uint32_t i) {
        const std::uint32_t begin = face_offsets_[f], n = face_offsets_[f + 1] - begin;
        VertexHandle a = face_loops_[begin + i], b = face_loops_[begin + (i + 1) % n];
        return a < b ? std::pair{a, b} : std::pair{b, a};
    };
    for (std::size_t f = 0; f < n_faces(); ++f)
        for (std::uint32_t i = 0; i < face_offsets_[f + 1] - face_offsets_[f]; ++i) ++bucket[side(f, i).first.index() + 1];
    for (std::size_t v = 0; v < positions_.size(); ++v) bucket[v + 1] += bucket[v];
    std::vector<std::uint32_t> cursor(bucket.begin(), bucket.end() - 1);
    for (std::size_t f = 0; f < n_faces(); ++f)
        for (std::uint32_t i = 0; i < face_offsets_[f + 1] - face_offsets_[f]; ++i) {
            const auto [a, b] = side(f, i);
            const std::uint32_t slot = cursor[a.index()]++;
            other[slot] = b;
            corner_of[slot] = face_offsets_[f] + i;
        }

    face_edges_.assign(n_corners, EdgeHandle{});
    edge_vertices_.clear();
    for (std::size_t a = 0; a < positions_.size(); ++a) {
        const std::size_t first_edge = edge_vertices_.size();
        for (std::uint32_t s = bucket[a]; s < bucket[a + 1]; ++s) {
            std::size_t e = first_edge;
            while (e < edge_vertices_.size() && edge_vertices_[e][1] != other[s]) ++e;
            if (e == edge_vertices_.size()) edge_vertices_.push_back({VertexHandle(a), other[s]});
            face_edges_[corner_of[s]] = EdgeHandle(e);
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
