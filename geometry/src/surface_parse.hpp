#pragma once
// Shared pieces of the strict surface readers (read_obj/off/stl/ply.cpp): the polygon soup
// they fill, a line cursor over the file's bytes, strict number parsing and the errors.
//
// Every reader takes the whole file as bytes and never trusts a count it has not checked
// against the bytes left, so hostile input costs at most O(file size) memory and time.
// Every failure is a SurfaceError "file:line: what, 'value'" (binary formats name the
// record and its byte offset instead of a line).
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry::detail {

/// What a reader produces: points as doubles, polygons already split into triangle fans.
struct PolygonSoup {
    std::vector<Eigen::Vector3d> points;
    std::vector<std::array<int, 3>> triangles;
    std::size_t faces = 0;  ///< polygons as the file lists them
};

/// Magnitude limit of a coordinate: beyond it squared distances and volumes overflow.
inline constexpr double kMaxCoordinate = 1e100;

/// "'text'" with control bytes, quotes and non-ASCII shown as \xNN, cut after 60 bytes.
[[nodiscard]] std::string quoted(std::string_view text);

/// Splits bytes into lines ('\n', a trailing '\r' removed), counting them from 1.
class LineCursor {
public:
    LineCursor(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}
    /// Next line (false at the end of the bytes).
    bool next(std::string_view& line);
    /// Next line that is not blank once a '#' comment is cut off (false at the end).
    bool next_content(std::string_view& line);
    [[nodiscard]] std::int64_t line() const { return line_; }
    [[nodiscard]] std::size_t offset() const { return pos_; }
    [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }
    [[nodiscard]] const std::string& source() const { return source_; }
    /// Throws SurfaceError "source:line: message".
    [[noreturn]] void fail(const std::string& message) const;

private:
    std::string_view bytes_;
    const std::string& source_;
    std::size_t pos_ = 0;
    std::int64_t line_ = 0;
};

/// Whitespace-separated fields of a line.
[[nodiscard]] std::vector<std::string_view> split_fields(std::string_view line);

/// A decimal floating-point number, the whole token, finite and within kMaxCoordinate;
/// else `cursor.fail` naming `what` and the token.
[[nodiscard]] double parse_coordinate(std::string_view token, const LineCursor& cursor, const char* what);
/// Like parse_coordinate for values that are read and ignored (colours, normals): any finite double.
void check_number(std::string_view token, const LineCursor& cursor, const char* what);
/// A decimal integer, the whole token (an optional leading '-', no '+').
[[nodiscard]] std::int64_t parse_integer(std::string_view token, const LineCursor& cursor, const char* what);

/// Appends polygon `ids` (0-based, checked in [0, points) and without repeats) as a fan.
/// `fail(message)` reports a bad polygon where it was read.
template <class Fail>
void add_polygon(PolygonSoup& soup, const std::vector<std::int64_t>& ids, Fail&& fail) {
    if (ids.size() < 3) fail("face with " + std::to_string(ids.size()) + " corners (at least 3 needed)");
    const auto n = static_cast<std::int64_t>(soup.points.size());
    if (n > std::numeric_limits<int>::max()) fail("more vertices than int indices can address");
    for (std::size_t c = 0; c < ids.size(); ++c) {
        if (ids[c] < 0 || ids[c] >= n)
            fail("vertex index " + std::to_string(ids[c]) + " out of range [0, " + std::to_string(n) + ")");
        for (std::size_t d = 0; d < c; ++d)
            if (ids[d] == ids[c]) fail("face repeats vertex " + std::to_string(ids[c]));
    }
    for (std::size_t c = 1; c + 1 < ids.size(); ++c)
        soup.triangles.push_back({static_cast<int>(ids[0]), static_cast<int>(ids[c]), static_cast<int>(ids[c + 1])});
    ++soup.faces;
}

/// Welds points by exact equality of the parsed values (-0 equals +0): STL lists every
/// triangle's corners separately. Returns the vertex id of `p`.
class PointWelder {
public:
    explicit PointWelder(PolygonSoup& soup) : soup_(soup) {}
    int id(const Eigen::Vector3d& p);

private:
    struct Hash {
        std::size_t operator()(const std::array<double, 3>& p) const;
    };
    PolygonSoup& soup_;
    std::unordered_map<std::array<double, 3>, int, Hash> ids_;
};

// The four readers: `bytes` is the whole file, `source` names it in messages.
[[nodiscard]] PolygonSoup read_obj(std::string_view bytes, const std::string& source);
[[nodiscard]] PolygonSoup read_off(std::string_view bytes, const std::string& source);
[[nodiscard]] PolygonSoup read_stl(std::string_view bytes, const std::string& source);
[[nodiscard]] PolygonSoup read_ply(std::string_view bytes, const std::string& source);

}  // namespace dualhex::geometry::detail
