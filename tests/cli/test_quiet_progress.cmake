# Quiet means quiet, long means progress (issue 13, point 4), for every app:
# - with -q a successful run prints nothing at all (stdout and stderr);
# - without a terminal (as here: pipes) the progress is plain lines, never a '\r' redraw;
# - travel-nav-sim prints no MRPT DEBUG line without -v;
# - Ctrl-C (SIGINT) during travel-nav-sim exits with 130 and leaves no temporary folder (its
#   scratch lives under TMPDIR) and no partial output; travel-rawlog leaves no output either.
# -DTRAVEL_KITTI -DTRAVEL_EVAL -DTRAVEL_RAWLOG -DTRAVEL_MAP -DTRAVEL_NAV_SIM -DMAKE_SYNTHETIC
# -DSAMPLE -DDATA_DIR -DWORK_DIR
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# Runs a command that must succeed and print nothing.
function(expect_silent)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "expected success: ${ARGN}\n${out}${err}")
  endif()
  if(NOT "${out}${err}" STREQUAL "")
    message(FATAL_ERROR "-q printed something: ${ARGN}\nstdout: '${out}'\nstderr: '${err}'")
  endif()
endfunction()

# Runs a command that must succeed; its output must not contain a carriage return (no
# terminal here), nor any of the extra words given after NOT.
function(expect_plain_output)
  cmake_parse_arguments(arg "" "" "NOT;COMMAND" ${ARGN})
  expect_success(${arg_COMMAND})
  string(ASCII 13 cr)
  string(FIND "${last_output}" "${cr}" pos)
  if(NOT pos EQUAL -1)
    message(FATAL_ERROR "'\\r' in the output without a terminal: ${arg_COMMAND}\n${last_output}")
  endif()
  foreach(word IN LISTS arg_NOT)
    string(FIND "${last_output}" "${word}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "'${word}' in the output: ${arg_COMMAND}\n${last_output}")
    endif()
  endforeach()
  set(last_output "${last_output}" PARENT_SCOPE)
endfunction()

# travel-kitti and travel-eval on two real frames.
set(seq ${DATA_DIR}/semantickitti/sequences/00)
if(EXISTS ${seq}/velodyne/000001.bin AND EXISTS ${seq}/labels/000001.label)
  file(MAKE_DIRECTORY ${WORK_DIR}/scans ${WORK_DIR}/labels)
  foreach(stem 000000 000001)
    file(COPY ${seq}/velodyne/${stem}.bin DESTINATION ${WORK_DIR}/scans)
    file(COPY ${seq}/labels/${stem}.label DESTINATION ${WORK_DIR}/labels)
  endforeach()
  expect_silent(${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/kitti -q)
  expect_plain_output(COMMAND ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/kitti)
  # The progress line, not a line per frame (that is -v's).
  string(FIND "${last_output}" "2/2 scans" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "travel-kitti: no k/N progress:\n${last_output}")
  endif()
  expect_plain_output(COMMAND ${TRAVEL_KITTI} -i ${WORK_DIR}/scans -o ${WORK_DIR}/kitti -v)
  string(FIND "${last_output}" "000001 " pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "travel-kitti -v: no per-frame line:\n${last_output}")
  endif()
  set(eval_io -i ${WORK_DIR}/scans --labels ${WORK_DIR}/labels --methods travel)
  expect_silent(${TRAVEL_EVAL} report ${eval_io} -o ${WORK_DIR}/eval -q)
  expect_plain_output(COMMAND ${TRAVEL_EVAL} report ${eval_io} -o ${WORK_DIR}/eval)
else()
  message(STATUS "SemanticKITTI frames not found in ${seq}: travel-kitti/travel-eval part skipped")
endif()

# travel-rawlog and travel-map on MRPT's VLP-16 sample.
if(EXISTS ${SAMPLE})
  expect_silent(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/rawlog/out.rawlog -p vlp16 -q)
  expect_plain_output(COMMAND ${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/rawlog/out.rawlog
                      -p vlp16)
  # travel-map: no INFO line, no liboctomap " done." with -q.
  expect_silent(${TRAVEL_MAP} -i ${SAMPLE} -o ${WORK_DIR}/map -p vlp16 -q)
  # Without -q: the missing-pose warning comes first, and no "without pose: 0".
  expect_plain_output(COMMAND ${TRAVEL_MAP} -i ${SAMPLE} -o ${WORK_DIR}/map -p vlp16
                      NOT " done." "without pose")
  string(FIND "${last_output}" "identity pose" warning_pos)
  string(FIND "${last_output}" "LiDAR frames mapped" summary_pos)
  if(warning_pos EQUAL -1 OR summary_pos EQUAL -1)
    message(FATAL_ERROR "travel-map: no missing-pose warning or no summary:\n${last_output}")
  endif()
  # A truncated rawlog: the same message as travel-rawlog's (one reader).
  execute_process(COMMAND head -c 30000 ${SAMPLE} OUTPUT_FILE ${WORK_DIR}/cut.rawlog)
  foreach(app ${TRAVEL_MAP} ${TRAVEL_RAWLOG})
    get_filename_component(name ${app} NAME)  # travel-map's -o is a folder, travel-rawlog's a file
    expect_failure_mentioning("cut.rawlog: record 0: truncated (end of file inside the record)"
      ${app} -i ${WORK_DIR}/cut.rawlog -o ${WORK_DIR}/cut_${name} -q)
  endforeach()
else()
  message(STATUS "${SAMPLE} not found: travel-rawlog/travel-map part skipped")
endif()

# travel-nav-sim: a short run.
set(nav ${TRAVEL_NAV_SIM} -i flat_obstacles.world --timeout 2)
expect_silent(${nav} -q -o ${WORK_DIR}/nav)
expect_plain_output(COMMAND ${nav} -o ${WORK_DIR}/nav NOT "DEBUG" ".travel-nav-sim-")
string(FIND "${last_output}" "t = 2.0 / 2 s" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "travel-nav-sim: no simulated-time progress:\n${last_output}")
endif()

# Ctrl-C during a long travel-nav-sim run (about 20 s): exit code 130, the scratch folder under
# TMPDIR is gone, and no output was written.
find_program(TIMEOUT_PROGRAM timeout)
if(TIMEOUT_PROGRAM)
  file(MAKE_DIRECTORY ${WORK_DIR}/tmp)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${WORK_DIR}/tmp
            ${TIMEOUT_PROGRAM} --preserve-status -s INT 3
            ${TRAVEL_NAV_SIM} --timeout 60 -o ${WORK_DIR}/nav_interrupted
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 130)
    message(FATAL_ERROR "travel-nav-sim after SIGINT: exit code ${rc}, expected 130\n${out}${err}")
  endif()
  file(GLOB leftovers ${WORK_DIR}/tmp/* ${WORK_DIR}/tmp/.* ${WORK_DIR}/nav_interrupted/*
       ${WORK_DIR}/nav_interrupted/.*)
  if(leftovers)
    message(FATAL_ERROR "travel-nav-sim after SIGINT left: ${leftovers}")
  endif()
  string(FIND "${err}" "interrupted" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "travel-nav-sim after SIGINT does not say 'interrupted':\n${err}")
  endif()
  # travel-rawlog: an interrupted run leaves no output at all (no OUT.rawlog, no .part, no CSV).
  if(MAKE_SYNTHETIC)
    expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/long.rawlog 300)
    execute_process(
      COMMAND ${TIMEOUT_PROGRAM} --preserve-status -s INT 2
              ${TRAVEL_RAWLOG} -i ${WORK_DIR}/long.rawlog -o ${WORK_DIR}/long/out.rawlog
              --csv ${WORK_DIR}/long/frames.csv -p vlp16 -q
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 130)
      file(GLOB leftovers ${WORK_DIR}/long/*)
      if(leftovers)
        message(FATAL_ERROR "travel-rawlog after SIGINT left: ${leftovers}")
      endif()
    elseif(rc EQUAL 0)
      message(STATUS "travel-rawlog finished before the SIGINT: interrupt part not checked")
    else()
      message(FATAL_ERROR "travel-rawlog after SIGINT: exit code ${rc}, expected 130\n${out}${err}")
    endif()
  endif()
else()
  message(STATUS "no 'timeout' program: the SIGINT part skipped")
endif()
