// VTK legacy reader (ASCII or BINARY, DATASET UNSTRUCTURED_GRID): POINTS, CELLS, CELL_TYPES; the
// 5.x layout (CELLS with OFFSETS / CONNECTIVITY) too, without polyhedra.
#include <string>
#include <vector>

#include "cell_stream.hpp"
#include "legacy_values.hpp"
#include "dualhex/audit/read_mesh.hpp"
#include "text_scanner.hpp"

namespace dualhex::audit {
namespace {

using detail::LegacyValues;
using detail::quote;
using detail::TextScanner;

struct RawCell {
    std::vector<std::int64_t> row;  // the CELLS row after its count (ids or a face stream)
    int line = 0;
};

// The three header lines; returns the offset of line 4 and sets `binary`.
std::size_t read_header(const std::string& path, const std::string& text, bool& binary) {
    std::size_t pos = 0;
    std::string lines[3];
    for (int i = 0; i < 3; ++i) {
        const std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) throw InputError(path, i + 1, "truncated header (expected 3 lines)");
        lines[i] = text.substr(pos, end - pos);
        while (!lines[i].empty() && (lines[i].back() == '\r' || lines[i].back() == ' ')) lines[i].pop_back();
        pos = end + 1;
    }
    if (lines[0].rfind("# vtk DataFile Version", 0) != 0)
        throw InputError(path, 1, "not a VTK legacy file (expected '# vtk DataFile Version', got " + quote(lines[0]) + ")");
    binary = lines[2] == "BINARY";
    if (lines[2] != "ASCII" && !binary) throw InputError(path, 3, "expected ASCII or BINARY, got " + quote(lines[2]));
    return pos;
}

void read_points(TextScanner& in, bool binary, MeshFile& mesh) {
    const std::int64_t n = in.read_int("point count");
    in.check_count(n, 3, "POINTS");
    const std::string_view type = in.expect("point data type");
    LegacyValues values(in, binary, 3 * n, type, "POINTS");
    mesh.points.resize(static_cast<std::size_t>(n));
    for (auto& p : mesh.points)
        for (double& x : p) x = values.read_double("point coordinate");
}

std::vector<RawCell> read_cells_classic(TextScanner& in, bool binary, std::int64_t n, std::int64_t size) {
    const int header_line = in.line();
    if (n > size) in.fail("CELLS count " + std::to_string(n) + " exceeds its size " + std::to_string(size));
    LegacyValues values(in, binary, size, "int", "CELLS");
    std::vector<RawCell> cells(static_cast<std::size_t>(n));
    std::int64_t used = 0;
    for (auto& c : cells) {
        const std::int64_t k = values.read_int("cell size");
        c.line = binary ? header_line : values.line();
        if (k < 0 || k > size - used - 1)
            in.fail("cell size " + std::to_string(k) + " overruns the CELLS size " + std::to_string(size));
        c.row.resize(static_cast<std::size_t>(k));
        for (auto& v : c.row) v = values.read_int("cell entry");
        used += 1 + k;
    }
    if (used != size) throw InputError(in.path(), header_line, "CELLS size " + std::to_string(size) + " but the rows hold " + std::to_string(used));
    return cells;
}

// Version 5: "CELLS n_offsets n_connectivity", OFFSETS type, values, CONNECTIVITY type, values.
std::vector<RawCell> read_cells_offsets(TextScanner& in, bool binary, std::int64_t n_offsets, std::int64_t n_conn) {
    in.check_count(n_offsets + n_conn, binary ? 0 : 1, "CELLS");
    std::vector<std::int64_t> offsets(static_cast<std::size_t>(n_offsets));
    std::vector<int> lines(offsets.size());
    LegacyValues offset_values(in, binary, n_offsets, in.expect("offsets type"), "OFFSETS");
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        offsets[i] = offset_values.read_int("offset");
        lines[i] = offset_values.line();
        if ((i == 0 && offsets[i] != 0) || (i > 0 && (offsets[i] < offsets[i - 1] || offsets[i] > n_conn)))
            in.fail("bad offset " + std::to_string(offsets[i]));
    }
    if (n_offsets < 1 || offsets.back() != n_conn) in.fail("the last offset must equal the connectivity size");
    if (in.expect("CONNECTIVITY") != "CONNECTIVITY") in.fail("expected CONNECTIVITY");
    LegacyValues conn(in, binary, n_conn, in.expect("connectivity type"), "CONNECTIVITY");
    std::vector<RawCell> cells(offsets.size() - 1);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        cells[c].line = lines[c];
        cells[c].row.resize(static_cast<std::size_t>(offsets[c + 1] - offsets[c]));
        for (auto& v : cells[c].row) v = conn.read_int("connectivity entry");
    }
    return cells;
}

