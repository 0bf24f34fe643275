# The Python module's pytest suites (python/tests/test_*.py), one CTest test per file, run
# with the interpreter the module was built for (Debian's /usr/bin/python3) against the
# build tree's package (PYTHONPATH=<build>/python). Not registered when the module is not
# built (DUALHEX_BUILD_PYTHON OFF, the default in a DUALHEX_SANITIZE build: an
# uninstrumented python cannot load an ASan-instrumented extension without LD_PRELOAD).
if(TARGET dualhex_python AND NOT DUALHEX_SANITIZE)
  file(GLOB dualhex_pytest_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/tests/test_*.py)
  foreach(file IN LISTS dualhex_pytest_files)
    get_filename_component(stem ${file} NAME_WE)
    add_test(NAME python_${stem}
             COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${file}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties(python_${stem} PROPERTIES
      ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;DUALHEX_SHARED_DATA=${DUALHEX_SHARED_DATA};DUALHEX_EXE=$<TARGET_FILE:dualhex>;PYTHONDONTWRITEBYTECODE=1"
      TIMEOUT 600)
  endforeach()
endif()

# The installed package, moved away from its prefix, imported from outside the trees.
if(TARGET dualhex_python AND NOT DUALHEX_SANITIZE)
  add_test(NAME python_installed_module
           COMMAND ${CMAKE_COMMAND} -DDUALHEX_BUILD_DIR=${PROJECT_BINARY_DIR}
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/python-installed-work
                   -DPYTHON=${Python_EXECUTABLE} -DSITE=${DUALHEX_PYTHON_INSTALL_DIR}
                   -P ${PROJECT_SOURCE_DIR}/python/tests/run_installed_test.cmake)
  set_tests_properties(python_installed_module PROPERTIES TIMEOUT 300)
endif()
