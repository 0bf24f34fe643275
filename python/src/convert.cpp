#include "convert.hpp"

#include <string>

namespace dualhex::python {

py::object to_python(const nlohmann::json& j) {
    switch (j.type()) {
        case nlohmann::json::value_t::object: {
            py::dict d;
            for (const auto& [k, v] : j.items()) d[py::str(k)] = to_python(v);
            return d;
        }
        case nlohmann::json::value_t::array: {
            py::list l;
            for (const auto& v : j) l.append(to_python(v));
            return l;
        }
        case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
        case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
        case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
        case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
        case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
        default: return py::none();
    }
}

py::array_t<double> points_array(const geometry::HexMesh& mesh) {
    py::array_t<double> a({static_cast<py::ssize_t>(mesh.points.size()), py::ssize_t{3}});
    auto w = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < w.shape(0); ++i)
        for (py::ssize_t c = 0; c < 3; ++c) w(i, c) = mesh.points[static_cast<std::size_t>(i)][c];
    return a;
}

py::array_t<std::int64_t> hexes_array(const geometry::HexMesh& mesh) {
    py::array_t<std::int64_t> a({static_cast<py::ssize_t>(mesh.hexes.size()), py::ssize_t{8}});
    auto w = a.mutable_unchecked<2>();
    for (py::ssize_t h = 0; h < w.shape(0); ++h)
        for (py::ssize_t c = 0; c < 8; ++c) w(h, c) = mesh.hexes[static_cast<std::size_t>(h)][static_cast<std::size_t>(c)];
    return a;
}

py::dict mesh_dict(const geometry::HexMesh& mesh, const std::vector<double>& quality,
                   const std::vector<std::int64_t>* level, py::dict report) {
    py::dict d;
    d["points"] = points_array(mesh);
    d["hexes"] = hexes_array(mesh);
    d["quality"] = vector_array(quality);
    d["level"] = level ? py::object(vector_array(*level)) : py::object(py::none());
    d["report"] = std::move(report);
    return d;
}

}  // namespace dualhex::python
