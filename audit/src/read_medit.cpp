// MEDIT .mesh reader (ASCII): the volume elements with 1-based vertex ids; boundary
// elements and markers are counted and skipped.
#include <string>
#include <string_view>

#include "dualhex/audit/read_mesh.hpp"
#include "text_scanner.hpp"

namespace dualhex::audit {
namespace {

using detail::quote;
using detail::TextScanner;

struct Section {
    std::string_view keyword;
    int ids;   // vertex ids per entry (0: Vertices)
    int type;  // VTK type of the entry (0: lower-dimensional, skipped)
    int extra;  // further integers per entry (references)
};
// Entries: ids then one reference, except the single-id marker lists.
constexpr Section kSections[] = {
    {"Tetrahedra", 4, kVtkTetra, 1},   {"Prisms", 6, kVtkWedge, 1},     {"Pyramids", 5, kVtkPyramid, 1},
    {"Hexahedra", 8, kVtkHexahedron, 1}, {"Edges", 2, 0, 1},            {"Triangles", 3, 0, 1},
    {"Quadrilaterals", 4, 0, 1},       {"Corners", 1, 0, 0},            {"Ridges", 1, 0, 0},
    {"RequiredVertices", 1, 0, 0},     {"RequiredEdges", 1, 0, 0},      {"RequiredTriangles", 1, 0, 0},
    {"RequiredQuadrilaterals", 1, 0, 0},
};

void read_vertices(TextScanner& in, MeshFile& mesh) {
    if (!mesh.points.empty()) in.fail("a second Vertices section");
    const std::int64_t n = in.read_int("Vertices count");
    in.check_count(n, 4, "Vertices");
    mesh.points.resize(static_cast<std::size_t>(n));
    for (auto& p : mesh.points) {
        for (double& x : p) x = in.read_double("vertex coordinate");
        in.read_int("vertex reference");
    }
}

void read_elements(TextScanner& in, const Section& s, MeshFile& mesh, std::size_t& next_index) {
    const std::int64_t n = in.read_int(std::string(s.keyword) + " count");
    in.check_count(n, s.ids + s.extra, s.keyword);
    const auto n_points = static_cast<std::int64_t>(mesh.points.size());
    if (s.type != 0 && n_points == 0 && n > 0) in.fail(std::string(s.keyword) + " before Vertices");
    for (std::int64_t e = 0; e < n; ++e) {
        MeshCell cell;
        cell.type = s.type;
        cell.points.resize(static_cast<std::size_t>(s.ids));
        for (auto& v : cell.points) {
            v = in.read_int("vertex id");
            if (cell.line == 0) cell.line = in.line();
            if (s.type != 0 && (v < 1 || v > n_points))
                in.fail(std::string(s.keyword) + " " + std::to_string(e + 1) + ": vertex id " + std::to_string(v) +
                        " out of range [1, " + std::to_string(n_points) + "]");
            --v;  // 0-based
        }
        for (int r = 0; r < s.extra; ++r) in.read_int("reference");
        if (s.type == 0) {
            ++mesh.lower_dimensional_cells;
            continue;
        }
        cell.index = next_index++;
        mesh.cells.push_back(std::move(cell));
    }
}

}  // namespace

MeshFile read_medit(const std::string& path) {
    const std::string text = detail::read_regular_file(path);
    TextScanner in(path, text, 1, '#');
    MeshFile mesh;
    mesh.path = path;
    mesh.format = "medit";
    if (const auto t = in.expect("MeshVersionFormatted"); t != "MeshVersionFormatted")
        in.fail("not a MEDIT file (expected MeshVersionFormatted, got " + quote(t) + ")");
    in.read_int_in("mesh version", 1, 2);
    if (const auto t = in.expect("Dimension"); t != "Dimension") in.fail("expected Dimension, got " + quote(t));
    in.read_int_in("dimension", 3, 3);
    std::size_t next_index = 0;
    std::string_view key;
    bool ended = false;
    while (!ended && in.next(key)) {
        if (key == "End") {
            ended = true;
        } else if (key == "Vertices") {
            read_vertices(in, mesh);
        } else {
            const Section* section = nullptr;
            for (const Section& s : kSections)
                if (s.keyword == key) section = &s;
            if (section == nullptr) in.fail("unknown or unsupported keyword " + quote(key));
            read_elements(in, *section, mesh, next_index);
        }
    }
    if (!ended) in.fail("unexpected end of file, expected End");
    if (!in.at_end()) {
        std::string_view t;
        in.next(t);
        in.fail("data after End: " + quote(t));
    }
    return mesh;
}

}  // namespace dualhex::audit
