// C++ exceptions -> Python exceptions, keeping the library's located messages:
//   dualhex::InputError (leaf files, leaf arrays)  -> dualhex.InputError (file, line, message)
//   geometry::SurfaceError (surface files, arrays) -> dualhex.InputError (file, line 0)
//   SchemeFormatError (element files)              -> dualhex.InputError (file, line)
//   InstallError (grid not paired / not balanced)  -> dualhex.InstallError (an InputError)
//   std::invalid_argument (bad options)            -> ValueError (pybind11's default)
// Anything else keeps pybind11's mapping (std::runtime_error -> RuntimeError, ...).
#include <string>

#include "bindings.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/grid/input_error.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/schemes/element.hpp"

namespace dualhex::python {
namespace {

// Owned by the module object (attributes), so the pointers live as long as it does.
PyObject* g_input_error = nullptr;
PyObject* g_install_error = nullptr;
PyObject* g_verification_error = nullptr;

void raise(PyObject* type, const std::string& what, const std::string& file, int line, const std::string& message) {
    py::object error = py::reinterpret_borrow<py::object>(type)(what);
    error.attr("file") = file.empty() ? py::object(py::none()) : py::object(py::str(file));
    error.attr("line") = line > 0 ? py::object(py::int_(line)) : py::object(py::none());
    error.attr("message") = message;
    PyErr_SetObject(type, error.ptr());
}

void translate(std::exception_ptr p) {
    try {
        if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
        raise(g_input_error, e.what(), e.file(), e.line(), e.message());
    } catch (const geometry::SurfaceError& e) {
        raise(g_input_error, e.what(), e.file(), 0, e.what());
    } catch (const SchemeFormatError& e) {
        raise(g_input_error, e.what(), e.file(), e.line(), e.message());
    } catch (const VerificationError& e) {
        PyErr_SetString(g_verification_error, e.what());
    } catch (const GridInstallError& e) {
        raise(g_install_error, e.what(), e.file, 0, e.message);
    } catch (const InstallError& e) {
        raise(g_install_error, e.what(), "", 0, e.what());
    }
}

}  // namespace

void bind_errors(py::module_& m) {
    // Never destroyed: a static py::object would be released after the interpreter is gone.
    const auto* input_error = new py::exception<InputError>(m, "InputError", PyExc_Exception);
    const auto* install_error = new py::exception<InstallError>(m, "InstallError", input_error->ptr());
    const auto* verification_error = new py::exception<VerificationError>(m, "VerificationError", PyExc_RuntimeError);
    g_input_error = input_error->ptr();
    g_install_error = install_error->ptr();
    g_verification_error = verification_error->ptr();
    py::register_exception_translator(&translate);
}

}  // namespace dualhex::python
