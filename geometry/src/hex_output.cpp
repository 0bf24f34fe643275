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
void check_field(const std::string& path, const char* name, std::size_t size, std::size_t hexes) {
    if (size != 0 && size != hexes)
        throw std::runtime_error(path + ": cell field " + name + " has " + std::to_string(size) + " values for " +
                                 std::to_string(hexes) + " hexes");
}

std::ofstream open_for_write(const std::string& path, const HexMesh& mesh, bool overwrite, const HexCellData& cells) {
    check_can_write(path, overwrite);
    check_field(path, "scaled_jacobian", cells.scaled_jacobian.size(), mesh.hexes.size());
    check_field(path, "level", cells.level.size(), mesh.hexes.size());
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
template <class T>
void write_legacy_scalars(std::ofstream& out, const char* name, const char* type, const std::vector<T>& values) {
    if (values.empty()) return;
    out << "SCALARS " << name << ' ' << type << " 1\nLOOKUP_TABLE default\n";
    for (const T& v : values) out << v << '\n';
}

template <class T>
void write_vtu_array(std::ofstream& out, const char* name, const char* type, const std::vector<T>& values) {
    if (values.empty()) return;
    out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (const T& v : values) out << "          " << v << '\n';
    out << "        </DataArray>\n";
}

void finish(std::ofstream& out, const std::string& path) {
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed");
}
}  // namespace

void write_vtk_legacy(const std::string& path, const HexMesh& mesh, bool overwrite, const HexCellData& cells) {
    auto out = open_for_write(path, mesh, overwrite, cells);
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
    if (!cells.scaled_jacobian.empty() || !cells.level.empty()) {
        out << "CELL_DATA " << mesh.hexes.size() << '\n';
        write_legacy_scalars(out, "scaled_jacobian", "double", cells.scaled_jacobian);
        write_legacy_scalars(out, "level", "int", cells.level);
    }
    finish(out, path);
}

void write_vtu(const std::string& path, const HexMesh& mesh, bool overwrite, const HexCellData& cells) {
    auto out = open_for_write(path, mesh, overwrite, cells);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << mesh.hexes.size()
        << "\">\n";
    if (!cells.scaled_jacobian.empty() || !cells.level.empty()) {
        out << "      <CellData" << (cells.scaled_jacobian.empty() ? "" : " Scalars=\"scaled_jacobian\"") << ">\n";
        write_vtu_array(out, "scaled_jacobian", "Float64", cells.scaled_jacobian);
        write_vtu_array(out, "level", "Int32", cells.level);
        out << "      </CellData>\n";
    }
    out << "      <Points>\n"
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

void write_medit(const std::string& path, const HexMesh& mesh, bool overwrite, const HexCellData& cells) {
    auto out = open_for_write(path, mesh, overwrite, cells);
    out << "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" << mesh.points.size() << '\n';
    for (const auto& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << " 0\n";
    out << "\nHexahedra\n" << mesh.hexes.size() << '\n';
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        for (int v : mesh.hexes[h]) out << v + 1 << ' ';
        out << (cells.level.empty() ? 0 : cells.level[h]) << '\n';
    }
    out << "\nEnd\n";
    finish(out, path);
}

void write_hex_mesh(const std::string& path, const HexMesh& mesh, bool overwrite, const HexCellData& cells) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".vtk") write_vtk_legacy(path, mesh, overwrite, cells);
    else if (ext == ".vtu") write_vtu(path, mesh, overwrite, cells);
    else if (ext == ".mesh") write_medit(path, mesh, overwrite, cells);
    else throw std::invalid_argument(path + ": unknown hex mesh format '" + ext + "' (expected .vtk, .vtu, .mesh)");
}

}  // namespace dualhex::geometry
