// read_surface: OpenMesh's readers feed a minimal importer that only records the polygon
// soup (points and vertex index lists). No half-edge structure is built, so OpenMesh never
// silently drops a non-manifold face; closedness is then checked by clean_surface.
#include <cctype>
#include <filesystem>
#include <fstream>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {
namespace {

using namespace OpenMesh;

class SoupImporter final : public IO::BaseImporter {
public:
    std::vector<Eigen::Vector3d> points;
    std::vector<std::vector<int>> faces;

    VertexHandle add_vertex(const Vec3f& p) override { return add_vertex(Vec3d(p[0], p[1], p[2])); }
    VertexHandle add_vertex(const Vec3d& p) override {
        points.emplace_back(p[0], p[1], p[2]);
        return VertexHandle(static_cast<int>(points.size()) - 1);
    }
    VertexHandle add_vertex() override { return add_vertex(Vec3d(0, 0, 0)); }
    HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
    FaceHandle add_face(const VHandles& ids) override {
        std::vector<int> f;
        f.reserve(ids.size());
        for (const auto& v : ids) f.push_back(v.idx());
        faces.push_back(std::move(f));
        return FaceHandle(static_cast<int>(faces.size()) - 1);
    }
    FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
    void set_face_texindex(FaceHandle, int) override {}
    void set_point(VertexHandle v, const Vec3f& p) override {
        if (v.idx() >= 0 && static_cast<std::size_t>(v.idx()) < points.size()) points[v.idx()] = {p[0], p[1], p[2]};
    }
    void set_halfedge(VertexHandle, HalfedgeHandle) override {}
    void set_normal(VertexHandle, const Vec3f&) override {}
    void set_normal(VertexHandle, const Vec3d&) override {}
    void set_color(VertexHandle, const Vec3uc&) override {}
    void set_color(VertexHandle, const Vec4uc&) override {}
    void set_color(VertexHandle, const Vec3f&) override {}
    void set_color(VertexHandle, const Vec4f&) override {}
    void set_texcoord(VertexHandle, const Vec2f&) override {}
    void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
    void set_next(HalfedgeHandle, HalfedgeHandle) override {}
    void set_face(HalfedgeHandle, FaceHandle) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
    void set_texcoord(VertexHandle, const Vec3f&) override {}
    void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
    void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
    void set_color(EdgeHandle, const Vec3uc&) override {}
    void set_color(EdgeHandle, const Vec4uc&) override {}
    void set_color(EdgeHandle, const Vec3f&) override {}
    void set_color(EdgeHandle, const Vec4f&) override {}
    void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
    void set_normal(FaceHandle, const Vec3f&) override {}
    void set_normal(FaceHandle, const Vec3d&) override {}
    void set_color(FaceHandle, const Vec3uc&) override {}
    void set_color(FaceHandle, const Vec4uc&) override {}
    void set_color(FaceHandle, const Vec3f&) override {}
    void set_color(FaceHandle, const Vec4f&) override {}
    void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
    void add_texture_information(int, std::string) override {}
    void reserve(unsigned nv, unsigned, unsigned nf) override {
        points.reserve(nv);
        faces.reserve(nf);
    }
    size_t n_vertices() const override { return points.size(); }
    size_t n_faces() const override { return faces.size(); }
    size_t n_edges() const override { return 0; }
};

}  // namespace

TriangleSurface read_surface(const std::string& path, const SurfaceReadOptions& options, SurfaceReport* report) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw SurfaceError(path, "no such file");
    if (!std::ifstream(path)) throw SurfaceError(path, "cannot open for reading");
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".ply")
        throw SurfaceError(path, "unknown surface format '" + ext + "' (expected .obj, .off, .stl, .ply)");

    SoupImporter soup;
    IO::Options opt;
    bool ok = false;
    try {
        ok = IO::IOManager().read(path, soup, opt);
    } catch (const std::exception& e) {
        throw SurfaceError(path, std::string("OpenMesh reader failed: ") + e.what());
    }
    if (!ok) throw SurfaceError(path, "OpenMesh could not read the file (malformed " + ext + "?)");

    SurfaceReport local;
    SurfaceReport& r = report ? *report : local;
    r = SurfaceReport{};
    r.file_vertices = soup.points.size();
    r.file_faces = soup.faces.size();

    TriangleSurface s;
    s.source = path;
    s.vertices = std::move(soup.points);
    s.triangles.reserve(soup.faces.size());
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        const auto& poly = soup.faces[f];
        if (poly.size() < 3)
            throw SurfaceError(path, "face " + std::to_string(f) + " has " + std::to_string(poly.size()) + " vertices");
        for (std::size_t c = 1; c + 1 < poly.size(); ++c) s.triangles.push_back({poly[0], poly[c], poly[c + 1]});
    }
    return clean_surface(std::move(s), options, &r);
}

}  // namespace dualhex::geometry
