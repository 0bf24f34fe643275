#include "dualhex/geometry/surface.hpp"

#include <algorithm>
#include <sstream>

namespace dualhex::geometry {

namespace {
// Control bytes shown as \xNN: a NUL or an escape sequence in a file name cannot cut or
// garble the message.
std::string printable(const std::string& text) {
    std::string out;
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c != 0x7f) {
            out += ch;
        } else {
            static const char* hex = "0123456789abcdef";
            out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
        }
    }
    return out;
}
}  // namespace

SurfaceError::SurfaceError(std::string file, const std::string& message)
    : std::runtime_error(file.empty() ? printable(message) : printable(file) + ": " + printable(message)),
      file_(std::move(file)) {}

SurfaceError::SurfaceError(std::string file, std::int64_t line, const std::string& message)
    : std::runtime_error(printable(file) + ":" + std::to_string(line) + ": " + printable(message)),
      file_(std::move(file)) {}

EdgeCheck check_edges(const TriangleSurface& s) {
    // Directed half-edges sorted by undirected key; runs of equal keys are one edge.
    struct Half {
        int a, b;   // undirected, a < b
        bool forward;
    };
    std::vector<Half> halves;
    halves.reserve(3 * s.triangles.size());
    for (const auto& t : s.triangles)
        for (int c = 0; c < 3; ++c) {
            const int u = t[c], v = t[(c + 1) % 3];
            halves.push_back({std::min(u, v), std::max(u, v), u < v});
        }
    std::sort(halves.begin(), halves.end(),
              [](const Half& x, const Half& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    EdgeCheck out;
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i;
        while (j < halves.size() && halves[j].a == halves[i].a && halves[j].b == halves[i].b) ++j;
        const int n = static_cast<int>(j - i);
        ++out.edges;
        if (n == 1) out.boundary.push_back({halves[i].a, halves[i].b, 1});
        else if (n > 2) out.non_manifold.push_back({halves[i].a, halves[i].b, n});
        else if (halves[i].forward == halves[i + 1].forward) ++out.misoriented;
        i = j;
    }
    return out;
}

Eigen::AlignedBox3d bounding_box(const TriangleSurface& s) {
    Eigen::AlignedBox3d box;
    for (const auto& p : s.vertices) box.extend(p);
    return box;
}

double signed_volume(const TriangleSurface& s) {
    // Tetrahedra from a point of the surface, not from the origin: far from the origin the
    // terms would be huge and cancel (a 0.001 cube at 1e4 came out with 10^4 times its volume).
    if (s.vertices.empty()) return 0;
    const Eigen::Vector3d o = s.vertices.front();
    double v = 0;
    for (const auto& t : s.triangles)
        v += (s.vertices[t[0]] - o).dot((s.vertices[t[1]] - o).cross(s.vertices[t[2]] - o));
    return v / 6.0;
}

std::string describe_edges(const TriangleSurface& s, const std::vector<EdgeUse>& edges, const char* what,
                           std::size_t max_listed) {
    std::ostringstream os;
    os << edges.size() << ' ' << what << (edges.size() == 1 ? " edge" : " edges");
    for (std::size_t n = 0; n < edges.size() && n < max_listed; ++n) {
        const auto& e = edges[n];
        const auto& p = s.vertices[e.a];
        const auto& q = s.vertices[e.b];
        os << (n == 0 ? ", e.g. " : ", ") << "vertices " << e.a << '-' << e.b << " at (" << p.x() << ' '
           << p.y() << ' ' << p.z() << ")-(" << q.x() << ' ' << q.y() << ' ' << q.z() << ')';
        if (e.triangles > 2) os << " [" << e.triangles << " triangles]";
    }
    if (edges.size() > max_listed) os << ", ...";
    return os.str();
}

namespace {
// The floating-point stages (octree, distances, projection) need the model to span many
// ulps of its coordinates and its squared size to stay clear of underflow.
void check_scale(const TriangleSurface& s, const Eigen::AlignedBox3d& box) {
    const double size = box.diagonal().norm();
    const double far = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
    std::ostringstream os;
    os.precision(3);
    if (!(size >= kMinSurfaceSize) || size < kMinRelativeSize * far) {
        os << "surface too small to mesh: bounding box diagonal " << size << " at distance " << far
           << " from the origin (needs >= " << kMinSurfaceSize << " and >= " << kMinRelativeSize
           << " times that distance)";
        throw SurfaceError(s.source, os.str());
    }
}
}  // namespace

TriangleSurface clean_surface(TriangleSurface s, const SurfaceReadOptions& options, SurfaceReport* report) {
    SurfaceReport local;
    SurfaceReport& r = report ? *report : local;
    if (r.file_vertices == 0) r.file_vertices = s.vertices.size();
    if (r.file_faces == 0) r.file_faces = s.triangles.size();
    if (s.triangles.empty()) throw SurfaceError(s.source, "no faces");
    const int nv = static_cast<int>(s.vertices.size());
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
        const auto& t = s.triangles[f];
        for (int c : t)
            if (c < 0 || c >= nv)
                throw SurfaceError(s.source, "triangle " + std::to_string(f) + " refers to vertex " +
                                                 std::to_string(c) + " of " + std::to_string(nv));
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            throw SurfaceError(s.source, "triangle " + std::to_string(f) + " repeats a vertex (" +
                                             std::to_string(t[0]) + ' ' + std::to_string(t[1]) + ' ' +
                                             std::to_string(t[2]) + ")");
    }
    for (const auto& p : s.vertices)
        if (!p.allFinite()) throw SurfaceError(s.source, "a vertex coordinate is not finite");
    // Drop unused vertices, keeping the order of the rest.
    std::vector<int> remap(s.vertices.size(), -1);
    for (const auto& t : s.triangles)
        for (int c : t) remap[c] = 0;
    int next = 0;
    std::vector<Eigen::Vector3d> kept;
    kept.reserve(s.vertices.size());
    std::string unused;
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        if (remap[v] < 0) {
            if (r.dropped_vertices < 5) unused += (unused.empty() ? "" : ", ") + std::to_string(v);
            ++r.dropped_vertices;
            continue;
        }
        remap[v] = next++;
        kept.push_back(s.vertices[v]);
    }
    if (r.dropped_vertices > 0) {
        for (auto& t : s.triangles)
            for (int& c : t) c = remap[c];
        s.vertices = std::move(kept);
        r.warnings.push_back(s.source + ": dropped " + std::to_string(r.dropped_vertices) +
                             " unused vertex(es) (file ids " + unused + (r.dropped_vertices > 5 ? ", ..." : "") +
                             ")");
    }
    const EdgeCheck edges = check_edges(s);
    r.closed = edges.closed();
    r.oriented = r.closed && edges.misoriented == 0;
    if (options.require_closed && !r.closed) {
        std::string msg = "surface is not closed and manifold: ";
        if (!edges.boundary.empty()) msg += describe_edges(s, edges.boundary, "boundary");
        if (!edges.non_manifold.empty())
            msg += std::string(edges.boundary.empty() ? "" : "; ") +
                   describe_edges(s, edges.non_manifold, "non-manifold");
        throw SurfaceError(s.source, msg);
    }
    if (options.require_closed && edges.misoriented > 0)
        throw SurfaceError(s.source, "surface is not consistently oriented: " + std::to_string(edges.misoriented) +
                                         " edges are walked the same way by both triangles");
    if (options.orient_outward && r.oriented && signed_volume(s) < 0) {
        for (auto& t : s.triangles) std::swap(t[1], t[2]);
        r.warnings.push_back(s.source + ": triangles were oriented inward; flipped");
    }
    r.vertices = s.vertices.size();
    r.triangles = s.triangles.size();
    r.bbox = bounding_box(s);
    check_scale(s, r.bbox);
    return s;
}

}  // namespace dualhex::geometry
