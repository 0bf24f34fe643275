// The clipped dual (see clipped_dual.hpp for the construction and why it is a cube).
#include "dualhex/topology/clipped_dual.hpp"

#include "dual_cell_cube.hpp"

#include <algorithm>
#include <bit>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

namespace dualhex {
namespace {

using detail::DualCellFaces;
using detail::oriented_cube;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Does half-face h walk the directed edge a -> b?
bool walks(const CellComplex& k, HalfFaceHandle h, VertexHandle a, VertexHandle b) {
    const auto loop = k.face_vertices(h.face());
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (loop[i] != a) continue;
        const VertexHandle next = h.side() == 0 ? loop[i + 1 == n ? 0 : i + 1] : loop[i == 0 ? n - 1 : i - 1];
        if (next == b) return true;
    }
    return false;
}

// The vertex before v in half-face h's loop, or an invalid handle.
VertexHandle before(const CellComplex& k, HalfFaceHandle h, VertexHandle v) {
    const auto loop = k.face_vertices(h.face());
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i)
        if (loop[i] == v) return h.side() == 0 ? loop[i == 0 ? n - 1 : i - 1] : loop[i + 1 == n ? 0 : i + 1];
    return {};
}

// The per-entity tables every dual cell reads: built once, then shared read-only by the
// per-vertex workers (copies of Builder referring to them).
struct Tables {
    std::vector<std::uint8_t> vertex_planes, face_plane;
    std::vector<std::uint32_t> face_dual, edge_dual, vertex_dual;
};

// Sum and number of the distinct vertices of every cell (its dual vertex's centroid): each
// vertex added to the cells Incidence lists it in (once per cell). One pass over the
// vertex -> cells relation, written in vertex order (serial: a few adds per vertex-cell
// pair, no per-cell deduplication); exact sums, so the same as any per-cell order.
void cell_centroids(const CellComplex& k, const Incidence& inc, std::vector<RationalPoint>& points) {
    for (std::size_t c = 0; c < k.n_cells(); ++c) points[c] = {{0, 0, 0}, 0};
    for (std::size_t v = 0; v < k.n_vertices(); ++v) {
        const LatticePoint& p = k.position(VertexHandle(v));
        for (CellHandle c : inc.vertex_cells(VertexHandle(v))) {
            RationalPoint& r = points[c.index()];
            r.sum = r.sum + p;
            ++r.denominator;
        }
    }
}

// Vertices (cells) per parallel task: any split gives the same result (each has its own slot).
constexpr std::size_t kGrain = 2048;

class Builder {
public:
    Builder(const CellComplex& k, const Incidence& inc, const LatticePoint& lo, const LatticePoint& hi, Tables& t)
        : k_(k), inc_(inc), lo_(lo), hi_(hi), vertex_planes_(t.vertex_planes), face_plane_(t.face_plane),
          face_dual_(t.face_dual), edge_dual_(t.edge_dual), vertex_dual_(t.vertex_dual) {}

    ClippedDual run() {
        ClippedDual out;
        out.box_min = lo_;
        out.box_max = hi_;
        const std::size_t nv = k_.n_vertices(), nf = k_.n_faces(), nc = k_.n_cells();

        // Room for every dual vertex up front (no regrowth copies): cells, then boundary
        // faces, crease edges (at most the boundary edges) and corners.
        std::size_t n_boundary = 0;
        for (std::size_t f = 0; f < nf; ++f) n_boundary += inc_.is_boundary(FaceHandle(f)) ? 1 : 0;
        const std::size_t n_points = nc + 3 * n_boundary + 8;
        out.points.reserve(n_points);
        out.kind.reserve(n_points);
        out.primal.reserve(n_points);

        // Dual vertices of cells: centroid of the distinct vertices (exact sums: the same
        // in any order).
        out.points.resize(nc);
        out.kind.assign(nc, DualVertexKind::Cell);
        out.primal.resize(nc);
        cell_centroids(k_, inc_, out.points);
        for (std::size_t c = 0; c < nc; ++c) out.primal[c] = static_cast<std::uint32_t>(c);

        // Vertex planes: bit 2a (lo side) / 2a+1 (hi side) of axis a.
        vertex_planes_.resize(nv);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t v = r.begin(); v != r.end(); ++v) vertex_planes_[v] = planes_of(k_.position(VertexHandle(v)));
        });
        add_boundary_points(out);
        add_hexes(out);
        return out;
    }

