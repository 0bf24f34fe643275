#include "dualhex/audit/mesh_file.hpp"

#include "cell_stream.hpp"

namespace dualhex::audit {

std::string cell_type_name(int type) {
    switch (type) {
        case kVtkVertex: return "vertex";
        case kVtkLine: return "line";
        case kVtkTriangle: return "triangle";
        case kVtkPolygon: return "polygon";
        case kVtkQuad: return "quad";
        case kVtkTetra: return "tetra";
        case kVtkHexahedron: return "hexahedron";
        case kVtkWedge: return "wedge";
        case kVtkPyramid: return "pyramid";
        case kVtkPolyhedron: return "polyhedron";
        default: return "type " + std::to_string(type);
    }
}

bool is_volume_type(int type) {
    return type == kVtkTetra || type == kVtkHexahedron || type == kVtkWedge || type == kVtkPyramid ||
           type == kVtkPolyhedron;
}

int fixed_point_count(int type) {
    switch (type) {
        case kVtkVertex: return 1;
        case kVtkLine: return 2;
        case kVtkTriangle: return 3;
        case kVtkQuad: return 4;
        case kVtkTetra: return 4;
        case kVtkHexahedron: return 8;
        case kVtkWedge: return 6;
        case kVtkPyramid: return 5;
        default: return 0;
    }
}

namespace detail {

std::optional<std::string> cell_type_error(int type, std::size_t listed_points) {
    const bool known = type == kVtkVertex || type == kVtkLine || type == kVtkTriangle || type == kVtkPolygon ||
                       type == kVtkQuad || is_volume_type(type);
    if (!known) return "unsupported cell type " + std::to_string(type);
    const int n = fixed_point_count(type);
    if (n > 0 && listed_points != static_cast<std::size_t>(n))
        return cell_type_name(type) + " with " + std::to_string(listed_points) + " points (expected " +
               std::to_string(n) + ")";
    return std::nullopt;
}

std::optional<std::string> decode_face_stream(std::span<const std::int64_t> stream, std::size_t n_points,
                                              std::vector<std::vector<std::int64_t>>& faces) {
    faces.clear();
    if (stream.empty()) return "empty face stream";
    const std::int64_t n_faces = stream[0];
    if (n_faces < 1 || static_cast<std::size_t>(n_faces) > stream.size())
        return "bad number of faces " + std::to_string(n_faces);
    std::size_t pos = 1;
    for (std::int64_t f = 0; f < n_faces; ++f) {
        if (pos >= stream.size()) return "face stream ends in face " + std::to_string(f);
        const std::int64_t n = stream[pos++];
        if (n < 1 || static_cast<std::size_t>(n) > stream.size() - pos)
            return "face " + std::to_string(f) + " has bad size " + std::to_string(n);
        std::vector<std::int64_t> loop(stream.begin() + static_cast<std::ptrdiff_t>(pos),
                                       stream.begin() + static_cast<std::ptrdiff_t>(pos + static_cast<std::size_t>(n)));
        for (std::int64_t v : loop)
            if (v < 0 || static_cast<std::size_t>(v) >= n_points)
                return "face " + std::to_string(f) + ": point id " + std::to_string(v) + " out of range [0, " +
                       std::to_string(n_points) + ")";
        faces.push_back(std::move(loop));
        pos += static_cast<std::size_t>(n);
    }
    if (pos != stream.size())
        return "face stream has " + std::to_string(stream.size() - pos) + " values after its " +
               std::to_string(n_faces) + " faces";
    return std::nullopt;
}

std::optional<std::string> point_id_error(std::span<const std::int64_t> ids, std::size_t n_points) {
    for (std::int64_t v : ids)
        if (v < 0 || static_cast<std::size_t>(v) >= n_points)
            return "point id " + std::to_string(v) + " out of range [0, " + std::to_string(n_points) + ")";
    return std::nullopt;
}

}  // namespace detail
}  // namespace dualhex::audit
