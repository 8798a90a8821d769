# travel_add_rawlog_regression(NAME <test> RAWLOG <in.rawlog> GOLDEN <golden.rawlog>
#                              [CONFIG <file>] [PRESET <name>] [SET <key=value> ...]
#                              [REPORT_DIR <dir>] [ARGS <more travel-regress flags> ...]
#                              [TIMEOUT <seconds>] [LABELS <label> ...])
#
# Adds the CTest test <test>: travel-regress replays RAWLOG with the configuration (PRESET, then
# CONFIG, then each SET, as -p / -c / --set) and compares every labelled frame with the golden
# labelled rawlog GOLDEN (one travel-rawlog wrote). The test passes when the differences are
# within the tolerances of the configuration's regress section (exit 0); it fails when they are
# outside (exit 1) or on an error (exit 2: unreadable or truncated rawlog, ...). With REPORT_DIR
# the report (report.md, frames.csv, diff_*.png) is written there. docs/regression.md.
#
#   find_package(travel REQUIRED COMPONENTS mrpt)   # installs this function
#   enable_testing()
#   travel_add_rawlog_regression(NAME labels.drive RAWLOG data/drive.rawlog
#     GOLDEN data/drive_golden.rawlog CONFIG robot.yaml SET regress.min_class_agreement=99.5)
#
# The executable is the build tree's travel-regress target when there is one (this project),
# else the installed travel::travel-regress (find_package(travel COMPONENTS mrpt)).
function(travel_add_rawlog_regression)
  cmake_parse_arguments(R "" "NAME;RAWLOG;GOLDEN;CONFIG;PRESET;REPORT_DIR;TIMEOUT"
                        "SET;ARGS;LABELS" ${ARGN})
  foreach(required IN ITEMS NAME RAWLOG GOLDEN)
    if(NOT R_${required})
      message(FATAL_ERROR "travel_add_rawlog_regression: ${required} is required")
    endif()
  endforeach()
  if(R_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "travel_add_rawlog_regression(${R_NAME}): unknown arguments "
                        "${R_UNPARSED_ARGUMENTS}")
  endif()
  if(TARGET travel-regress)
    set(exe travel-regress)
  elseif(TARGET travel::travel-regress)
    set(exe travel::travel-regress)
  else()
    message(FATAL_ERROR "travel_add_rawlog_regression: no travel-regress executable (build "
                        "TRAVEL with its MRPT apps and call find_package(travel COMPONENTS mrpt))")
  endif()
  set(command ${exe} -i ${R_RAWLOG} --golden ${R_GOLDEN} -q)
  if(R_PRESET)
    list(APPEND command -p ${R_PRESET})
  endif()
  if(R_CONFIG)
    list(APPEND command -c ${R_CONFIG})
  endif()
  foreach(kv IN LISTS R_SET)
    list(APPEND command --set ${kv})
  endforeach()
  if(R_REPORT_DIR)
    list(APPEND command -o ${R_REPORT_DIR})
  endif()
  add_test(NAME ${R_NAME} COMMAND ${command} ${R_ARGS})
  if(NOT R_TIMEOUT)
    set(R_TIMEOUT 600)
  endif()
  set_tests_properties(${R_NAME} PROPERTIES TIMEOUT ${R_TIMEOUT})
  if(R_LABELS)
    set_tests_properties(${R_NAME} PROPERTIES LABELS "${R_LABELS}")
  endif()
endfunction()
