# cmake -P script: `cmake --install` the build tree into a fresh prefix, move the prefix
# elsewhere, and import the installed package from there (outside the source and build
# trees, DUALHEX_ELEMENTS unset): it must install a grid and pass the element checks.
# Inputs: DUALHEX_BUILD_DIR, WORK_DIR, PYTHON, SITE (site-packages relative to the prefix).
foreach(var DUALHEX_BUILD_DIR WORK_DIR PYTHON SITE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_installed_test.cmake: ${var} not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/run")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${DUALHEX_BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed module test: cmake --install failed (${rc})")
endif()
file(RENAME "${WORK_DIR}/prefix" "${WORK_DIR}/moved")
set(ENV{DUALHEX_ELEMENTS})
set(ENV{PYTHONPATH} "${WORK_DIR}/moved/${SITE}")
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
execute_process(COMMAND "${PYTHON}" -c [=[
import os, sys
import dualhex
where = os.path.realpath(dualhex.__file__)
assert where.startswith(os.path.realpath(os.environ["PYTHONPATH"])), where
m = dualhex.install([[1, i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)])
assert m.report["ok"] and len(m.hexes) == 27, m.report
# The element files on disk (which the crossing-variant check copies) are found beside the module.
moved = os.path.realpath(os.path.join(os.environ["PYTHONPATH"], "..", "..", ".."))
assert dualhex.elements_directory() == os.path.join(moved, "share", "dualhex", "elements"), dualhex.elements_directory()
r = dualhex.verify(only=["schemes.strong-elements", "schemes.weak-elements", "schemes.crossing-variants"])
assert r["ok"] and r["passed"] == 3, [(c["name"], c["summary"]) for c in r["checks"]]
print("installed module OK:", where)
]=] WORKING_DIRECTORY "${WORK_DIR}/run" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed module test: the installed package failed (${rc})")
endif()
