// Strict STL reader, ASCII and binary. Binary is recognised by its size (84 + 50 n bytes
// for the n triangles its header counts), whatever its first bytes say (binary headers
// often start with "solid"); otherwise the file must be ASCII "solid ... endsolid".
// Corners are welded by exact equality of the parsed values (the same value is the same
// vertex); binary floats widen to doubles exactly.
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>

#include "surface_parse.hpp"

namespace dualhex::geometry::detail {

namespace {

constexpr std::size_t kBinaryHeader = 84, kBinaryRecord = 50;

std::uint32_t le32(const char* p) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
    return v;
}

float le_float(const char* p) {
    const std::uint32_t bits = le32(p);
    float f = 0;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

void add_triangle(PolygonSoup& soup, PointWelder& welder, const std::array<Eigen::Vector3d, 3>& corners,
                  const std::function<void(const std::string&)>& fail) {
    std::vector<std::int64_t> ids;
    for (const auto& p : corners) ids.push_back(welder.id(p));
    add_polygon(soup, ids, fail);
}

PolygonSoup read_binary(std::string_view bytes, const std::string& source, std::size_t n) {
    PolygonSoup soup;
    PointWelder welder(soup);
    soup.triangles.reserve(n);
    for (std::size_t t = 0; t < n; ++t) {
        const std::size_t at = kBinaryHeader + t * kBinaryRecord;
        const auto fail = [&](const std::string& m) {
            throw SurfaceError(source, "binary triangle " + std::to_string(t) + " at byte " + std::to_string(at) + ": " + m);
        };
        std::array<Eigen::Vector3d, 3> corners;
        for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) {
                const double x = le_float(bytes.data() + at + 12 + 12 * c + 4 * d);  // after the normal
                if (!std::isfinite(x)) fail("coordinate is not finite");
                corners[static_cast<std::size_t>(c)][d] = x;
            }
        add_triangle(soup, welder, corners, fail);
    }
    return soup;
}

// The line must be exactly `n` fields starting "a" (and "b" unless empty).
void expect(const std::vector<std::string_view>& f, std::string_view a, std::string_view b, std::size_t n,
            const LineCursor& cur) {
    const bool ok = f.size() == n && f[0] == a && (b.empty() || f[1] == b);
    if (ok) return;
    // (built by appending: `"x" + std::string` trips GCC 12's -Wrestrict false positive)
    std::string line, want(a);
    for (auto x : f) {
        if (!line.empty()) line += ' ';
        line += x;
    }
    if (!b.empty()) {
        want += ' ';
        want += b;
    }
    std::string message = "expected '";
    message += want;
    message += "', found ";
    message += quoted(line);
    cur.fail(message);
}

PolygonSoup read_ascii(std::string_view bytes, const std::string& source) {
    LineCursor cur(bytes, source);
    PolygonSoup soup;
    PointWelder welder(soup);
    std::string_view line;
    bool in_solid = false, any_solid = false;
    while (cur.next_content(line)) {
        auto f = split_fields(line);
        if (!in_solid) {
            if (f[0] != "solid") cur.fail("expected 'solid', found " + quoted(line));
            in_solid = any_solid = true;
            continue;
        }
        if (f[0] == "endsolid") {
            in_solid = false;
            continue;
        }
        expect(f, "facet", "normal", 5, cur);
        for (std::size_t c = 2; c < 5; ++c) check_number(f[c], cur, "normal");
        const std::int64_t facet_line = cur.line();
        if (!cur.next_content(line)) cur.fail("file ends inside a facet");
        expect(split_fields(line), "outer", "loop", 2, cur);
        std::array<Eigen::Vector3d, 3> corners;
        for (auto& p : corners) {
            if (!cur.next_content(line)) cur.fail("file ends inside a facet");
            f = split_fields(line);
            expect(f, "vertex", "", 4, cur);
            for (int d = 0; d < 3; ++d) p[d] = parse_coordinate(f[static_cast<std::size_t>(d + 1)], cur, "coordinate");
        }
        for (const char* end : {"endloop", "endfacet"}) {
            if (!cur.next_content(line)) cur.fail("file ends inside a facet");
            expect(split_fields(line), end, "", 1, cur);
        }
        add_triangle(soup, welder, corners, [&](const std::string& m) {
            throw SurfaceError(source, facet_line, "facet: " + m);
        });
    }
    if (!any_solid) cur.fail("empty file (expected 'solid')");
    if (in_solid) cur.fail("file ends without 'endsolid'");
    return soup;
}

bool starts_with_solid(std::string_view bytes) {
    std::size_t p = 0;
    while (p < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[p]))) ++p;
    return bytes.substr(p, 5) == "solid";
}

}  // namespace

PolygonSoup read_stl(std::string_view bytes, const std::string& source) {
    if (bytes.size() >= kBinaryHeader) {
        const std::size_t n = le32(bytes.data() + 80);
        if ((bytes.size() - kBinaryHeader) / kBinaryRecord == n && (bytes.size() - kBinaryHeader) % kBinaryRecord == 0)
            return read_binary(bytes, source, n);
        if (!starts_with_solid(bytes))
            throw SurfaceError(source, "binary STL header counts " + std::to_string(n) + " triangles (" +
                                           std::to_string(kBinaryHeader + kBinaryRecord * n) + " bytes) but the file has " +
                                           std::to_string(bytes.size()) + " bytes");
    }
    if (!starts_with_solid(bytes)) throw SurfaceError(source, "neither ASCII STL ('solid') nor a complete binary STL");
    return read_ascii(bytes, source);
}

}  // namespace dualhex::geometry::detail
