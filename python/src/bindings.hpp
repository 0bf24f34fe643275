#pragma once
// The pieces of the `dualhex._dualhex` extension module (module.cpp builds it): each
// bind_* adds one area's functions; errors.cpp maps the library's exceptions to Python.
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace dualhex::python {

namespace py = pybind11;

/// An InstallError with the grid's source (file name, or "<leaves array>") known:
/// dualhex.InstallError with .file set; what() is "<file>: <message>".
struct GridInstallError : std::runtime_error {
    GridInstallError(std::string file_, std::string message_)
        : std::runtime_error(file_ + ": " + message_), file(std::move(file_)), message(std::move(message_)) {}
    std::string file, message;
};

/// A result that fails its verification: dualhex.VerificationError (a RuntimeError).
struct VerificationError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Creates dualhex.InputError, InstallError, VerificationError and registers the
/// translators of the C++ exceptions (see errors.cpp for the mapping).
void bind_errors(py::module_& m);
void bind_install(py::module_& m);  // install()
void bind_mesh(py::module_& m);     // mesh()
void bind_verify(py::module_& m);   // verify(), list_checks(), classify()

}  // namespace dualhex::python
