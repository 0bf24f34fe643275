#include "dualhex/geometry/complex_output.hpp"

#include <fstream>
#include <stdexcept>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::geometry {

void write_complex_vtk(const std::string& path, const CellComplex& complex, const LatticeEmbedding& embed,
                       bool overwrite) {
    check_can_write(path, overwrite);
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out.precision(17);
    out << "# vtk DataFile Version 4.2\ndualhex polyhedral complex\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << complex.n_vertices() << " double\n";
    for (const auto& p : complex.positions()) {
        const Eigen::Vector3d q = embed(p);
        out << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
    }
    // Each cell: n_faces, then per face: n_points, ids (outward loop).
    std::size_t total = 0;
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        std::size_t size = 1;
        for (const HalfFaceHandle h : complex.cell_halffaces(CellHandle(c)))
            size += 1 + complex.face_vertices(h.face()).size();
        total += 1 + size;
    }
    out << "CELLS " << complex.n_cells() << ' ' << total << '\n';
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        const auto hfs = complex.cell_halffaces(CellHandle(c));
        std::size_t size = 1;
        for (const HalfFaceHandle h : hfs) size += 1 + complex.face_vertices(h.face()).size();
        out << size << ' ' << hfs.size();
        for (const HalfFaceHandle h : hfs) {
            const auto loop = complex.halfface_vertices(h);
            out << ' ' << loop.size();
            for (const VertexHandle v : loop) out << ' ' << v.index();
        }
        out << '\n';
    }
    out << "CELL_TYPES " << complex.n_cells() << '\n';
    for (std::size_t c = 0; c < complex.n_cells(); ++c) out << "42\n";
    out << "CELL_DATA " << complex.n_cells() << "\nSCALARS faces int 1\nLOOKUP_TABLE default\n";
    for (std::size_t c = 0; c < complex.n_cells(); ++c) out << complex.cell_halffaces(CellHandle(c)).size() << '\n';
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed");
}

void write_complex_faces_vtk(const std::string& path, const CellComplex& complex, const LatticeEmbedding& embed,
                             bool overwrite) {
    check_can_write(path, overwrite);
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out.precision(17);
    out << "# vtk DataFile Version 4.2\ndualhex complex faces\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << complex.n_vertices() << " double\n";
    for (const auto& p : complex.positions()) {
        const Eigen::Vector3d q = embed(p);
        out << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
    }
    std::vector<int> cells_on_face(complex.n_faces(), 0);
    for (const HalfFaceHandle h : complex.all_cell_halffaces()) ++cells_on_face[h.face().index()];
    out << "CELLS " << complex.n_faces() << ' ' << complex.n_faces() + complex.face_loops().size() << '\n';
    for (std::size_t f = 0; f < complex.n_faces(); ++f) {
        const auto loop = complex.face_vertices(FaceHandle(f));
        out << loop.size();
        for (const VertexHandle v : loop) out << ' ' << v.index();
        out << '\n';
    }
    out << "CELL_TYPES " << complex.n_faces() << '\n';
    for (std::size_t f = 0; f < complex.n_faces(); ++f) out << "7\n";
    out << "CELL_DATA " << complex.n_faces() << "\nSCALARS cells int 1\nLOOKUP_TABLE default\n";
    for (int n : cells_on_face) out << n << '\n';
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace dualhex::geometry
