// Strict OBJ reader: "v x y z [w]" (w must be 1) or "v x y z r g b" (colours ignored),
// "f" with "i", "i/t", "i//n" or "i/t/n" corners (1-based, negative = relative to the
// vertices so far). Statements that carry no surface (vn vt vp o g s usemtl mtllib l p)
// are ignored; any other statement is refused, so freeform or unknown geometry is never
// silently dropped. A vertex line that does not parse is an error, never skipped (a
// skipped vertex would shift every later index).
#include "surface_parse.hpp"

#include <array>

namespace dualhex::geometry::detail {

namespace {

bool ignored_statement(std::string_view s) {
    static constexpr std::array<std::string_view, 10> kIgnored{"vn", "vt", "vp", "o", "g", "s", "usemtl", "mtllib", "l", "p"};
    for (auto k : kIgnored)
        if (s == k) return true;
    return false;
}

void read_vertex(const std::vector<std::string_view>& f, const LineCursor& cur, PolygonSoup& soup) {
    if (f.size() != 4 && f.size() != 5 && f.size() != 7)
        cur.fail("expected 'v x y z' (optionally w, or r g b), found " + std::to_string(f.size() - 1) + " values");
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c) p[c] = parse_coordinate(f[static_cast<std::size_t>(c + 1)], cur, "coordinate");
    for (std::size_t c = 4; c < f.size(); ++c) check_number(f[c], cur, "vertex colour or weight");
    if (f.size() == 5 && parse_coordinate(f[4], cur, "weight") != 1.0)
        cur.fail("homogeneous weight other than 1 is not supported, " + quoted(f[4]));
    soup.points.push_back(p);
}

// "12", "12/3", "12//7", "-1/2/3" -> the 0-based vertex id.
std::int64_t corner_id(std::string_view token, const LineCursor& cur, std::size_t defined) {
    const std::string_view index = token.substr(0, token.find('/'));
    const std::int64_t i = parse_integer(index, cur, "vertex index");
    const auto n = static_cast<std::int64_t>(defined);
    if (i == 0) cur.fail("vertex index 0 (OBJ indices start at 1), " + quoted(token));
    if (i > n || i < -n)
        cur.fail("vertex index " + std::to_string(i) + " refers to no vertex defined so far (" + std::to_string(n) +
                 "), " + quoted(token));
    return i > 0 ? i - 1 : n + i;
}

}  // namespace

PolygonSoup read_obj(std::string_view bytes, const std::string& source) {
    LineCursor cur(bytes, source);
    PolygonSoup soup;
    std::string_view line;
    std::vector<std::int64_t> ids;
    while (cur.next_content(line)) {
        const auto f = split_fields(line);
        if (f[0] == "v") {
            read_vertex(f, cur, soup);
        } else if (f[0] == "f") {
            ids.clear();
            for (std::size_t c = 1; c < f.size(); ++c) ids.push_back(corner_id(f[c], cur, soup.points.size()));
            add_polygon(soup, ids, [&](const std::string& m) { cur.fail(m + ", in " + quoted(line)); });
        } else if (!ignored_statement(f[0])) {
            cur.fail("unsupported OBJ statement " + quoted(f[0]));
        }
    }
    return soup;
}

}  // namespace dualhex::geometry::detail
