// read_surface: the file's bytes through one of the strict readers (read_*.cpp), then
// clean_surface (indices, unused vertices, closedness, orientation) and, for closed
// surfaces, the exact self-intersection check. OpenMesh is no longer on this path.
#include <cctype>
#include <filesystem>
#include <fstream>

#include "dualhex/geometry/self_intersection.hpp"
#include "dualhex/geometry/surface.hpp"
#include "surface_parse.hpp"

namespace dualhex::geometry {

namespace {

std::string read_bytes(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw SurfaceError(path, "no such file");
    // A FIFO, device or directory could block, never end or not be a file at all.
    if (!fs::is_regular_file(status)) throw SurfaceError(path, "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SurfaceError(path, "cannot open for reading");
    const auto size = fs::file_size(path, ec);
    if (ec) throw SurfaceError(path, "cannot read the file size");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) throw SurfaceError(path, "cannot read the whole file");
    return bytes;
}

detail::PolygonSoup parse(const std::string& bytes, const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".obj") return detail::read_obj(bytes, path);
    if (ext == ".off") return detail::read_off(bytes, path);
    if (ext == ".stl") return detail::read_stl(bytes, path);
    if (ext == ".ply") return detail::read_ply(bytes, path);
    throw SurfaceError(path, "unknown surface format " + detail::quoted(ext) + " (expected .obj, .off, .stl, .ply)");
}

}  // namespace

TriangleSurface read_surface(const std::string& path, const SurfaceReadOptions& options, SurfaceReport* report) {
    detail::PolygonSoup soup = parse(read_bytes(path), path);
    SurfaceReport local;
    SurfaceReport& r = report ? *report : local;
    r = SurfaceReport{};
    r.file_vertices = soup.points.size();
    r.file_faces = soup.faces;

    TriangleSurface s;
    s.source = path;
    s.vertices = std::move(soup.points);
    s.triangles = std::move(soup.triangles);
    s = clean_surface(std::move(s), options, &r);
    if (options.reject_self_intersections && r.closed) {
        const SelfIntersections found = find_self_intersections(s);
        if (!found.empty()) throw SurfaceError(path, "surface is not embedded: " + found.describe(s));
    }
    return s;
}

}  // namespace dualhex::geometry