void read_cell_types(TextScanner& in, bool binary, const std::vector<RawCell>& raw, bool offsets_layout,
                     MeshFile& mesh) {
    const std::int64_t n = in.read_int("CELL_TYPES count");
    if (n != static_cast<std::int64_t>(raw.size()))
        in.fail("CELL_TYPES count " + std::to_string(n) + " differs from CELLS count " + std::to_string(raw.size()));
    LegacyValues values(in, binary, n, "int", "CELL_TYPES");
    for (std::size_t c = 0; c < raw.size(); ++c) {
        const std::int64_t t = values.read_int("cell type");
        if (t < 0 || t > 255) in.fail("cell " + std::to_string(c) + ": cell type " + std::to_string(t) + " out of range [0, 255]");
        const int type = static_cast<int>(t);
        MeshCell cell;
        cell.type = type;
        cell.line = raw[c].line;
        cell.index = c;
        if (type == kVtkPolyhedron) {
            if (offsets_layout) in.fail("VTK_POLYHEDRON in a version-5 legacy file is not supported (write VTU)");
            if (auto e = detail::decode_face_stream(raw[c].row, mesh.points.size(), cell.faces))
                throw InputError(in.path(), raw[c].line, "cell " + std::to_string(c) + " (polyhedron): " + *e);
        } else {
            if (auto e = detail::cell_type_error(type, raw[c].row.size())) in.fail("cell " + std::to_string(c) + ": " + *e);
            if (auto e = detail::point_id_error(raw[c].row, mesh.points.size()))
                throw InputError(in.path(), raw[c].line, "cell " + std::to_string(c) + ": " + *e);
            cell.points = raw[c].row;
        }
        if (is_volume_type(type)) mesh.cells.push_back(std::move(cell));
        else ++mesh.lower_dimensional_cells;
    }
}

}  // namespace

MeshFile read_vtk_legacy(const std::string& path) {
    const std::string text = detail::read_regular_file(path);
    bool binary = false;
    const std::size_t body = read_header(path, text, binary);
    TextScanner in(path, std::string_view(text).substr(body), 4);
    MeshFile mesh;
    mesh.path = path;
    mesh.format = "vtk";
    if (in.expect("DATASET") != "DATASET") in.fail("expected DATASET");
    if (const auto t = in.expect("dataset type"); t != "UNSTRUCTURED_GRID")
        in.fail("dataset " + quote(t) + " is not UNSTRUCTURED_GRID");
    bool have_points = false, have_types = false, offsets_layout = false;
    std::vector<RawCell> raw;
    bool have_cells = false;
    std::string_view key;
    while (!have_types && in.next(key)) {
        if (key == "POINTS" && !have_points) {
            read_points(in, binary, mesh);
            have_points = true;
        } else if (key == "CELLS" && have_points && !have_cells) {
            const std::int64_t a = in.read_int("CELLS count"), b = in.read_int("CELLS size");
            in.check_count(a, 1, "CELLS");
            std::string_view next;
            TextScanner peek = in;
            offsets_layout = peek.next(next) && next == "OFFSETS";
            if (offsets_layout) {
                in.expect("OFFSETS");
                raw = read_cells_offsets(in, binary, a, b);
            } else {
                raw = read_cells_classic(in, binary, a, b);
            }
            have_cells = true;
        } else if (key == "CELL_TYPES" && have_cells) {
            read_cell_types(in, binary, raw, offsets_layout, mesh);
            have_types = true;
        } else if (key == "METADATA") {
            in.fail("METADATA is not supported");
        } else {
            in.fail("unexpected " + quote(key) + (have_points ? (have_cells ? " (expected CELL_TYPES)" : " (expected CELLS)")
                                                               : " (expected POINTS)"));
        }
    }
    if (!have_types)
        in.fail(std::string("unexpected end of file, expected ") +
                (!have_points ? "POINTS" : !have_cells ? "CELLS" : "CELL_TYPES"));
    return mesh;  // POINT_DATA / CELL_DATA / FIELD sections after the cells are not read
}

}  // namespace dualhex::audit
