# The Python module's tests (pytest), one CTest test per file so that ctest -j runs them side by
# side. Without the module (TRAVEL_BUILD_PYTHON=OFF, or no Python / pybind11 / pytest found) one
# test says why and is reported as skipped.
set(python_tests api examples kitti install)
set(pytest_ok FALSE)
if(TARGET travel_python)
  execute_process(COMMAND ${TRAVEL_PYTHON_EXECUTABLE} -c "import pytest"
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc EQUAL 0)
    set(pytest_ok TRUE)
  else()
    set(why "${TRAVEL_PYTHON_EXECUTABLE} has no pytest (Debian: apt install python3-pytest)")
  endif()
elseif(NOT TRAVEL_BUILD_PYTHON)
  set(why "built with TRAVEL_BUILD_PYTHON=OFF")
else()
  set(why "no Python 3 with pybind11 and numpy was found (Debian: apt install python3-dev "
          "python3-pybind11 python3-numpy python3-pytest)")
endif()

if(NOT pytest_ok)
  add_test(NAME python.skipped COMMAND ${CMAKE_COMMAND} -E echo
    "python tests skipped: ${why}")
  set_tests_properties(python.skipped PROPERTIES SKIP_REGULAR_EXPRESSION "python tests skipped")
  return()
endif()

set(env "PYTHONPATH=${TRAVEL_PYTHON_PATH}" "TRAVEL_DATA_DIR=${TRAVEL_DATA_DIR}"
  "PYTHONDONTWRITEBYTECODE=1" "TRAVEL_BUILD_DIR=${PROJECT_BINARY_DIR}" "TRAVEL_CMAKE=${CMAKE_COMMAND}"
  "TRAVEL_PYTHON_INSTALL_DIR=${TRAVEL_PYTHON_INSTALL_DIR}")
if(TARGET travel-kitti)
  list(APPEND env "TRAVEL_KITTI=$<TARGET_FILE:travel-kitti>")
endif()
foreach(name IN LISTS python_tests)
  add_test(NAME python.${name}
    COMMAND ${TRAVEL_PYTHON_EXECUTABLE} -m pytest -q -rs -p no:cacheprovider
      ${CMAKE_CURRENT_LIST_DIR}/test_${name}.py)
  # All skipped (no real data): pytest prints only "N skipped in ..."; report it as skipped.
  set_tests_properties(python.${name} PROPERTIES ENVIRONMENT "${env}" TIMEOUT 600
    SKIP_REGULAR_EXPRESSION "\n[0-9]+ skipped in ")
endforeach()
