# MRPT's rawlog-edit reads the labelled rawlog with the plugin (-p) and cannot without it.
#   cmake -DRAWLOG_EDIT=<exe or empty> -DPLUGIN=<abs .so> -DRAWLOG=<rawlog> -DWORK_DIR=<dir>
#         -P test_rawlog_edit.cmake
# Prints "SKIPPED: ..." (the test's SKIP_REGULAR_EXPRESSION) when rawlog-edit is not installed.
if(NOT RAWLOG_EDIT OR NOT EXISTS "${RAWLOG_EDIT}")
  message("SKIPPED: rawlog-edit not installed (Debian package mrpt-apps)")
  return()
endif()
set(kClass "travel_mrpt::CObservationTravelLabels")

function(run_rawlog_edit out_var rc_var)
  execute_process(COMMAND ${RAWLOG_EDIT} ${ARGN}
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 60)
  set(${out_var} "${out}${err}" PARENT_SCOPE)
  set(${rc_var} "${rc}" PARENT_SCOPE)
endfunction()

function(expect_contains text needle what)
  string(FIND "${text}" "${needle}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what}: expected '${needle}' in:\n${text}")
  endif()
endfunction()

# 1. --info with the plugin: every object parsed, our sensor label listed.
run_rawlog_edit(out rc -p ${PLUGIN} -i ${RAWLOG} --info)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rawlog-edit -p ... --info failed (${rc}):\n${out}")
endif()
expect_contains("${out}" "_travel" "--info with -p")
string(FIND "${out}" "not registered" bad)
if(NOT bad EQUAL -1)
  message(FATAL_ERROR "rawlog-edit -p did not register the class:\n${out}")
endif()
string(REGEX MATCH "Overall number of objects *: ([0-9]+)" _ "${out}")
set(with_plugin "${CMAKE_MATCH_1}")

# 2. --list-timestamps names the class of every observation.
set(list_file ${WORK_DIR}/rawlog_edit_timestamps.txt)
file(REMOVE ${list_file})
run_rawlog_edit(out rc -p ${PLUGIN} -i ${RAWLOG} --list-timestamps --text-file-output ${list_file})
if(NOT rc EQUAL 0 OR NOT EXISTS ${list_file})
  message(FATAL_ERROR "rawlog-edit --list-timestamps failed (${rc}):\n${out}")
endif()
file(READ ${list_file} listing)
expect_contains("${listing}" "${kClass}" "--list-timestamps")

# 3. --describe prints our getDescriptionAsText().
run_rawlog_edit(out rc -p ${PLUGIN} -i ${RAWLOG} --describe)
expect_contains("${out}" "ClassName: ${kClass}" "--describe")
expect_contains("${out}" "TRAVEL labels of a" "--describe")
expect_contains("${out}" "Clusters:" "--describe")

# 4. Without the plugin rawlog-edit 2.5.8 stops at our first object: it prints MRPT's
#    "Stored object has class '...' which is not registered!" (and still exits 0, counting
#    only the objects before it).
run_rawlog_edit(out rc -i ${RAWLOG} --info)
expect_contains("${out}" "Stored object has class '${kClass}' which is not registered" "--info without -p")
string(REGEX MATCH "Overall number of objects *: ([0-9]+)" _ "${out}")
if(NOT CMAKE_MATCH_1 LESS with_plugin)
  message(FATAL_ERROR "without -p rawlog-edit counted ${CMAKE_MATCH_1} objects, with it ${with_plugin}")
endif()
message(STATUS "rawlog-edit: ${with_plugin} objects with the plugin, ${CMAKE_MATCH_1} without")
