#pragma once
// Conversions between the library's results and Python objects (call with the GIL held).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::python {

namespace py = pybind11;

/// A JSON value as the equal Python value (dict, list, str, int, float, bool, None).
[[nodiscard]] py::object to_python(const nlohmann::json& j);

/// {key: count} with int keys (a histogram such as face sizes or edge valences).
template <class Key>
[[nodiscard]] py::dict histogram_dict(const std::map<Key, std::size_t>& h) {
    py::dict d;
    for (const auto& [k, v] : h) d[py::cast(k)] = v;
    return d;
}

/// points (N,3) float64 and hexes (M,8) int64 (VTK_HEXAHEDRON order) of a hex mesh.
[[nodiscard]] py::array_t<double> points_array(const geometry::HexMesh& mesh);
[[nodiscard]] py::array_t<std::int64_t> hexes_array(const geometry::HexMesh& mesh);
template <class T>
[[nodiscard]] py::array_t<T> vector_array(const std::vector<T>& values) {
    return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

/// The dict `dualhex.Mesh` is built from: points, hexes, quality (scaled Jacobian per hex),
/// level (per hex, or None), report.
[[nodiscard]] py::dict mesh_dict(const geometry::HexMesh& mesh, const std::vector<double>& quality,
                                 const std::vector<std::int64_t>* level, py::dict report);

}  // namespace dualhex::python
