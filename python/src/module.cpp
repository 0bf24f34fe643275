// The extension module behind `import dualhex` (python/dualhex/__init__.py wraps it).
#include "bindings.hpp"

PYBIND11_MODULE(_dualhex, m) {
    m.doc() = "dualhex: octree dual transition schemes installed as exact integer topology (C++ core)";
    dualhex::python::bind_errors(m);
    dualhex::python::bind_install(m);
    dualhex::python::bind_mesh(m);
    dualhex::python::bind_verify(m);
}
