#pragma once
// Internal: an exact, numbering-free form of a complex moved by a lattice motion, so that
// "complex B is the image of complex A under motion m" is one comparison of two forms:
// form(B, identity) == form(A, m). Used to carry one checked configuration's outcome over
// to every configuration proved congruent to it (compositional windows, weak tori and windows).
//
// The form: the sorted moved vertex positions, then the cells sorted, each cell the sorted
// list of its outward loops (in the half-face's orientation, reversed when the motion is a
// reflection, so that outward stays outward), each loop rotated to start at its smallest
// point. Cells and faces are kept with multiplicity. Flat int64 encoding (lengths first), a
// point packed into one int64 (21 bits a coordinate, order-preserving); a complex with a
// coordinate beyond +-2^20 has no form (empty: callers then check it themselves).
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex::detail {

using OrientedForm = std::vector<std::int64_t>;

/// What a form reads of a complex: its vertices, face loops and cells' half-faces, from a
/// CellComplex or straight from a builder's parts. A member that is only to be proved an
/// image of its representative needs no CellComplex (whose constructor derives the edges,
/// which the form does not read; configuration_parts.hpp).
struct FormArrays {
    std::span<const LatticePoint> positions;
    std::span<const std::uint32_t> face_offsets;
    std::span<const VertexHandle> face_loops;
    std::span<const std::uint32_t> cell_offsets;
    std::span<const HalfFaceHandle> cell_halffaces;

    FormArrays(const CellComplex& k)  // NOLINT(google-explicit-constructor): every complex has a form
        : positions(k.positions()), face_offsets(k.face_offsets()), face_loops(k.face_loops()),
          cell_offsets(k.cell_offsets()), cell_halffaces(k.all_cell_halffaces()) {}
    FormArrays(const ComplexBuilder::Parts& p)  // NOLINT(google-explicit-constructor)
        : positions(p.positions), face_offsets(p.face_offsets), face_loops(p.face_loops), cell_offsets(p.cell_offsets),
          cell_halffaces(p.cell_halffaces) {}

    [[nodiscard]] std::size_t n_faces() const { return face_offsets.size() - 1; }
    [[nodiscard]] std::size_t n_cells() const { return cell_offsets.size() - 1; }
    [[nodiscard]] std::span<const VertexHandle> face_vertices(FaceHandle f) const {
        return face_loops.subspan(face_offsets[f.index()], face_offsets[f.index() + 1] - face_offsets[f.index()]);
    }
    [[nodiscard]] std::span<const HalfFaceHandle> cell_halffaces_of(std::size_t c) const {
        return cell_halffaces.subspan(cell_offsets[c], cell_offsets[c + 1] - cell_offsets[c]);
    }
};

namespace oriented_form_detail {

using Span = std::pair<std::size_t, std::size_t>;  // offset, length into a buffer

constexpr std::int64_t kReach = std::int64_t{1} << 20;

inline bool packable(const LatticePoint& p) {
    return -kReach <= p.x && p.x < kReach && -kReach <= p.y && p.y < kReach && -kReach <= p.z && p.z < kReach;
}
// Lexicographic order of (x, y, z) is the order of the packed values.
inline std::int64_t pack(const LatticePoint& p) {
    return (p.x + kReach) << 42 | (p.y + kReach) << 21 | (p.z + kReach);
}

inline void sort_spans(std::vector<Span>& spans, const std::vector<std::int64_t>& buffer) {
    std::sort(spans.begin(), spans.end(), [&](const Span& a, const Span& b) {
        return std::lexicographical_compare(buffer.begin() + static_cast<std::ptrdiff_t>(a.first),
                                            buffer.begin() + static_cast<std::ptrdiff_t>(a.first + a.second),
                                            buffer.begin() + static_cast<std::ptrdiff_t>(b.first),
                                            buffer.begin() + static_cast<std::ptrdiff_t>(b.first + b.second));
    });
}

inline void append(std::vector<std::int64_t>& out, const std::vector<std::int64_t>& buffer, const Span& s) {
    out.insert(out.end(), buffer.begin() + static_cast<std::ptrdiff_t>(s.first),
               buffer.begin() + static_cast<std::ptrdiff_t>(s.first + s.second));
}

}  // namespace oriented_form_detail

/// `move(p)`: the moved lattice point; `reflect`: the motion reverses orientation.
template <class Move>
[[nodiscard]] OrientedForm oriented_form(const FormArrays& k, Move&& move, bool reflect) {
    using namespace oriented_form_detail;
    OrientedForm out;
    // Scratch kept per thread: forms are computed for tens of thousands of small complexes
    // (every compositional member), where the buffers' allocations cost as much as the work.
    struct Scratch {
        std::vector<std::int64_t> moved, points, cells_buffer, faces_buffer, loop;
        std::vector<Span> cells, faces;
    };
    thread_local Scratch scratch;
    std::vector<std::int64_t>& moved = scratch.moved;  // per vertex, packed once: a vertex is on many loops
    moved.clear();
    moved.reserve(k.positions.size());
    for (const LatticePoint& p : k.positions) {
        const LatticePoint q = move(p);
        if (!packable(q)) return {};
        moved.push_back(pack(q));
    }
    std::vector<std::int64_t>& points = scratch.points;
    points.assign(moved.begin(), moved.end());
    std::sort(points.begin(), points.end());
    out.push_back(static_cast<std::int64_t>(points.size()));
    out.insert(out.end(), points.begin(), points.end());

    std::vector<std::int64_t>& cells_buffer = scratch.cells_buffer;
    std::vector<std::int64_t>& faces_buffer = scratch.faces_buffer;
    std::vector<Span>& cells = scratch.cells;
    std::vector<Span>& faces = scratch.faces;
    std::vector<std::int64_t>& loop = scratch.loop;
    cells_buffer.clear();
    cells.clear();
    // An upper bound: every face is on at most two cells.
    out.reserve(2 + points.size() + k.n_cells() + 2 * (k.n_faces() + k.face_loops.size()));
    for (std::size_t c = 0; c < k.n_cells(); ++c) {
        faces_buffer.clear();
        faces.clear();
        for (HalfFaceHandle h : k.cell_halffaces_of(c)) {
            const auto stored = k.face_vertices(h.face());
            loop.clear();
            for (VertexHandle v : stored) loop.push_back(moved[v.index()]);
            if ((h.side() == 1) != reflect) std::reverse(loop.begin(), loop.end());
            std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
            faces.emplace_back(faces_buffer.size(), 1 + loop.size());
            faces_buffer.push_back(static_cast<std::int64_t>(loop.size()));
            faces_buffer.insert(faces_buffer.end(), loop.begin(), loop.end());
        }
        sort_spans(faces, faces_buffer);
        const std::size_t begin = cells_buffer.size();
        cells_buffer.push_back(static_cast<std::int64_t>(faces.size()));
        for (const Span& f : faces) append(cells_buffer, faces_buffer, f);
        cells.emplace_back(begin, cells_buffer.size() - begin);
    }
    sort_spans(cells, cells_buffer);
    out.push_back(static_cast<std::int64_t>(cells.size()));
    for (const Span& c : cells) append(out, cells_buffer, c);
    return out;
}

}  // namespace dualhex::detail
