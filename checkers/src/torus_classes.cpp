// Motions of a configuration torus and classes under them (torus_classes.hpp).
#include "dualhex/checkers/torus_classes.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "dualhex/topology/incidence.hpp"

namespace dualhex {

namespace {

LatticePoint shift_vector(int shift) { return {shift & 1, (shift >> 1) & 1, (shift >> 2) & 1}; }

}  // namespace

LatticePoint TorusMotion::apply(const LatticePoint& p, std::int64_t octant) const {
    const std::int64_t period = 2 * octant;
    LatticePoint q = symmetry.apply(p) + shift_vector(shift) * octant;
    for (int a = 0; a < 3; ++a) q[a] = ((q[a] % period) + period) % period;
    return q;
}

int TorusMotion::apply_octant(int b) const {
    // the cube's centre, in half-octant units (octant = 2)
    const LatticePoint q = apply({2 * (b & 1) + 1, 2 * ((b >> 1) & 1) + 1, 2 * ((b >> 2) & 1) + 1}, 2);
    return (q.x >= 2 ? 1 : 0) | (q.y >= 2 ? 2 : 0) | (q.z >= 2 ? 4 : 0);
}

TorusMotion TorusMotion::inverse() const {
    // m(p) = g(p) + s O, so m^-1(q) = g^-1(q) - g^-1(s) O, and -O = O modulo the period
    TorusMotion out{symmetry.inverse(), 0};
    const LatticePoint back = out.symmetry.apply(shift_vector(shift));
    for (int a = 0; a < 3; ++a)
        if (back[a] != 0) out.shift |= 1 << a;
    return out;
}

std::string TorusMotion::to_string() const {
    std::string s = symmetry.to_string();
    if (shift == 0) return s;
    const LatticePoint v = shift_vector(shift);
    s.append(" + (").append(std::to_string(v.x)).append(",").append(std::to_string(v.y)).append(",");
    return s.append(std::to_string(v.z)).append(") octants");
}

std::vector<TorusMotion> torus_translations() {
    std::vector<TorusMotion> out;
    for (int t = 0; t < 8; ++t) out.push_back({CubeSymmetry{}, t});
    return out;
}

std::vector<TorusMotion> torus_motions() {
    std::vector<TorusMotion> out;
    for (int g = 0; g < CubeSymmetry::kOrder; ++g)
        for (int t = 0; t < 8; ++t) out.push_back({CubeSymmetry::from_index(g), t});
    return out;
}

CanonicalCells canonical_cells(const CellComplex& complex, const TorusMotion& motion, std::int64_t octant) {
    const bool reflect = motion.symmetry.determinant() < 0;
    CanonicalCells cells;
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        std::vector<std::vector<LatticePoint>> faces;
        for (HalfFaceHandle h : complex.cell_halffaces(CellHandle(c))) {
            std::vector<LatticePoint> loop;
            for (VertexHandle v : complex.halfface_vertices(h)) loop.push_back(motion.apply(complex.position(v), octant));
            if (reflect) std::reverse(loop.begin(), loop.end());
            std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
            faces.push_back(std::move(loop));
        }
        std::sort(faces.begin(), faces.end());
        cells.insert(std::move(faces));
    }
    return cells;
}

void require_closed_torus(const CellComplex& complex, std::int64_t octant, const std::string& what) {
    for (const LatticePoint& p : complex.positions())
        for (int a = 0; a < 3; ++a)
            if (p[a] < 0 || p[a] >= 2 * octant)
                throw std::runtime_error("certify: " + what + ": a vertex lies outside the period " +
                                         std::to_string(2 * octant));
    const Incidence incidence(complex);
    for (std::size_t v = 0; v < complex.n_vertices(); ++v)
        if (incidence.is_boundary(VertexHandle(v)))
            throw std::runtime_error("certify: " + what + ": vertex " + std::to_string(v) + " is not interior");
}

std::vector<TorusClass> torus_classes(std::size_t n, const std::function<std::size_t(std::size_t, const TorusMotion&)>& image,
                                      const std::function<CellComplex(std::size_t)>& build,
                                      const std::vector<TorusMotion>& motions, std::int64_t octant,
                                      const Progress& progress, std::string_view stage) {
    ProgressCounter counter(progress, stage, n);
    std::vector<char> done(n, 0);
    std::vector<TorusClass> out;
    for (std::size_t rep = 0; rep < n; ++rep) {
        if (done[rep]) continue;
        done[rep] = 1;
        TorusClass c{rep, {{rep, TorusMotion{}}}};
        const CanonicalCells target = canonical_cells(build(rep), TorusMotion{}, octant);
        std::map<std::size_t, CellComplex> pending;  // orbit members no motion tried so far reproduces
        for (const TorusMotion& m : motions) {
            const std::size_t label = image(rep, m);
            if (done[label]) continue;
            auto it = pending.find(label);
            if (it == pending.end()) it = pending.emplace(label, build(label)).first;
            if (canonical_cells(it->second, m.inverse(), octant) != target) continue;
            done[label] = 1;
            pending.erase(it);
            c.members.emplace_back(label, m);
        }
        if (!pending.empty())
            throw std::runtime_error("certify: the torus of label " + std::to_string(pending.begin()->first) +
                                     " is not the image of the torus of label " + std::to_string(rep) +
                                     " under any motion mapping one to the other");
        std::sort(c.members.begin() + 1, c.members.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        counter.add(c.members.size());
        out.push_back(std::move(c));
    }
    return out;
}

}  // namespace dualhex