private:
    // The dual vertices on the box surface, numbered in primal order after the cells:
    // boundary faces, crease edges, corners (few: a serial pass over flags).
    void add_boundary_points(ClippedDual& out) {
        const std::size_t nv = k_.n_vertices(), ne = k_.n_edges(), nf = k_.n_faces();
        // Boundary faces: the plane they lie in (a single bit), or none (a hole).
        face_plane_.assign(nf, 0);
        face_dual_.assign(nf, kNone);
        for (std::size_t f = 0; f < nf; ++f) {
            const FaceHandle fh(f);
            if (!inc_.is_boundary(fh)) continue;
            unsigned common = 0x3F;
            RationalPoint r{{0, 0, 0}, 0};
            for (VertexHandle v : k_.face_vertices(fh)) {
                common &= vertex_planes_[v.index()];
                r.sum = r.sum + k_.position(v);
                ++r.denominator;
            }
            if (common == 0) continue;  // off the box: its vertices' cells will fail
            face_plane_[f] = static_cast<std::uint8_t>(common & (~common + 1));  // lowest bit
            face_dual_[f] = add(out, r, DualVertexKind::BoundaryFace, f);
        }

        // Crease edges: two boundary faces in planes of different axes.
        edge_dual_.assign(ne, kNone);
        for (std::size_t e = 0; e < ne; ++e) {
            const EdgeHandle eh(e);
            if (!inc_.is_boundary(eh)) continue;
            unsigned planes[2] = {0, 0};
            int n = 0;
            for (FaceHandle f : inc_.edge_faces(eh))
                if (inc_.is_boundary(f) && n < 2) planes[n++] = face_plane_[f.index()];
            if (n != 2 || planes[0] == 0 || planes[1] == 0 || axis_of(planes[0]) == axis_of(planes[1])) continue;
            const auto& [a, b] = k_.edge_vertices(eh);
            edge_dual_[e] = add(out, {k_.position(a) + k_.position(b), 2}, DualVertexKind::CreaseEdge, e);
        }

        // Corners: on three box planes (one per axis).
        vertex_dual_.assign(nv, kNone);
        for (std::size_t v = 0; v < nv; ++v)
            if (axes_of(vertex_planes_[v]) == 3)
                vertex_dual_[v] = add(out, {k_.position(VertexHandle(v)), 1}, DualVertexKind::Corner, v);
    }

    // One hex per vertex, in vertex order; each range of vertices is built by its own copy
    // of this builder (its own scratch, the shared tables), into the vertex's own slot.
    void add_hexes(ClippedDual& out) const {
        const std::size_t nv = k_.n_vertices();
        out.hexes.resize(nv);
        out.primal_vertex.resize(nv);
        std::vector<std::uint8_t> failed(nv, 0);
        tbb::combinable<std::vector<DualError>> errors;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
            Builder worker(*this);
            for (std::size_t v = r.begin(); v != r.end(); ++v) {
                const VertexHandle vh(v);
                out.primal_vertex[v] = vh;
                worker.faces_.clear();
                worker.collect(vh);
                const char* defect = worker.faces_.why ? worker.faces_.why : oriented_cube(worker.faces_, out.hexes[v]);
                if (!defect) continue;
                failed[v] = 1;
                errors.local().push_back({vh, std::string("clipped dual cell of vertex ") + std::to_string(v) + ": " + defect});
            }
        });
        errors.combine_each([&](const std::vector<DualError>& e) { out.errors.insert(out.errors.end(), e.begin(), e.end()); });
        if (out.errors.empty()) return;
        std::sort(out.errors.begin(), out.errors.end(), [](const DualError& a, const DualError& b) { return a.vertex < b.vertex; });
        std::size_t kept = 0;
        for (std::size_t v = 0; v < nv; ++v)
            if (!failed[v]) {
                out.hexes[kept] = out.hexes[v];
                out.primal_vertex[kept++] = out.primal_vertex[v];
            }
        out.hexes.resize(kept);
        out.primal_vertex.resize(kept);
    }

    static int axis_of(unsigned plane_bit) { return plane_bit & 0x3 ? 0 : plane_bit & 0xC ? 1 : 2; }
    static int axes_of(unsigned planes) {
        return ((planes & 0x3) != 0) + ((planes & 0xC) != 0) + ((planes & 0x30) != 0);
    }
    unsigned planes_of(const LatticePoint& p) const {
        unsigned m = 0;
        for (int a = 0; a < 3; ++a) {
            if (p[a] == lo_[a]) m |= 1U << (2 * a);
            if (p[a] == hi_[a]) m |= 1U << (2 * a + 1);
        }
        return m;
    }
    static std::uint32_t add(ClippedDual& out, const RationalPoint& r, DualVertexKind kind, std::size_t primal) {
        out.points.push_back(r);
        out.kind.push_back(kind);
        out.primal.push_back(static_cast<std::uint32_t>(primal));
        return static_cast<std::uint32_t>(out.points.size() - 1);
    }

    // The dual face loops of v's clipped dual cell, into faces_.
    void collect(VertexHandle v) {
        gather_around(v);
        for (EdgeHandle e : inc_.vertex_edges(v)) {
            if (!faces_.open()) return faces_.fail("more than 6 dual faces");
            edge_face(v, e);
        }
        const unsigned planes = vertex_planes_[v.index()];
        for (unsigned bit = 1; bit < 64; bit <<= 1) {
            if (!(planes & bit)) continue;
            if (!faces_.open()) return faces_.fail("more than 6 dual faces");
            cap_face(v, bit);
        }
        if (faces_.overflow) faces_.fail("a dual face with too many vertices");
    }

    // The faces at v, read once for all of v's interior edges (instead of once per edge
    // through edge_faces and a loop scan each): v's neighbours in each loop, the cells and
    // the sides they use. Valid (around_ok_) when v occurs exactly once in every loop of
    // its faces: then the faces of the edge (v, w) are exactly those with w before or after
    // v, in the same (ascending) order as edge_faces, and the face walks v -> w iff w is
    // after v. Otherwise edge_face takes the general path.
    void gather_around(VertexHandle v) {
        const auto faces = inc_.vertex_faces(v);
        around_ok_ = faces.size() <= around_.size();
        if (!around_ok_) return;
        n_around_ = 0;
        for (FaceHandle f : faces) {
            const auto loop = k_.face_vertices(f);
            const std::size_t n = loop.size();
            std::size_t at = n, count = 0;
            for (std::size_t i = 0; i < n; ++i)
                if (loop[i] == v) at = i, ++count;
            if (count != 1) {
                around_ok_ = false;
                return;
            }
            Around& a = around_[n_around_++];
            a.prev = loop[at == 0 ? n - 1 : at - 1];
            a.next = loop[at + 1 == n ? 0 : at + 1];
            const auto cells = inc_.face_cells(f);
            a.two_cells = cells.size() == 2;
            if (a.two_cells) {
                const auto hfs = inc_.face_halffaces(f);
                a.cells = {cells[0], cells[1]};
                a.side0 = {hfs[0].side() == 0, hfs[1].side() == 0};
            }
        }
    }

    // The face through which cell c leaves, turning counter-clockwise about v -> w
    // (c's half-face walking v -> w), or an invalid handle.
    FaceHandle exit_face(EdgeHandle e, CellHandle c, VertexHandle v, VertexHandle w) const {
        for (FaceHandle f : inc_.edge_faces(e)) {
            const auto cells = inc_.face_cells(f);
            const auto hfs = inc_.face_halffaces(f);
            for (std::size_t i = 0; i < cells.size(); ++i)
                if (cells[i] == c && walks(k_, hfs[i], v, w)) return f;
        }
        return {};
    }

    // Dual face of edge e at v: cells counter-clockwise about v -> w; on the surface
    // [entry face, cells..., exit face, crease].
    void edge_face(VertexHandle v, EdgeHandle e) {
        const auto [a, b] = k_.edge_vertices(e);
        const VertexHandle w = a == v ? b : a;
        constexpr int kMaxSteps = 12;
        if (!inc_.is_boundary(e)) {
            // Each face at e joins the cell walking it v -> w (leaving, counter-clockwise)
            // to the other one: one loop scan per face, then follow the links.
            std::array<std::pair<CellHandle, CellHandle>, kMaxSteps> link{};
            std::size_t n = 0;
            if (around_ok_) {
                std::size_t n_faces = 0;
                for (std::size_t i = 0; i < n_around_; ++i)
                    n_faces += around_[i].prev == w || around_[i].next == w ? 1 : 0;
                if (n_faces == 0 || n_faces > kMaxSteps) return faces_.fail("an interior edge with too many faces");
                for (std::size_t i = 0; i < n_around_; ++i) {
                    const Around& a = around_[i];
                    if (a.prev != w && a.next != w) continue;
                    if (!a.two_cells) return faces_.fail("a face around an interior edge without two cells");
                    const bool side0 = a.next == w;
                    const std::size_t from = a.side0[0] == side0 ? 0 : 1;
                    if (a.side0[1 - from] == side0) return faces_.fail("cells around an interior edge are not consistently oriented");
                    link[n++] = {a.cells[from], a.cells[1 - from]};
                }
            }
            const auto faces = around_ok_ ? std::span<const FaceHandle>{} : inc_.edge_faces(e);
            if (!around_ok_ && (faces.empty() || faces.size() > kMaxSteps))
                return faces_.fail("an interior edge with too many faces");
            for (FaceHandle f : faces) {
                const auto cells = inc_.face_cells(f);
                const auto hfs = inc_.face_halffaces(f);
                if (cells.size() != 2) return faces_.fail("a face around an interior edge without two cells");
                const bool side0 = walks(k_, HalfFaceHandle(f, 0), v, w);
                const std::size_t from = (hfs[0].side() == 0) == side0 ? 0 : 1;
                if ((hfs[1 - from].side() == 0) == side0) return faces_.fail("cells around an interior edge are not consistently oriented");
                link[n++] = {cells[from], cells[1 - from]};
            }
            const CellHandle first = link[0].first;
            CellHandle c = first;
            for (int step = 0;; ++step) {
                if (step == kMaxSteps) return faces_.fail("cells around an interior edge do not close");
                faces_.push(c.index());
                std::size_t i = 0;
                while (i < n && link[i].first != c) ++i;
                if (i == n) return faces_.fail("cells around an interior edge are not consistently oriented");
                c = link[i].second;
                if (c == first) return;
            }
        }
        FaceHandle entry;
        for (FaceHandle f : inc_.edge_faces(e))
            if (inc_.is_boundary(f) && walks(k_, inc_.face_halffaces(f)[0], w, v)) entry = f;
        if (!entry.valid()) return faces_.fail("a boundary edge without an entry boundary face");
        if (face_dual_[entry.index()] == kNone) return faces_.fail("a boundary face off the box surface (a hole)");
        faces_.push(face_dual_[entry.index()]);
        CellHandle c = inc_.face_cells(entry)[0];
        for (int step = 0;; ++step) {
            if (step == kMaxSteps) return faces_.fail("cells around a boundary edge do not reach the surface");
            faces_.push(c.index());
            const FaceHandle f = exit_face(e, c, v, w);
            if (!f.valid()) return faces_.fail("cells around a boundary edge are not consistently oriented");
            if (inc_.is_boundary(f)) {
                if (face_dual_[f.index()] == kNone) return faces_.fail("a boundary face off the box surface (a hole)");
                faces_.push(face_dual_[f.index()]);
                break;
            }
            c = inc_.other_cell(f, c);
            if (!c.valid()) return faces_.fail("a face around a boundary edge with more than two cells");
        }
        if (edge_dual_[e.index()] != kNone) faces_.push(edge_dual_[e.index()]);
    }

    // A crease edge at v lying in `plane` other than `not_this`.
    EdgeHandle crease_in_plane(VertexHandle v, unsigned plane, EdgeHandle not_this) const {
        for (EdgeHandle e : inc_.vertex_edges(v)) {
            if (e == not_this || edge_dual_[e.index()] == kNone) continue;
            const auto& [a, b] = k_.edge_vertices(e);
            if (vertex_planes_[a.index()] & vertex_planes_[b.index()] & plane) return e;
        }
        return {};
    }

    // The boundary face in `plane` at edge e other than `not_this`.
    FaceHandle surface_face(EdgeHandle e, unsigned plane, FaceHandle not_this) const {
        for (FaceHandle f : inc_.edge_faces(e))
            if (f != not_this && inc_.is_boundary(f) && face_plane_[f.index()] == plane) return f;
        return {};
    }

    // The cap of v in a box plane: its boundary faces around v counter-clockwise seen from
    // outside, crease edges (and the corner) closing the loop.
    void cap_face(VertexHandle v, unsigned plane) {
        FaceHandle start;
        for (FaceHandle f : inc_.vertex_faces(v))
            if (inc_.is_boundary(f) && face_plane_[f.index()] == plane) {
                start = f;
                break;
            }
        if (!start.valid()) return faces_.fail("no boundary face in a box plane through the vertex");
        FaceHandle f = start;
        for (int step = 0;; ++step) {
            if (step == 12) return faces_.fail("the boundary faces around a surface vertex do not close");
            faces_.push(face_dual_[f.index()]);
            // Counter-clockwise from outside, the next face is across the edge (v, before v).
            const VertexHandle a = before(k_, inc_.face_halffaces(f)[0], v);
            const EdgeHandle e = a.valid() ? inc_.find_edge(v, a) : EdgeHandle{};
            if (!e.valid()) return faces_.fail("a boundary face loop without the vertex");
            FaceHandle next;
            if (edge_dual_[e.index()] != kNone) {
                faces_.push(edge_dual_[e.index()]);
                if (vertex_dual_[v.index()] != kNone) faces_.push(vertex_dual_[v.index()]);
                const EdgeHandle e2 = crease_in_plane(v, plane, e);
                if (!e2.valid()) return faces_.fail("a crease vertex with one crease edge in a plane");
                faces_.push(edge_dual_[e2.index()]);
                next = surface_face(e2, plane, {});
            } else {
                next = surface_face(e, plane, f);
            }
            if (!next.valid()) return faces_.fail("a surface edge without a second boundary face in its plane");
            if (next == start) return;
            f = next;
        }
    }

    const CellComplex& k_;
    const Incidence& inc_;
    LatticePoint lo_, hi_;
    std::vector<std::uint8_t>&vertex_planes_, &face_plane_;
    std::vector<std::uint32_t>&face_dual_, &edge_dual_, &vertex_dual_;
    DualCellFaces faces_;
    struct Around {
        VertexHandle prev, next;
        bool two_cells = false;
        std::array<CellHandle, 2> cells{};
        std::array<bool, 2> side0{};  // does cells[i] use side 0?
    };
    std::array<Around, 32> around_{};
    std::size_t n_around_ = 0;
    bool around_ok_ = false;
};

}  // namespace

ClippedDual clipped_dual(const CellComplex& k, const Incidence& inc, const LatticePoint& lo, const LatticePoint& hi) {
    Tables tables;
    return Builder(k, inc, lo, hi, tables).run();
}

ClippedDual clipped_dual(const CellComplex& k, const Incidence& inc) {
    LatticePoint lo{0, 0, 0}, hi{0, 0, 0};
    if (k.n_vertices() > 0) lo = hi = k.positions().front();
    for (const LatticePoint& p : k.positions())
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    return clipped_dual(k, inc, lo, hi);
}

ClippedDual clipped_dual(const CellComplex& k) { return clipped_dual(k, Incidence(k)); }

}  // namespace dualhex
