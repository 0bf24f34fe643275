#pragma once
// The `leaves` argument of dualhex.install(): a path to a leaf file, or an (N, 4) integer
// array of rows "level i j k" (validated exactly like a file; row r is "line" r + 1).
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "dualhex/grid/leaf.hpp"

namespace dualhex::python {

namespace py = pybind11;

/// Either a file to read (path non-empty) or leaves taken from an array (source "<leaves array>").
struct LeafInput {
    std::string path;
    std::vector<Leaf> leaves;
    std::vector<int> rows;  ///< 1-based row of each leaf
    [[nodiscard]] const std::string& source() const;
};

/// Converts with the GIL held. TypeError for neither a path nor an array, ValueError for
/// an array that is not integer or not (N, 4); InputError for a level out of range.
[[nodiscard]] LeafInput leaf_input(const py::handle& leaves);

/// True iff `value` is a str or an os.PathLike; then `path` receives os.fspath(value).
[[nodiscard]] bool as_path(const py::handle& value, std::string& path);

}  // namespace dualhex::python
