// Canonical forms of variant complexes under the leaf's 6 axis permutations, and the
// symmetries mapping one variant to another (variants.hpp).
#include <algorithm>
#include <set>

#include "dualhex/schemes/variants.hpp"
#include "variant_loops.hpp"

namespace dualhex::variants {

using namespace detail;

ComplexForm complex_form(const CellComplex& complex, const CubeSymmetry& symmetry) {
    ComplexForm form;
    form.reserve(complex.n_cells());
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        std::vector<std::vector<LatticePoint>> cell;
        for (auto h : complex.cell_halffaces(CellHandle(c))) {
            Loop loop;
            for (auto v : complex.face_vertices(h.face())) loop.push_back(symmetry.apply(complex.position(v)));
            cell.push_back(canonical_loop(loop));
        }
        std::sort(cell.begin(), cell.end());
        form.push_back(std::move(cell));
    }
    std::sort(form.begin(), form.end());
    return form;
}

const std::array<CubeSymmetry, 6>& leaf_symmetries() {
    static const std::array<CubeSymmetry, 6> kSymmetries = {
        CubeSymmetry({0, 1, 2}, {1, 1, 1}), CubeSymmetry({0, 2, 1}, {1, 1, 1}), CubeSymmetry({1, 0, 2}, {1, 1, 1}),
        CubeSymmetry({1, 2, 0}, {1, 1, 1}), CubeSymmetry({2, 0, 1}, {1, 1, 1}), CubeSymmetry({2, 1, 0}, {1, 1, 1})};
    return kSymmetries;
}

ComplexForm canonical_form(const CellComplex& complex) {
    ComplexForm best;
    bool first = true;
    for (const auto& s : leaf_symmetries()) {
        ComplexForm f = complex_form(complex, s);
        if (first || f < best) best = std::move(f);
        first = false;
    }
    return best;
}

std::vector<CubeSymmetry> symmetries_mapping(const CellComplex& a, const CellComplex& b) {
    const ComplexForm fa = complex_form(a);
    std::vector<CubeSymmetry> out;
    for (const auto& s : leaf_symmetries())
        if (complex_form(b, s) == fa) out.push_back(s);
    return out;
}

std::map<int, std::size_t> cells_face_histogram(const CellComplex& complex, const std::vector<int>& cells) {
    std::set<std::size_t> faces;
    for (int c : cells)
        for (auto h : complex.cell_halffaces(CellHandle(static_cast<std::size_t>(c)))) faces.insert(h.face().index());
    std::map<int, std::size_t> hist;
    for (std::size_t f : faces) ++hist[static_cast<int>(complex.face_vertices(FaceHandle(f)).size())];
    return hist;
}

}  // namespace dualhex::variants
