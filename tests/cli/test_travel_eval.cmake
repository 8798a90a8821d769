# Command-line contract of travel-eval: bad methods and sweep specs are errors naming them; with
# the real SemanticKITTI frames, a report writes both protocols' tables and one CSV row per
# (method, frame), a sweep writes its CSV and three non-empty PNG plots, and merges its tables
# and one CSV row per part.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/scans ${WORK_DIR}/labels)

include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

function(run_ok)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}${err}")
  endif()
endfunction()

# Every needle after `path` is in the file.
function(expect_file_contains path)
  file(READ ${path} text)
  foreach(needle ${ARGN})
    string(FIND "${text}" "${needle}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "${path} does not contain '${needle}':\n${text}")
    endif()
  endforeach()
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
expect_failure_mentioning("--methods: empty value" ${TRAVEL_EVAL} report ${io} --methods=)
# An empty number is no number: not --max-frames' default (all frames), nor -j's
expect_failure_mentioning("--max-frames: empty value" ${TRAVEL_EVAL} report ${io} --max-frames=)
expect_failure_mentioning("-j/--jobs: empty value" ${TRAVEL_EVAL} report ${io} -j " ")
# Sweep spec without '=', without values, with an unknown key, with a value out of range
expect_failure_mentioning("foo" ${TRAVEL_EVAL} sweep ${io} --sweep foo)
expect_failure_mentioning("tgf_resolution=" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=)
expect_failure_mentioning("tgf_resolutoin" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolutoin=2,4)
expect_failure_mentioning("tgf_resolution" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=2,-1)
# Unknown leave-one-out score; --loo-score outside sweep
expect_failure_mentioning("coverage" ${TRAVEL_EVAL} sweep ${io} --sweep tgf_resolution=2,4 --loo-score nope)
expect_failure_mentioning("--loo-score is for sweep" ${TRAVEL_EVAL} report ${io} --loo-score f1a)
# merges diagnoses TRAVEL's object stage: not a baseline's, not with the stage off
expect_failure_mentioning("--method travel or travel-no-ttmf, not 'gpf'" ${TRAVEL_EVAL} merges ${io} --method gpf)
expect_failure_mentioning("merges diagnoses the object stage" ${TRAVEL_EVAL} merges ${io} --set cluster_objects=false)
# A flag the command does not use is refused, not ignored
expect_failure_mentioning("merges runs one --method, not --methods" ${TRAVEL_EVAL} merges ${io} --methods gpf)
expect_failure_mentioning("--sweep is for sweep" ${TRAVEL_EVAL} merges ${io} --sweep tgf_resolution=2,4)
expect_failure_mentioning("--method is for sweep and merges" ${TRAVEL_EVAL} report ${io} --method gpf)
# Unknown subcommand; no scan; missing directory
expect_failure_mentioning("report" ${TRAVEL_EVAL} frob ${io})
expect_failure_mentioning("missing the command: report, sweep or merges" ${TRAVEL_EVAL} ${io})
expect_failure_mentioning("no scans" ${TRAVEL_EVAL} report ${io})
expect_failure_mentioning("no_such_dir" ${TRAVEL_EVAL} report -i ${WORK_DIR}/no_such_dir
                          --labels ${WORK_DIR}/labels -o ${WORK_DIR}/out)

# Two inputs, the second without any label of its scans (an empty labels folder): an error naming
# it, not a report of the first alone.
file(MAKE_DIRECTORY ${WORK_DIR}/a/velodyne ${WORK_DIR}/a/labels ${WORK_DIR}/b/velodyne
     ${WORK_DIR}/b/labels)
foreach(side a b)
  file(WRITE ${WORK_DIR}/${side}/velodyne/000000.bin "0123456789abcdef")  # one KITTI point
endforeach()
file(WRITE ${WORK_DIR}/a/labels/000000.label "0000")
expect_failure_mentioning("no labelled frames in '${WORK_DIR}/b': none of its 1 scans"
                          ${TRAVEL_EVAL} report -i ${WORK_DIR}/a -i ${WORK_DIR}/b --methods tgs
                          -o ${WORK_DIR}/two)
# -o in what is read (the ground-truth labels, the scans, the sequence), however spelt: refused
# before anything is written.
foreach(o a/labels a/./velodyne/../labels/ a/velodyne a)
  expect_failure_mentioning("-o ${WORK_DIR}/${o}: the same path as" ${TRAVEL_EVAL} report
                            -i ${WORK_DIR}/a --methods tgs -o ${WORK_DIR}/${o})
endforeach()
file(GLOB written ${WORK_DIR}/a/*.md ${WORK_DIR}/a/*.csv ${WORK_DIR}/a/*/*.md ${WORK_DIR}/a/*/*.csv)
if(written)
  message(FATAL_ERROR "a refused -o was written: ${written}")
endif()
# A file that cannot be written whole (a 1-block file size limit, as a full disk): an error
# naming it and exit 1, not a cut report.md and exit 0.
execute_process(COMMAND sh -c "ulimit -f 1; trap '' XFSZ; exec \"$0\" \"$@\"" ${TRAVEL_EVAL}
                        report -i ${WORK_DIR}/a --methods tgs -o ${WORK_DIR}/limited -q
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "report.md: cannot write \\(File too large\\)" OR EXISTS ${WORK_DIR}/limited/report.md)
  message(FATAL_ERROR "report.md over the file size limit (${rc}): ${err}")
endif()

set(seq ${DATA_DIR}/semantickitti/sequences/00)
if(EXISTS ${seq}/velodyne/000000.bin AND EXISTS ${seq}/labels/000000.label)
  set(real -i ${seq} --max-frames 1)  # labels/ found beside velodyne/

  run_ok(${TRAVEL_EVAL} report ${real} -o ${WORK_DIR}/report --methods travel,gpf)
  expect_file_contains(${WORK_DIR}/report/report.md
                       "A (Patchwork benchmark)" "B (Patchwork++)" "| travel |" "| gpf |")
  # Header + one row per (method, frame): 2 methods x 1 frame.
  file(STRINGS ${WORK_DIR}/report/frames.csv rows)
  list(LENGTH rows n)
  if(NOT n EQUAL 3)
    message(FATAL_ERROR "frames.csv has ${n} lines, expected 3 (header + 2 rows)")
  endif()

  # --max-frames above 2^32: all (three) frames, not the count modulo 2^32 (1).
  run_ok(${TRAVEL_EVAL} report -i ${seq} --max-frames 4294967297 -o ${WORK_DIR}/all --methods tgs)
  file(STRINGS ${WORK_DIR}/all/frames.csv rows)
  list(LENGTH rows n)
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "--max-frames 4294967297: frames.csv has ${n} lines, expected 4")
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

  # Leave-one-out on coverage of a ground-only method: an error, and no sweep files of it;
  # --loo-score where there is no leave-one-out (one frame): a usage error.
  expect_failure_mentioning("choose f1b or f1a" ${TRAVEL_EVAL} sweep -i ${seq} --max-frames 2
                            --method tgs --sweep tgf_resolution=4,8 --loo-score coverage
                            -o ${WORK_DIR}/sweep_tgs)
  if(EXISTS ${WORK_DIR}/sweep_tgs)
    message(FATAL_ERROR "sweep --loo-score coverage of tgs left ${WORK_DIR}/sweep_tgs")
  endif()
  expect_failure_mentioning("two labelled frames or more; 1 found" ${TRAVEL_EVAL} sweep ${real}
                            --sweep tgf_resolution=4,8 --loo-score f1a -o ${WORK_DIR}/sweep_one)

  # merges: the three tables, and one CSV row per part whose rule is one of the six names.
  run_ok(${TRAVEL_EVAL} merges ${real} -o ${WORK_DIR}/merges)
  expect_file_contains(${WORK_DIR}/merges/merges.md
                       "| linkage rule | parts |" "| owner + part class | parts |" "| horizontal |")
  file(STRINGS ${WORK_DIR}/merges/merges.csv rows)
  list(POP_FRONT rows header)
  if(NOT header MATCHES "^frame,cluster,.*,rule,link_distance,depth_jump,row_gap$" OR NOT rows)
    message(FATAL_ERROR "merges.csv: header '${header}', ${rows}")
  endif()
  foreach(row ${rows})
    if(NOT row MATCHES "^00/000000,[0-9]+,.*,(horizontal|vertical|range-scaled vertical|occlusion|seam|indirect),[0-9.e-]+,[0-9.e-]+,[0-9]+$")
      message(FATAL_ERROR "merges.csv: unexpected row '${row}'")
    endif()
  endforeach()

  # merges on two workers: the same tables and rows as on one.
  run_ok(${TRAVEL_EVAL} merges -i ${seq} --max-frames 2 -j 2 -o ${WORK_DIR}/merges2)
  run_ok(${TRAVEL_EVAL} merges -i ${seq} --max-frames 2 -j 1 -o ${WORK_DIR}/merges1)
  foreach(file merges.md merges.csv)
    file(MD5 ${WORK_DIR}/merges1/${file} one)
    file(MD5 ${WORK_DIR}/merges2/${file} two)
    if(NOT one STREQUAL two)
      message(FATAL_ERROR "merges -j 2 wrote another ${file} than -j 1")
    endif()
  endforeach()

  # A label file of the wrong length on the second frame: an error naming it, and no output at all (no
  # merges.csv holding the first frame's rows, no empty folder).
  file(MAKE_DIRECTORY ${WORK_DIR}/cut/velodyne ${WORK_DIR}/cut/labels)
  file(COPY ${seq}/velodyne/000000.bin ${seq}/velodyne/000001.bin
       DESTINATION ${WORK_DIR}/cut/velodyne)
  file(COPY ${seq}/labels/000000.label DESTINATION ${WORK_DIR}/cut/labels)
  file(WRITE ${WORK_DIR}/cut/labels/000001.label "12345678")  # 2 labels for 124k points
  foreach(command report merges)
    expect_failure_mentioning("000001.label" ${TRAVEL_EVAL} ${command} -i ${WORK_DIR}/cut -j 1
                              -o ${WORK_DIR}/cut_${command})
    if(EXISTS ${WORK_DIR}/cut_${command})
      file(GLOB left ${WORK_DIR}/cut_${command}/*)
      message(FATAL_ERROR "${command}: a run that failed on a frame left ${WORK_DIR}/cut_${command} (${left})")
    endif()
  endforeach()
else()
  message(STATUS "SemanticKITTI frames not found in ${seq}: real-data part skipped")
endif()
