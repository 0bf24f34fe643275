// VTK XML UnstructuredGrid reader: one Piece, Points, and the Cells arrays connectivity,
// offsets, types (and faces / faceoffsets for VTK_POLYHEDRON cells).
#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

#include "cell_stream.hpp"
#include "dualhex/audit/read_mesh.hpp"
#include "dualhex/grid/input_error.hpp"
#include "text_scanner.hpp"
#include "vtu_data_array.hpp"
#include "xml_scan.hpp"

namespace dualhex::audit {
namespace {

using detail::DataArrayValues;
using detail::XmlScanner;
using detail::XmlTag;

std::string attribute(const XmlTag& tag, const char* key) {
    const auto it = tag.attrs.find(key);
    return it == tag.attrs.end() ? std::string() : it->second;
}

std::int64_t count_attribute(XmlScanner& xml, const XmlTag& tag, const char* key, std::size_t file_size) {
    const std::string s = attribute(tag, key);
    std::int64_t v = 0;
    std::size_t used = 0;
    try {
        v = std::stoll(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (s.empty() || used != s.size() || v < 0)
        xml.fail(tag.begin, std::string("bad ") + key + " '" + s + "' in <" + tag.name + ">");
    if (static_cast<std::uint64_t>(v) > file_size)
        xml.fail(tag.begin, std::string(key) + " " + s + " exceeds what the file (" + std::to_string(file_size) +
                                " bytes) can hold");
    return v;
}

struct CellArrays {
    std::optional<DataArrayValues> connectivity, offsets, types, faces, faceoffsets;
};

int value_line(const DataArrayValues& a, std::size_t i) { return a.lines.empty() ? a.tag_line : a.lines[i]; }

void assemble_cells(const std::string& path, const CellArrays& a, std::size_t n_cells, MeshFile& mesh) {
    const auto need = [&](const std::optional<DataArrayValues>& x, const char* name) -> const DataArrayValues& {
        if (!x) throw InputError(path, 0, std::string("no Cells DataArray Name=\"") + name + "\"");
        return *x;
    };
    const auto& conn = need(a.connectivity, "connectivity");
    const auto& offsets = need(a.offsets, "offsets");
    const auto& types = need(a.types, "types");
    if ((a.faces.has_value()) != (a.faceoffsets.has_value()))
        throw InputError(path, 0, "a \"faces\" DataArray needs \"faceoffsets\" and vice versa");
    std::int64_t prev = 0, prev_face = 0;
    for (std::size_t c = 0; c < n_cells; ++c) {
        const std::int64_t end = offsets.ints[c];
        if (end < prev || end > static_cast<std::int64_t>(conn.ints.size()))
            throw InputError(path, value_line(offsets, c), "offsets: cell " + std::to_string(c) + " ends at " +
                                                              std::to_string(end) + " (previous " + std::to_string(prev) +
                                                              ", connectivity size " + std::to_string(conn.ints.size()) + ")");
        MeshCell cell;
        cell.type = static_cast<int>(types.ints[c]);
        cell.index = c;
        cell.line = prev < end ? value_line(conn, static_cast<std::size_t>(prev)) : value_line(offsets, c);
        cell.points.assign(conn.ints.begin() + prev, conn.ints.begin() + end);
        if (auto e = detail::point_id_error(cell.points, mesh.points.size()))
            throw InputError(path, cell.line, "cell " + std::to_string(c) + ": " + *e);
        if (cell.type == kVtkPolyhedron) {
            if (!a.faces) throw InputError(path, value_line(types, c), "polyhedron cell " + std::to_string(c) + " but no faces array");
            const std::int64_t face_end = a.faceoffsets->ints[c];
            if (face_end < prev_face || face_end > static_cast<std::int64_t>(a.faces->ints.size()))
                throw InputError(path, value_line(*a.faceoffsets, c), "faceoffsets: bad offset " + std::to_string(face_end) +
                                                                           " for cell " + std::to_string(c));
            const std::span<const std::int64_t> stream(a.faces->ints.data() + prev_face, static_cast<std::size_t>(face_end - prev_face));
            if (auto e = detail::decode_face_stream(stream, mesh.points.size(), cell.faces))
                throw InputError(path, value_line(*a.faces, static_cast<std::size_t>(prev_face)),
                                 "cell " + std::to_string(c) + " (polyhedron): " + *e);
            prev_face = face_end;
        } else if (auto e = detail::cell_type_error(cell.type, cell.points.size())) {
            throw InputError(path, value_line(types, c), "cell " + std::to_string(c) + ": " + *e);
        }
        prev = end;
        if (is_volume_type(cell.type)) mesh.cells.push_back(std::move(cell));
        else ++mesh.lower_dimensional_cells;
    }
    if (prev != static_cast<std::int64_t>(conn.ints.size()))
        throw InputError(path, conn.tag_line, "connectivity has " + std::to_string(conn.ints.size()) +
                                                  " values, the offsets use " + std::to_string(prev));
}

// <AppendedData encoding="raw|base64"> then blanks and '_': the data starts after the '_'.
void read_appended_header(const std::string& path, const std::string& file, std::size_t at, detail::VtuFileInfo& info) {
    XmlScanner xml(path, std::string_view(file).substr(at, file.find('>', at) == std::string::npos ? std::string::npos
                                                                                                 : file.find('>', at) - at + 1));
    XmlTag tag;
    const int line = 1 + static_cast<int>(std::count(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    if (!xml.next(tag)) throw InputError(path, line, "unterminated <AppendedData>");
    const std::string encoding = attribute(tag, "encoding");
    if (encoding != "raw" && encoding != "base64")
        throw InputError(path, line, "<AppendedData> encoding '" + encoding + "' (expected raw or base64)");
    const std::size_t underscore = file.find('_', at + tag.end);
    if (underscore == std::string::npos) throw InputError(path, line, "<AppendedData> without its '_' marker");
    for (std::size_t i = at + tag.end; i < underscore; ++i)
        if (!std::isspace(static_cast<unsigned char>(file[i]))) throw InputError(path, line, "text before the '_' of <AppendedData>");
    info.appended = std::string_view(file).substr(underscore + 1);
    info.appended_base64 = encoding == "base64";
    info.appended_line = line;
}

}  // namespace

MeshFile read_vtu(const std::string& path) {
    const std::string file = detail::read_regular_file(path);
    // Appended binary may hold any byte: the XML is scanned only up to <AppendedData>.
    const std::size_t appended_at = file.find("<AppendedData");
    const std::string_view text = std::string_view(file).substr(0, appended_at);
    XmlScanner xml(path, text);
    MeshFile mesh;
    mesh.path = path;
    mesh.format = "vtu";
    XmlTag tag;
    if (!xml.next(tag) || tag.name != "VTKFile") throw InputError(path, 1, "not a VTK XML file (no <VTKFile>)");
    if (attribute(tag, "type") != "UnstructuredGrid")
        xml.fail(tag.begin, "VTKFile type '" + attribute(tag, "type") + "' is not UnstructuredGrid");
    if (!attribute(tag, "compressor").empty()) xml.fail(tag.begin, "compressed data (compressor=\"" + attribute(tag, "compressor") + "\") is not supported");
    if (attribute(tag, "byte_order") == "BigEndian") xml.fail(tag.begin, "byte_order BigEndian is not supported");
    const std::string header = attribute(tag, "header_type");
    if (!header.empty() && header != "UInt32" && header != "UInt64") xml.fail(tag.begin, "bad header_type '" + header + "'");
    detail::VtuFileInfo info{header == "UInt64", {}, false, 0};
    if (appended_at != std::string::npos) read_appended_header(path, file, appended_at, info);

    std::int64_t n_points = -1, n_cells = -1;
    std::string section;  // the enclosing Points / Cells / PointData / CellData
    CellArrays cells;
    bool piece_done = false;
    while (!piece_done && xml.next(tag)) {
        if (tag.name == "Piece" && !tag.closing) {
            if (n_points >= 0) xml.fail(tag.begin, "more than one <Piece> is not supported");
            n_points = count_attribute(xml, tag, "NumberOfPoints", file.size());
            n_cells = count_attribute(xml, tag, "NumberOfCells", file.size());
        } else if (tag.name == "Piece") {
            piece_done = true;
        } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "PointData" || tag.name == "CellData") {
            section = tag.closing || tag.self_closing ? "" : tag.name;
        } else if (tag.name == "DataArray" && !tag.closing) {
            if (n_points < 0) xml.fail(tag.begin, "DataArray outside a <Piece>");
            const std::string name = attribute(tag, "Name");
            const auto n = static_cast<std::size_t>(n_cells);
            if (section == "Points") {
                if (!mesh.points.empty()) xml.fail(tag.begin, "a second Points DataArray");
                if (attribute(tag, "NumberOfComponents") != "3") xml.fail(tag.begin, "Points need NumberOfComponents=\"3\"");
                const auto v = detail::read_data_array(xml, tag, info, 3 * static_cast<std::size_t>(n_points), false, "Points");
                mesh.points.resize(static_cast<std::size_t>(n_points));
                for (std::size_t i = 0; i < mesh.points.size(); ++i)
                    mesh.points[i] = {v.reals[3 * i], v.reals[3 * i + 1], v.reals[3 * i + 2]};
            } else if (section == "Cells" && name == "connectivity") {
                cells.connectivity = detail::read_data_array(xml, tag, info, detail::kAnyCount, true, "connectivity");
            } else if (section == "Cells" && name == "offsets") {
                cells.offsets = detail::read_data_array(xml, tag, info, n, true, "offsets");
            } else if (section == "Cells" && name == "types") {
                cells.types = detail::read_data_array(xml, tag, info, n, true, "types");
            } else if (section == "Cells" && name == "faces") {
                cells.faces = detail::read_data_array(xml, tag, info, detail::kAnyCount, true, "faces");
            } else if (section == "Cells" && name == "faceoffsets") {
                cells.faceoffsets = detail::read_data_array(xml, tag, info, n, true, "faceoffsets");
            } else if (section == "Cells") {
                xml.fail(tag.begin, "unknown Cells DataArray Name=\"" + name + "\"");
            } else {
                (void)xml.content(tag);  // point / cell data: not audited
            }
        }
    }
    if (n_points < 0) throw InputError(path, xml.line_of(text.size()), "no <Piece> (truncated file?)");
    if (!piece_done) throw InputError(path, xml.line_of(text.size()), "<Piece> is never closed (truncated file?)");
    if (mesh.points.size() != static_cast<std::size_t>(n_points)) throw InputError(path, 0, "no Points DataArray");
    assemble_cells(path, cells, static_cast<std::size_t>(n_cells), mesh);
    return mesh;
}

MeshFile read_mesh(const std::string& path) {
    const auto dot = path.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    if (ext == ".vtk") return read_vtk_legacy(path);
    if (ext == ".vtu") return read_vtu(path);
    if (ext == ".mesh") return read_medit(path);
    throw InputError(path, 0, "unknown mesh format '" + ext + "' (expected .vtk, .vtu or .mesh)");
}

}  // namespace dualhex::audit
