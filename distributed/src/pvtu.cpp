// Pieces and the .pvtu index (pvtu.hpp). Plain ASCII: small figures, readable diffs.
#include "pvtu.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace dualhex::dist {

namespace {

std::ofstream open_or_throw(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot write");
    out << std::setprecision(17);
    return out;
}

const char* kHeader = "<?xml version=\"1.0\"?>\n";

}  // namespace

std::string piece_path(const std::string& prefix, int rank) { return prefix + "_" + std::to_string(rank) + ".vtu"; }

void write_piece(const std::string& path, const geometry::HexMesh& mesh, int rank, const std::vector<std::uint64_t>& vertex_id) {
    std::ofstream out = open_or_throw(path);
    out << kHeader << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << mesh.hexes.size() << "\">\n"
        << "      <CellData>\n        <DataArray type=\"Int32\" Name=\"rank\" format=\"ascii\">\n";
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << rank << '\n';
    out << "        </DataArray>\n        <DataArray type=\"UInt64\" Name=\"vertex_id\" format=\"ascii\">\n";
    for (std::uint64_t id : vertex_id) out << id << '\n';
    out << "        </DataArray>\n      </CellData>\n      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    out << "        </DataArray>\n      </Points>\n      <Cells>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& h : mesh.hexes) {
        for (int v : h) out << v << ' ';
        out << '\n';
    }
    out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << 8 * (h + 1) << '\n';
    out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) out << "12\n";  // VTK_HEXAHEDRON
    out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    if (!out) throw std::runtime_error(path + ": write failed");
}

void write_pvtu(const std::string& prefix, int ranks) {
    const std::string path = prefix + ".pvtu";
    std::ofstream out = open_or_throw(path);
    out << kHeader << "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PCellData>\n"
        << "      <PDataArray type=\"Int32\" Name=\"rank\"/>\n      <PDataArray type=\"UInt64\" Name=\"vertex_id\"/>\n"
        << "    </PCellData>\n    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (int r = 0; r < ranks; ++r)
        out << "    <Piece Source=\"" << std::filesystem::path(piece_path(prefix, r)).filename().string() << "\"/>\n";
    out << "  </PUnstructuredGrid>\n</VTKFile>\n";
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace dualhex::dist
