# Command-line contract of travel-view: a missing or corrupt scan is an error naming the file;
# with a real scan, a two-method picture is written and is not empty.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

# Missing scan
expect_failure_mentioning("no_such_scan.bin" ${TRAVEL_VIEW} -i ${WORK_DIR}/no_such_scan.bin -o ${WORK_DIR}/x.png)
# A .bin whose size is not a multiple of 16
file(WRITE ${WORK_DIR}/broken.bin "0123456789")
expect_failure_mentioning("broken.bin" ${TRAVEL_VIEW} -i ${WORK_DIR}/broken.bin -o ${WORK_DIR}/x.png)
# Unknown method: the message lists the valid ones
expect_failure_mentioning("gpf+slr" ${TRAVEL_VIEW} -i ${WORK_DIR}/broken.bin -o ${WORK_DIR}/x.png --methods nope)
# More than two methods
expect_failure_mentioning("--methods" ${TRAVEL_VIEW} -i ${WORK_DIR}/broken.bin -o ${WORK_DIR}/x.png --methods travel,gpf,tgs)

# Flags that would change nothing are usage errors: --frame with one scan, --no-nodes when no
# method draws tri-grid nodes.
expect_failure_mentioning("--frame chooses a scan of a folder or sequence" ${TRAVEL_VIEW}
                          -i ${WORK_DIR}/broken.bin --frame 0 -o ${WORK_DIR}/x.png)
expect_failure_mentioning("--no-nodes: no method here draws tri-grid nodes" ${TRAVEL_VIEW}
                          -i ${WORK_DIR}/broken.bin --methods gpf,gpf+slr --no-nodes
                          -o ${WORK_DIR}/x.png)

set(scan ${DATA_DIR}/semantickitti/sequences/00/velodyne/000000.bin)
if(EXISTS ${scan})
  set(png ${WORK_DIR}/pics/000000_travel_vs_gpfslr.png)
  execute_process(COMMAND ${TRAVEL_VIEW} -i ${scan} --methods travel,gpf+slr -o ${png}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "travel-view failed on a real scan:\n${out}${err}")
  endif()
  if(NOT EXISTS ${png})
    message(FATAL_ERROR "travel-view did not write ${png}")
  endif()
  file(SIZE ${png} png_size)
  if(png_size LESS 10000)
    message(FATAL_ERROR "${png} is only ${png_size} bytes")
  endif()
  file(READ ${png} magic LIMIT 4 HEX)
  if(NOT magic STREQUAL "89504e47")
    message(FATAL_ERROR "${png} is not a PNG (starts with ${magic})")
  endif()
  # sensor_height auto: the pipeline's note once on stderr (not with -q); the baselines refuse it.
  execute_process(COMMAND ${TRAVEL_VIEW} -i ${scan} --methods travel --set sensor_height=auto
                  -o ${WORK_DIR}/auto.png RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX MATCHALL "sensor_height auto: [0-9.]+ m" notes "${err}")
  list(LENGTH notes count)
  if(NOT rc EQUAL 0 OR NOT count EQUAL 1)
    message(FATAL_ERROR "no single 'sensor_height auto' note (${rc}):\n${out}${err}")
  endif()
  execute_process(COMMAND ${TRAVEL_VIEW} -q -i ${scan} --methods travel --set sensor_height=auto
                  -o ${WORK_DIR}/auto.png RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
    message(FATAL_ERROR "-q printed (${rc}):\n${out}${err}")
  endif()
  expect_failure_mentioning("sensor_height: auto is not supported by method 'gpf'"
                            ${TRAVEL_VIEW} -i ${scan} --methods gpf
                            --set sensor_height=auto -o ${WORK_DIR}/auto.png)
else()
  message(STATUS "SemanticKITTI scan not found at ${scan}: real-scan part skipped")
endif()
