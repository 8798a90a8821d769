# Command-line contract of travel-eval: bad methods and sweep specs are errors naming them; with
# the real SemanticKITTI frames, a report writes both protocols' tables and one CSV row per
# (method, frame), and a sweep writes its CSV and three non-empty PNG plots.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/scans ${WORK_DIR}/labels)

include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

function(run_ok)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}${err}")
  endif()
endfunction()

function(expect_nonempty_file path)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "missing output ${path}")
  endif()
  file(SIZE ${path} size)
  if(size EQUAL 0)
    message(FATAL_ERROR "empty output ${path}")
  endif()
endfunction()

set(io -i ${WORK_DIR}/scans --labels ${WORK_DIR}/labels -o ${WORK_DIR}/out)
# Configuration errors come before any file is read, so these need no data.
# Unknown method: the message lists the valid ones
expect_failure_mentioning("gpf+slr" ${TRAVEL_EVAL} report ${io} --methods travel,nope)
# Sweep spec without '=', without values, with an unknown key, with a value out of range
expect_failure_mentioning("foo" ${TRAVEL_EVAL} sweep ${io} --sweep foo)
expect_failure_mentioning("tgf_resolution=" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=)
expect_failure_mentioning("tgf_resolutoin" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolutoin=2,4)
expect_failure_mentioning("tgf_resolution" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=2,-1)
# Unknown leave-one-out score; --loo-score outside sweep
expect_failure_mentioning("coverage" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=2,4 --loo-score nope)
expect_failure_mentioning("--loo-score is for sweep" ${TRAVEL_EVAL} report ${io} --loo-score f1a)
# Unknown subcommand; no scan; missing directory
expect_failure_mentioning("report" ${TRAVEL_EVAL} frob ${io})
expect_failure_mentioning("no scans" ${TRAVEL_EVAL} report ${io})
expect_failure_mentioning("no_such_dir" ${TRAVEL_EVAL} report -i ${WORK_DIR}/no_such_dir
                          --labels ${WORK_DIR}/labels -o ${WORK_DIR}/out)

set(seq ${DATA_DIR}/semantickitti/sequences/00)
if(EXISTS ${seq}/velodyne/000000.bin AND EXISTS ${seq}/labels/000000.label)
  set(real -i ${seq} --max-frames 1)  # labels/ found beside velodyne/

  run_ok(${TRAVEL_EVAL} report ${real} -o ${WORK_DIR}/report --methods travel,gpf)
  file(READ ${WORK_DIR}/report/report.md md)
  foreach(needle "A (Patchwork benchmark)" "B (Patchwork++)" "| travel |" "| gpf |")
    string(FIND "${md}" "${needle}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "report.md does not contain '${needle}':\n${md}")
    endif()
  endforeach()
  # Header + one row per (method, frame): 2 methods x 1 frame.
  file(STRINGS ${WORK_DIR}/report/frames.csv rows)
  list(LENGTH rows n)
  if(NOT n EQUAL 3)
    message(FATAL_ERROR "frames.csv has ${n} lines, expected 3 (header + 2 rows)")
  endif()

  run_ok(${TRAVEL_EVAL} sweep -i ${seq} --max-frames 2 -o ${WORK_DIR}/sweep
         --sweep tgf_resolution=4,8)
  file(STRINGS ${WORK_DIR}/sweep/sweep_tgf_resolution.csv rows)
  list(LENGTH rows n)
  if(NOT n EQUAL 3)
    message(FATAL_ERROR "sweep_tgf_resolution.csv has ${n} lines, expected 3 (header + 2 values)")
  endif()
  foreach(plot ground objects time)
    expect_nonempty_file(${WORK_DIR}/sweep/sweep_tgf_resolution_${plot}.png)
  endforeach()
  # Leave-one-out: one row per held-out frame, the mean, the in-sample best.
  file(STRINGS ${WORK_DIR}/sweep/sweep_tgf_resolution_loo.csv rows)
  list(LENGTH rows n)
  if(NOT n EQUAL 5)
    message(FATAL_ERROR "sweep_tgf_resolution_loo.csv has ${n} lines, expected 5:\n${rows}")
  endif()
else()
  message(STATUS "SemanticKITTI frames not found in ${seq}: real-data part skipped")
endif()
