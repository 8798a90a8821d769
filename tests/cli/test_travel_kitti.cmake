# Command-line contract of travel-kitti: corrupt input is an error naming the file; a good run
# writes one .label per scan with one uint32 per point. Uses generated scans, no real data.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/scans ${WORK_DIR}/bad ${WORK_DIR}/labels)

include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

# Missing directory
expect_failure_mentioning("no_such_dir" ${TRAVEL_KITTI} -i ${WORK_DIR}/no_such_dir -o ${WORK_DIR}/out)
# Unknown preset
expect_failure_mentioning("nopreset" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out --preset nopreset)
# Misspelt parameter
expect_failure_mentioning("tgf_resolutoin" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out --set tgf_resolutoin=4)
# An unknown option stops with an error (MRPT's TCLAP would carry on without the check)
expect_failure_mentioning("--bogus" ${TRAVEL_KITTI} --bogus)
# Unknown method: the message lists the valid ones
expect_failure_mentioning("gpf+slr" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out --method nope)
# A .bin whose size is not a multiple of 16
file(WRITE ${WORK_DIR}/bad/broken.bin "0123456789")
expect_failure_mentioning("broken.bin" ${TRAVEL_KITTI} -i ${WORK_DIR}/bad -o ${WORK_DIR}/out)

# A real scan if available: labels are written, one uint32 per point; a label file with the wrong
# count is an error naming it.
set(seq ${DATA_DIR}/semantickitti/sequences/00)
if(EXISTS ${seq}/velodyne/000000.bin)
  file(COPY ${seq}/velodyne/000000.bin DESTINATION ${WORK_DIR}/scans)
  execute_process(COMMAND ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out -q
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "travel-kitti failed on a real scan:\n${out}${err}")
  endif()
  file(SIZE ${seq}/velodyne/000000.bin bin_size)
  file(SIZE ${WORK_DIR}/out/000000.label label_size)
  math(EXPR expected "${bin_size} / 4")
  if(NOT label_size EQUAL expected)
    message(FATAL_ERROR "label file has ${label_size} bytes, expected ${expected}")
  endif()
  # A label file of zeros (every point unlabeled) holds no ground truth: no scores printed as
  # 0.00, but "not scored".
  file(MAKE_DIRECTORY ${WORK_DIR}/zero)
  execute_process(COMMAND head -c ${expected} /dev/zero OUTPUT_FILE ${WORK_DIR}/zero/000000.label)
  execute_process(COMMAND ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out
                  --labels ${WORK_DIR}/zero RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${out}" "Ground, protocol B (Patchwork++)            not scored" not_scored)
  string(FIND "${out}" "F1 0.00" zero_f1)
  if(NOT rc EQUAL 0 OR not_scored EQUAL -1 OR NOT zero_f1 EQUAL -1)
    message(FATAL_ERROR "labels without ground truth (${rc}):\n${out}${err}")
  endif()
  # A .label that cannot be written whole (a file size limit, as a full disk): an error naming
  # it, and no cut .label left under its name.
  execute_process(COMMAND sh -c "ulimit -f 64; trap '' XFSZ; exec \"$0\" \"$@\"" ${TRAVEL_KITTI}
                          -i ${WORK_DIR}/scans -o ${WORK_DIR}/limited -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "000000.label" OR EXISTS ${WORK_DIR}/limited/000000.label)
    message(FATAL_ERROR "a .label over the file size limit (${rc}): ${err}")
  endif()
  # A CSV whose rows cannot be written (a full disk: Linux's /dev/full) is an error, not exit 0.
  if(EXISTS /dev/full)
    expect_failure_mentioning("/dev/full: cannot write (" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans
                              -o ${WORK_DIR}/full -q --csv /dev/full)
  endif()
  file(WRITE ${WORK_DIR}/labels/000000.label "12345678")
  expect_failure_mentioning("000000.label" ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/out --labels ${WORK_DIR}/labels)
else()
  message(STATUS "SemanticKITTI scans not found in ${seq}: real-scan part skipped")
endif()
