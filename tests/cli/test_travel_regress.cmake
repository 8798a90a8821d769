# travel-regress end to end on MRPT's VLP-16 sample (docs/regression.md): a replay against its
# own golden labelled rawlog passes (exit 0, 100 %); sensor_height + 0.3 m is detected with the
# frame and the classes that changed (exit 1, report, CSV, picture) and passes once the
# tolerances (--set or the config's regress section) allow it; a golden frame the replay lacks is
# reported missing; a truncated golden rawlog, a rawlog without labels and a missing file are
# errors (exit 2) named as such.
# Inputs: TRAVEL_RAWLOG, TRAVEL_REGRESS, SAMPLE, WORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(golden ${WORK_DIR}/golden.rawlog)

# Runs travel-regress; checks the exit code and that the output matches every regex given.
function(regress expected_rc)
  cmake_parse_arguments(R "" "" "ARGS;MATCH" ${ARGN})
  execute_process(COMMAND ${TRAVEL_REGRESS} -i ${SAMPLE} --golden ${golden} -p vlp16 ${R_ARGS}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL "${expected_rc}")
    message(FATAL_ERROR "exit ${rc}, expected ${expected_rc}: ${R_ARGS}\n${out}${err}")
  endif()
  foreach(regex IN LISTS R_MATCH)
    if(NOT "${out}${err}" MATCHES "${regex}")
      message(FATAL_ERROR "output does not match '${regex}': ${R_ARGS}\n${out}${err}")
    endif()
  endforeach()
endfunction()

execute_process(COMMAND ${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${golden} -p vlp16 -q RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "travel-rawlog failed: ${rc}")
endif()

# The run against itself.
regress(0 ARGS -o ${WORK_DIR}/self MATCH
  "PASS: 1 frames compared \\(0 differ\\), 0 missing, 0 extra; class agreement 100\\.000 %, cluster agreement 100\\.000 %, split 0, merged 0, traversable nodes changed 0")
file(READ ${WORK_DIR}/self/report.md report)
if(NOT report MATCHES "## Frames that differ\n\nNone\\.")
  message(FATAL_ERROR "self comparison lists differing frames:\n${report}")
endif()

# One parameter changed: sensor_height 0.5 -> 0.8 m.
regress(1 ARGS --set sensor_height=0.8 -o ${WORK_DIR}/height MATCH
  "FAIL: 1 frames compared \\(1 differ\\)" "class agreement [0-9.]+ % in frame 0 < min_class_agreement 100 %")
file(READ ${WORK_DIR}/height/report.md report)
if(NOT report MATCHES "\\| 0 \\| [0-9.]+ \\| Velodyne1_SCAN_travel \\| [1-9][0-9]* \\| (ground|nonground) -> (ground|nonground) [0-9]+")
  message(FATAL_ERROR "the report does not name the frame and the classes that changed:\n${report}")
endif()
file(STRINGS ${WORK_DIR}/height/frames.csv csv)
list(LENGTH csv lines)
list(GET csv 1 frame0)
if(NOT lines EQUAL 2 OR NOT frame0 MATCHES "^0,compared,[0-9.]+,Velodyne1_SCAN_travel,11305,11305,[1-9]")
  message(FATAL_ERROR "frames.csv:\n${csv}")
endif()
if(NOT EXISTS ${WORK_DIR}/height/diff_000000.png)
  message(FATAL_ERROR "no picture of the differing frame")
endif()

# Within tolerances given on the command line, and in a config file.
set(loose --set regress.min_class_agreement=90 --set regress.min_cluster_agreement=80
    --set regress.max_split_clusters=100 --set regress.max_merged_clusters=100
    --set regress.max_changed_nodes=1000)
regress(0 ARGS --set sensor_height=0.8 ${loose} MATCH "PASS: 1 frames compared \\(1 differ\\)")
file(WRITE ${WORK_DIR}/loose.yaml "regress:\n  min_class_agreement: 90\n  min_cluster_agreement: 80\n"
  "  max_split_clusters: 100\n  max_merged_clusters: 100\n  max_changed_nodes: 1000\n")
regress(0 ARGS -c ${WORK_DIR}/loose.yaml --set sensor_height=0.8 MATCH "PASS")

# --sensor-label comes before each --set (docs/cli.md).
regress(0 ARGS --sensor-label A --set filter.sensor_label=B --print-config
        MATCH "\n  sensor_label: B\n")

# A golden frame without a replayed twin is reported, not skipped.
regress(1 ARGS --sensor-label nothing MATCH "0 frames compared .*1 missing" "1 golden frames missing")

# Errors: exit 2 and the reader's message.
file(SIZE ${golden} size)
math(EXPR half "${size} / 2")
execute_process(COMMAND head -c ${half} ${golden} OUTPUT_FILE ${WORK_DIR}/truncated.rawlog)
set(golden ${WORK_DIR}/truncated.rawlog)
regress(2 MATCH "error: [^\n]*truncated.rawlog: record [0-9]+: truncated \\(end of file inside the record\\)")
set(golden ${SAMPLE})
regress(2 MATCH "no CObservationTravelLabels")
set(golden ${WORK_DIR}/none.rawlog)
regress(2 MATCH "none.rawlog: no such file")
regress(2 ARGS --pictures -1 MATCH "--pictures must be >= 0")
# Picture flags without -o, where the pictures are written, would be ignored: named instead.
regress(2 ARGS --pictures 2 MATCH "--pictures needs -o")
regress(2 ARGS --size 400 MATCH "--mpp and --size need -o")
regress(2 ARGS -o ${WORK_DIR}/no_pictures --pictures 0 --mpp 0.1 MATCH "--mpp and --size need")
