// The canonical summary (canonical.hpp): items keyed by lattice positions, hashed as a
// multiset so partial summaries add up.
#include "dualhex/distributed/canonical.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "dualhex/topology/cube_symmetry.hpp"

namespace dualhex {

std::uint64_t mix64(std::uint64_t v) {
    v += 0x9e3779b97f4a7c15ULL;
    v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ULL;
    v = (v ^ (v >> 27)) * 0x94d049bb133111ebULL;
    return v ^ (v >> 31);
}

void CanonicalSummary::add(const CanonicalSummary& o) {
    leaves += o.leaves;
    cells += o.cells;
    non_hex_cells += o.non_hex_cells;
    vertices += o.vertices;
    hexes += o.hexes;
    non_cube_vertices += o.non_cube_vertices;
    for (const auto& [k, n] : o.face_sizes) face_sizes[k] += n;
    for (const auto& [k, n] : o.elements) elements[k] += n;
    cell_hash += o.cell_hash;  // mod 2^64: the multiset hash
    hex_hash += o.hex_hash;
}

namespace {

std::uint64_t hash_words(std::span<const std::uint64_t> words) {
    std::uint64_t h = 0x243f6a8885a308d3ULL ^ words.size();
    for (std::uint64_t w : words) h = mix64(h ^ w);
    return h;
}

void push_point(std::vector<std::uint64_t>& w, const LatticePoint& p) {
    for (int a = 0; a < 3; ++a) w.push_back(static_cast<std::uint64_t>(p[a]));
}

// A set of vertices as its sorted distinct lattice positions, hashed.
std::uint64_t point_set_hash(const CellComplex& k, std::vector<VertexHandle> vs) {
    std::vector<LatticePoint> ps;
    ps.reserve(vs.size());
    for (VertexHandle v : vs) ps.push_back(k.position(v));
    std::sort(ps.begin(), ps.end());
    ps.erase(std::unique(ps.begin(), ps.end()), ps.end());
    std::vector<std::uint64_t> w;
    for (const LatticePoint& p : ps) push_point(w, p);
    return hash_words(w);
}

std::uint64_t face_hash(const CellComplex& k, FaceHandle f) {
    const auto vs = k.face_vertices(f);
    return point_set_hash(k, {vs.begin(), vs.end()});
}

// Face and cell hashes, computed once (a cell is a dual vertex of up to 8+ hexes).
struct HashCache {
    std::vector<std::uint64_t> face, cell;
    explicit HashCache(const CellComplex& k) : face(k.n_faces()), cell(k.n_cells()) {
        for (std::size_t f = 0; f < k.n_faces(); ++f) face[f] = face_hash(k, FaceHandle(f));
        std::vector<std::uint64_t> fs;
        for (std::size_t c = 0; c < k.n_cells(); ++c) {
            fs.clear();
            for (HalfFaceHandle h : k.cell_halffaces(CellHandle(c))) fs.push_back(face[h.face().index()]);
            std::sort(fs.begin(), fs.end());
            cell[c] = hash_words(fs);
        }
    }
};

// A dual vertex by what it is dual to, never by its index.
std::uint64_t dual_vertex_key(const CellComplex& k, const HashCache& hc, const ClippedDual& dual, std::uint32_t i) {
    const std::size_t e = dual.primal[i];
    std::uint64_t h = 0;
    switch (dual.kind[i]) {
        case DualVertexKind::Cell: h = hc.cell[e]; break;
        case DualVertexKind::BoundaryFace: h = hc.face[e]; break;
        case DualVertexKind::CreaseEdge: {
            const auto& ev = k.edge_vertices(EdgeHandle(e));
            h = point_set_hash(k, {ev[0], ev[1]});
            break;
        }
        case DualVertexKind::Corner: h = point_set_hash(k, {VertexHandle(e)}); break;
    }
    return mix64(h ^ static_cast<std::uint64_t>(dual.kind[i]));
}

// The 24 rotations of a VTK hexahedron as vertex permutations: corner i of the VTK order
// sits at kCorner[i]; a rotation moves it to corner perm[i].
const std::vector<std::array<int, 8>>& hex_rotations() {
    static const std::vector<std::array<int, 8>> perms = [] {
        static constexpr std::array<LatticePoint, 8> kCorner{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
        std::vector<std::array<int, 8>> out;
        for (int s = 0; s < CubeSymmetry::kOrder; ++s) {
            const CubeSymmetry sym = CubeSymmetry::from_index(s);
            if (!sym.is_rotation()) continue;
            std::array<int, 8> perm{};
            for (int i = 0; i < 8; ++i) {
                const LatticePoint q = sym.apply_about(kCorner[static_cast<std::size_t>(i)], 1);
                perm[static_cast<std::size_t>(i)] = static_cast<int>(std::find(kCorner.begin(), kCorner.end(), q) - kCorner.begin());
            }
            out.push_back(perm);
        }
        return out;
    }();
    return perms;
}

// The hex's dual vertex keys in the lexicographically least of its 24 rotations: the VTK
// order's starting corner depends on local numbering, the rotation class does not.
std::array<std::uint64_t, 8> canonical_hex(const std::array<std::uint64_t, 8>& keys) {
    std::array<std::uint64_t, 8> best{};
    bool first = true;
    for (const auto& perm : hex_rotations()) {
        std::array<std::uint64_t, 8> r{};
        for (std::size_t i = 0; i < 8; ++i) r[static_cast<std::size_t>(perm[i])] = keys[i];
        if (first || r < best) best = r;
        first = false;
    }
    return best;
}

bool is_plain_hex(const CellComplex& k, CellHandle c) {
    const auto hfs = k.cell_halffaces(c);
    bool hex = hfs.size() == 6;
    for (HalfFaceHandle h : hfs) hex = hex && k.face_vertices(h.face()).size() == 4;
    return hex;
}

void summarize_cells(const InstallResult& in, const HashCache& hc, std::size_t begin, std::size_t end, CanonicalSummary& s) {
    const CellComplex& k = in.complex;
    s.leaves = end - begin;
    for (std::size_t n = begin; n < end; ++n) {
        const std::int16_t e = in.leaf_element[n];
        ++s.elements[e < 0 ? std::string("hex") : in.element_names[static_cast<std::size_t>(e)]];
        for (std::size_t c = in.leaf_cells[n]; c < in.leaf_cells[n + 1]; ++c) {
            ++s.cells;
            s.non_hex_cells += is_plain_hex(k, CellHandle(c)) ? 0 : 1;
            s.cell_hash += mix64(hc.cell[c]);
        }
    }
}

}  // namespace

CanonicalSummary summarize(const InstallResult& in, const Incidence& incidence, const ClippedDual& dual,
                           const SummaryScope& scope) {
    (void)incidence;
    const CellComplex& k = in.complex;
    CanonicalSummary s;
    const HashCache hc(k);
    summarize_cells(in, hc, scope.leaf_begin, scope.leaf_end, s);
    for (std::size_t v = 0; v < k.n_vertices(); ++v) s.vertices += scope.owns(VertexHandle(v)) ? 1 : 0;
    for (std::size_t f = 0; f < k.n_faces(); ++f) {
        const auto vs = k.face_vertices(FaceHandle(f));
        const VertexHandle least = *std::min_element(vs.begin(), vs.end(), [&](VertexHandle a, VertexHandle b) {
            return k.position(a) < k.position(b);
        });
        if (scope.owns(least)) ++s.face_sizes[static_cast<int>(vs.size())];
    }
    for (std::size_t h = 0; h < dual.hexes.size(); ++h) {
        const VertexHandle v = dual.primal_vertex[h];
        if (!scope.owns(v)) continue;
        ++s.hexes;
        std::array<std::uint64_t, 8> keys{};
        for (std::size_t i = 0; i < 8; ++i) keys[i] = dual_vertex_key(k, hc, dual, dual.hexes[h][i]);
        std::vector<std::uint64_t> w;
        push_point(w, k.position(v));
        for (std::uint64_t key : canonical_hex(keys)) w.push_back(key);
        s.hex_hash += mix64(hash_words(w));
    }
    for (const DualError& e : dual.errors) s.non_cube_vertices += scope.owns(e.vertex) ? 1 : 0;
    return s;
}

CanonicalSummary summarize(const InstallResult& in, const Incidence& incidence, const ClippedDual& dual) {
    return summarize(in, incidence, dual, {0, in.leaf_cells.empty() ? 0 : in.leaf_cells.size() - 1, [](VertexHandle) { return true; }});
}

}  // namespace dualhex
