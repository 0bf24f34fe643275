#include "leaf_input.hpp"

#include <pybind11/numpy.h>

#include <limits>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::python {

namespace {
const std::string kArraySource = "<leaves array>";

std::string shape_text(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
    return s + (a.ndim() == 1 ? ",)" : ")");
}
}  // namespace

const std::string& LeafInput::source() const { return path.empty() ? kArraySource : path; }

bool as_path(const py::handle& value, std::string& path) {
    if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
        const py::object p = py::module_::import("os").attr("fspath")(value);
        if (!py::isinstance<py::str>(p)) throw py::type_error("a path must be a str path (bytes paths are not supported)");
        path = p.cast<std::string>();
        return true;
    }
    return false;
}

LeafInput leaf_input(const py::handle& leaves) {
    LeafInput in;
    if (as_path(leaves, in.path)) return in;
    if (!py::isinstance<py::array>(leaves) && !py::isinstance<py::sequence>(leaves))
        throw py::type_error("leaves: expected a path to a leaf file or an (N, 4) integer array, got " +
                             std::string(py::str(py::type::of(leaves))));
    const py::array raw = py::array::ensure(leaves);
    if (!raw) throw py::value_error("leaves: cannot be read as an array");
    const char kind = raw.dtype().kind();
    // Floats would be truncated silently and a ragged list becomes an object array.
    if (raw.size() > 0 && kind != 'i' && kind != 'u')
        throw py::value_error("leaves: expected an integer array, got dtype " + std::string(py::str(raw.dtype())));
    if (raw.ndim() != 2 || raw.shape(1) != 4)
        throw py::value_error("leaves: expected shape (N, 4) (rows: level i j k), got " + shape_text(raw));
    const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
    if (!a) throw py::value_error("leaves: cannot be converted to 64-bit integers");
    const auto r = a.unchecked<2>();
    for (py::ssize_t n = 0; n < r.shape(0); ++n) {
        const int row = static_cast<int>(n) + 1;
        if (r(n, 0) < 0 || r(n, 0) > kMaxLevel)
            throw InputError(kArraySource, row,
                             "invalid leaf " + std::to_string(r(n, 0)) + " " + std::to_string(r(n, 1)) + " " +
                                 std::to_string(r(n, 2)) + " " + std::to_string(r(n, 3)) + ": level must be in [0, " +
                                 std::to_string(kMaxLevel) + "]");
        in.leaves.push_back({static_cast<int>(r(n, 0)), r(n, 1), r(n, 2), r(n, 3)});
        in.rows.push_back(row);
    }
    return in;
}

}  // namespace dualhex::python
