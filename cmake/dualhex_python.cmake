# DUALHEX_BUILD_PYTHON: the pybind11 module in python/. ON by default when pybind11 (Debian
# pybind11-dev) and Python 3 (Debian's /usr/bin/python3 first, the one python3-numpy,
# python3-meshio and python3-pytest belong to) are found; OFF by default in a sanitizer
# build, where an extension module loads only with libasan preloaded into python.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the dualhex module and its tests")
endif()
find_package(Python 3 COMPONENTS Interpreter Development.Module QUIET)
set(PYBIND11_FINDPYTHON ON)
if(Python_FOUND)
  find_package(pybind11 CONFIG QUIET)
endif()
set(dualhex_python_default OFF)
if(Python_FOUND AND pybind11_FOUND AND NOT DUALHEX_SANITIZE)
  set(dualhex_python_default ON)
endif()
option(DUALHEX_BUILD_PYTHON "Build the dualhex Python module (python/, needs pybind11)" ${dualhex_python_default})
if(DUALHEX_BUILD_PYTHON)
  if(NOT pybind11_FOUND)
    message(FATAL_ERROR "DUALHEX_BUILD_PYTHON is ON but pybind11 was not found (Debian: pybind11-dev)")
  endif()
  message(STATUS "dualhex Python module: ${Python_EXECUTABLE}, pybind11 ${pybind11_VERSION}")
  add_subdirectory(python)
endif()
