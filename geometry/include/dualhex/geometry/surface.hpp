#pragma once
// A closed triangle surface as plain arrays (Eigen points, int triangles), read from
// OBJ, OFF, STL (ASCII or binary) or PLY (ASCII or binary) by dualhex's own strict readers
// (geometry/src/read_*.cpp), in double precision.
//
// Input : a regular file (format by extension: .obj, .off, .stl, .ply).
// Output: a TriangleSurface whose every vertex is used by some triangle, and a
//         SurfaceReport (counts, bounding box, closedness, warnings).
// Errors: SurfaceError, what() = "file:line: what, 'value'" for anything the reader cannot
//         parse (a number that is not a finite decimal, a count the file cannot hold, a
//         truncated file, an index out of range; binary formats name the record and its
//         byte offset), "file: message" for an empty mesh, a degenerate triangle, an open
//         or non-manifold surface (unless allowed; the message names the first bad edges)
//         or a self-intersecting one (the first intersecting triangle pairs). Never a
//         crash, a hang or an allocation the file size does not justify.
//
// Polygons with more than 3 corners are split into a triangle fan (OFF/OBJ/PLY allow
// them). Unused vertices (e.g. the duplicate in the gao_* files) are dropped with a
// warning; STL corners are welded by exact equality of the parsed values.
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dualhex::geometry {

struct TriangleSurface {
    std::vector<Eigen::Vector3d> vertices;
    /// Vertex ids, counter-clockwise seen from outside when the surface is oriented.
    std::vector<std::array<int, 3>> triangles;
    /// The file it came from (empty if built in memory): names it in messages.
    std::string source;
};

class SurfaceError : public std::runtime_error {
public:
    /// what() = "file: message" ("message" if `file` is empty). Control bytes and
    /// non-ASCII bytes of `file` are shown as \xNN, so a NUL cannot cut the message.
    SurfaceError(std::string file, const std::string& message);
    /// what() = "file:line: message" (1-based line).
    SurfaceError(std::string file, std::int64_t line, const std::string& message);
    [[nodiscard]] const std::string& file() const { return file_; }

private:
    std::string file_;
};

/// An undirected edge (smaller vertex id first) with the number of triangles using it.
struct EdgeUse {
    int a = 0, b = 0;
    int triangles = 0;
};

/// Edge structure of a surface: closed and edge-manifold iff every edge has exactly two
/// triangles; consistently oriented iff those two use it in opposite directions.
struct EdgeCheck {
    std::size_t edges = 0;
    std::vector<EdgeUse> boundary;      ///< edges with one triangle
    std::vector<EdgeUse> non_manifold;  ///< edges with three or more triangles
    std::size_t misoriented = 0;        ///< 2-triangle edges walked the same way by both
    [[nodiscard]] bool closed() const { return boundary.empty() && non_manifold.empty(); }
};

/// Edge use counts of `s` (O(F log F)).
[[nodiscard]] EdgeCheck check_edges(const TriangleSurface& s);

/// Axis-aligned bounding box of the vertices (empty box for no vertices).
[[nodiscard]] Eigen::AlignedBox3d bounding_box(const TriangleSurface& s);

/// Signed enclosed volume (positive iff triangles are oriented outward).
[[nodiscard]] double signed_volume(const TriangleSurface& s);

struct SurfaceReport {
    std::size_t file_vertices = 0;  ///< vertices as the file lists them (after STL welding)
    std::size_t file_faces = 0;     ///< faces as the file lists them (polygons count once)
    std::size_t vertices = 0;       ///< after dropping unused vertices
    std::size_t triangles = 0;
    std::size_t dropped_vertices = 0;
    Eigen::AlignedBox3d bbox;
    bool closed = false;            ///< every edge has exactly two triangles
    bool oriented = false;          ///< closed and consistently oriented
    std::vector<std::string> warnings;
};

/// The scale range a surface must be in (clean_surface refuses others): its bounding box
/// diagonal at least kMinSurfaceSize and at least kMinRelativeSize times the largest
/// coordinate magnitude (readers refuse coordinates beyond +-1e100).
inline constexpr double kMinSurfaceSize = 1e-100;
inline constexpr double kMinRelativeSize = 1e-9;

struct SurfaceReadOptions {
    /// Refuse (throw SurfaceError) a surface with boundary or non-manifold edges.
    bool require_closed = true;
    /// Flip all triangles if the enclosed volume is negative (outward orientation).
    bool orient_outward = true;
    /// Refuse a surface with degenerate (collinear-corner) or intersecting triangles,
    /// decided with exact predicates (self_intersection.hpp). Only checked when closed.
    bool reject_self_intersections = true;
};

/// Reads `path`; `report` (optional) receives counts, bbox, closedness and warnings.
[[nodiscard]] TriangleSurface read_surface(const std::string& path, const SurfaceReadOptions& options = {},
                                           SurfaceReport* report = nullptr);

/// Validates an in-memory surface like read_surface does (indices in range, no repeated
/// corner in a triangle, closed if required, scale in range); drops unused vertices.
/// Throws SurfaceError.
[[nodiscard]] TriangleSurface clean_surface(TriangleSurface s, const SurfaceReadOptions& options = {},
                                            SurfaceReport* report = nullptr);

/// "12 boundary edges, e.g. (3,7) at (0 0 1)-(1 0 1), ...": how messages name bad edges.
[[nodiscard]] std::string describe_edges(const TriangleSurface& s, const std::vector<EdgeUse>& edges,
                                         const char* what, std::size_t max_listed = 5);

}  // namespace dualhex::geometry
