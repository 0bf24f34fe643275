#include "dualhex/geometry/hex_output.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace dualhex::geometry {

void check_can_write(const std::string& path, bool overwrite) {
    std::error_code ec;
    if (!overwrite && std::filesystem::exists(path, ec))
        throw std::runtime_error(path + ": exists (pass overwrite to replace it)");
}

namespace {
std::ofstream open_for_write(const std::string& path, const HexMesh& mesh, bool overwrite) {
    check_can_write(path, overwrite);
    const auto n = static_cast<int>(mesh.points.size());
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h])
            if (v < 0 || v >= n)
                throw std::runtime_error(path + ": hex " + std::to_string(h) + " refers to point " +
                                         std::to_string(v) + " of " + std::to_string(n));
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out.precision(17);
    return out;
}
void finish(std::ofstream& out, const std::string& path) {
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed");
}
}  // namespace

void write_vtk_legacy(const std::string& path, const HexMesh& mesh, bool overwrite) {
    auto out = open_for_write(path, mesh, overwrite);
    out << "# vtk DataFile Version 4.2\ndualhex hex mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << mesh.points.size() << " double\n";
    for (const auto& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    out << "CELLS " << mesh.hexes.size() << ' ' << 9 * mesh.hexes.size() << '\n';
    for (const auto& h : mesh.hexes) {
        out << 8;
        for (int v : h) out << ' ' << v;
        out << '\n';
    }
    out << "CELL_TYPES " << mesh.hexes.size() << '\n';
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << "12\n";
    finish(out, path);
}

void write_vtu(const std::string& path, const HexMesh& mesh, bool overwrite) {
    auto out = open_for_write(path, mesh, overwrite);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << mesh.hexes.size()
        << "\">\n"
           "      <Points>\n"
           "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : mesh.points) out << "          " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    out << "        </DataArray>\n      </Points>\n      <Cells>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& h : mesh.hexes) {
        out << "         ";
        for (int v : h) out << ' ' << v;
        out << '\n';
    }
    out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << "          " << 8 * (h + 1) << '\n';
    out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << "          12\n";
    out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    finish(out, path);
}

void write_medit(const std::string& path, const HexMesh& mesh, bool overwrite) {
    auto out = open_for_write(path, mesh, overwrite);
    out << "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" << mesh.points.size() << '\n';
    for (const auto& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << " 0\n";
    out << "\nHexahedra\n" << mesh.hexes.size() << '\n';
    for (const auto& h : mesh.hexes) {
        for (int v : h) out << v + 1 << ' ';
        out << "0\n";
    }
    out << "\nEnd\n";
    finish(out, path);
}

void write_hex_mesh(const std::string& path, const HexMesh& mesh, bool overwrite) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".vtk") write_vtk_legacy(path, mesh, overwrite);
    else if (ext == ".vtu") write_vtu(path, mesh, overwrite);
    else if (ext == ".mesh") write_medit(path, mesh, overwrite);
    else throw std::invalid_argument(path + ": unknown hex mesh format '" + ext + "' (expected .vtk, .vtu, .mesh)");
}

}  // namespace dualhex::geometry
