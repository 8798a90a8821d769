# -j N of the batch apps: travel-kitti's labels with -j 2 and -j 3 are byte-identical to -j 1's (the workers'
# results are written in input order), also with `auto` mount values, which the first frames
# settle one by one before the frames are spread over the workers. Generated scans (no real
# data); the SemanticKITTI dev frames too when present, and then travel-eval's frames.csv.
# Variables: TRAVEL_KITTI, TRAVEL_EVAL (optional), MAKE_SCANS, WORK_DIR, DATA_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
expect_success(${MAKE_SCANS} ${WORK_DIR}/scans 7)

# Runs travel-kitti with -j 1, 2 and 3 on `input` (extra flags after it) and compares every
# .label file of the three runs byte for byte.
function(expect_same_labels name input)
  foreach(j 1 2)
    expect_success(${TRAVEL_KITTI} -i ${input} -o ${WORK_DIR}/${name}_j${j} -q -j ${j} ${ARGN})
  endforeach()
  # The value attached, as make users type it.
  expect_success(${TRAVEL_KITTI} -i ${input} -o ${WORK_DIR}/${name}_j3 -q -j3 ${ARGN})
  file(GLOB labels RELATIVE ${WORK_DIR}/${name}_j1 ${WORK_DIR}/${name}_j1/*.label)
  list(LENGTH labels count)
  if(count EQUAL 0)
    message(FATAL_ERROR "${name}: -j 1 wrote no .label file")
  endif()
  foreach(j 2 3)
    file(GLOB other RELATIVE ${WORK_DIR}/${name}_j${j} ${WORK_DIR}/${name}_j${j}/*.label)
    if(NOT other STREQUAL labels)
      message(FATAL_ERROR "${name}: -j ${j} wrote [${other}], -j 1 wrote [${labels}]")
    endif()
    foreach(label ${labels})
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                      ${WORK_DIR}/${name}_j1/${label} ${WORK_DIR}/${name}_j${j}/${label}
                      RESULT_VARIABLE differ)
      if(differ)
        message(FATAL_ERROR "${name}: ${label} differs between -j 1 and -j ${j}")
      endif()
    endforeach()
  endforeach()
endfunction()

expect_same_labels(synthetic ${WORK_DIR}/scans)
expect_same_labels(synthetic_auto ${WORK_DIR}/scans --set sensor_height=auto
                   --set mount_pitch_deg=auto)
expect_same_labels(synthetic_gpf ${WORK_DIR}/scans --method gpf+slr)

# -j 0 is a usage error, also attached; an unknown short flag stays one.
expect_failure_mentioning("-j must be >= 1" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans
                          -o ${WORK_DIR}/bad -j 0)
expect_failure_mentioning("-j must be >= 1" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans
                          -o ${WORK_DIR}/bad -j0)
expect_failure_mentioning("unknown flag -Y2" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans
                          -o ${WORK_DIR}/bad -Y2)

set(velodyne ${DATA_DIR}/semantickitti/sequences/00/velodyne)
if(EXISTS ${velodyne}/000000.bin)
  expect_same_labels(kitti ${velodyne})
else()
  message(STATUS "SemanticKITTI scans not found in ${velodyne}: real-scan part skipped")
endif()

# travel-eval: frames.csv of -j 2 equals -j 1's but for the time columns (the last two).
if(TRAVEL_EVAL AND EXISTS ${velodyne}/000000.bin)
  foreach(j 1 2)
    expect_success(${TRAVEL_EVAL} report -i ${DATA_DIR}/semantickitti/sequences/00
                   -o ${WORK_DIR}/eval_j${j} --methods travel,gpf+slr -q -j ${j})
    file(STRINGS ${WORK_DIR}/eval_j${j}/frames.csv rows_j${j})
    list(TRANSFORM rows_j${j} REPLACE ",[^,]*,[^,]*$" "")
  endforeach()
  if(NOT rows_j1 STREQUAL rows_j2)
    message(FATAL_ERROR "travel-eval frames.csv differs between -j 1 and -j 2:\n${rows_j1}\n${rows_j2}")
  endif()
endif()
