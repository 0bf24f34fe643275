#include "dualhex/topology/transform.hpp"

namespace dualhex {

CellComplex transform(const CellComplex& k, const CubeSymmetry& symmetry, const LatticePoint& translation) {
    std::vector<LatticePoint> positions;
    positions.reserve(k.n_vertices());
    for (const LatticePoint& p : k.positions()) positions.push_back(symmetry.apply(p) + translation);
    std::vector<HalfFaceHandle> halffaces = k.all_cell_halffaces();
    if (!symmetry.is_rotation())
        for (HalfFaceHandle& h : halffaces) h = h.opposite();
    return CellComplex(std::move(positions), k.face_offsets(), k.face_loops(), k.cell_offsets(), std::move(halffaces));
}

}  // namespace dualhex
