# The one command-line dialect (docs/cli.md), run once per app: --version prints the project's
# version, --help shows examples, an unknown or replaced flag is named with a suggestion and a
# non-zero exit, a missing -o is named, and -i/-o/-p/--set/-f with -q succeed printing nothing
# on stdout.
# Variables: APP (the app's name), EXE, VERSION (CMake's PROJECT_VERSION), WORK_DIR, DATA_DIR,
# MAKE_SYNTHETIC (travel-rawlog, travel-map, travel-regress), TRAVEL_RAWLOG (travel-regress's
# golden rawlog).
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# --version: "<app> <project version>", exit 0.
expect_success(${EXE} --version)
string(STRIP "${last_output}" version_line)
if(NOT version_line STREQUAL "${APP} ${VERSION}")
  message(FATAL_ERROR "--version printed '${version_line}', expected '${APP} ${VERSION}'")
endif()

# --help: the common flags and at least two examples of this app.
expect_success(${EXE} --help)
foreach(needle "-i <PATH>" "--output <PATH>" "--preset <NAME>" "--config <FILE>" "--set <"
               "--format <NAME>" "--quiet" "--verbose" "--print-config" "Examples:\n  ${APP}")
  string(FIND "${last_output}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "${APP} --help does not show '${needle}':\n${last_output}")
  endif()
endforeach()
string(REGEX MATCHALL "\n  ${APP}" examples "${last_output}")
list(LENGTH examples n)
if(n LESS 2)
  message(FATAL_ERROR "${APP} --help shows ${n} examples, expected two or three")
endif()

# A replaced spelling and a typo get the right flag suggested; neither prints the usage dump.
expect_failure_mentioning("unknown flag --scans; did you mean -i/--input?" ${EXE} --scans x)
expect_failure_mentioning("unknown flag --outptu; did you mean -o/--output?" ${EXE} --outptu x)
expect_failure_mentioning("unknown flag --bogus" ${EXE} --bogus)
execute_process(COMMAND ${EXE} --scans x RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}${err}" "USAGE" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "an unknown flag prints the whole usage:\n${out}${err}")
endif()
# --print-config alone prints the configuration (no input, output or command needed).
expect_success(${EXE} --print-config)
string(FIND "${last_output}" "travel:" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "${APP} --print-config printed no travel: section:\n${last_output}")
endif()

# -q and -v contradict.
set(pre "")
if(APP STREQUAL "travel-eval")
  set(pre report)  # its command
endif()
expect_failure_mentioning("-q/--quiet and -v/--verbose" ${EXE} ${pre} -q -v -i x -o ${WORK_DIR}/x)
# An empty value is refused, not taken as the default or, for -o, as the current folder
# (-o "$UNSET" in a script).
expect_failure_mentioning("-o/--output: empty value" ${EXE} ${pre} -i x --output=)
expect_failure_mentioning("-i/--input: empty value" ${EXE} ${pre} --input= -o ${WORK_DIR}/x)
# getopt_long's attached values: --input=x is --input x (the -q/-v check is reached), and a
# misspelt flag with one is still named with its suggestion.
expect_failure_mentioning("-q/--quiet and -v/--verbose"
                          ${EXE} ${pre} -q -v --input=x --output=${WORK_DIR}/x)
expect_failure_mentioning("unknown flag --outptu=x; did you mean -o/--output?" ${EXE} --outptu=x)

# -q on a successful run: nothing on stdout.
function(expect_quiet_success)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "expected success: ${ARGN}\n${out}${err}")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "-q printed on stdout: ${ARGN}\n${out}")
  endif()
endfunction()

function(expect_file path)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "${APP} did not write ${path}")
  endif()
endfunction()

set(seq ${DATA_DIR}/semantickitti/sequences/00)
set(have_kitti FALSE)
if(EXISTS ${seq}/velodyne/000000.bin)
  set(have_kitti TRUE)
  file(COPY ${seq}/velodyne/000000.bin DESTINATION ${WORK_DIR}/scans)
endif()
set(common -p hdl64 --set sensor_height=1.73 -q)
# An output folder that cannot be created (below a regular file): one message in every app.
file(WRITE ${WORK_DIR}/afile "not a folder")
set(no_folder "cannot create folder ${WORK_DIR}/afile")
# --max-frames N: 0 = all (the default), a negative N is a usage error, in every app that has it.
set(bad_max_frames "--max-frames must be >= 0")

if(APP STREQUAL "travel-kitti")
  expect_failure_mentioning("missing -o/--output" ${EXE} -i ${WORK_DIR}/scans)
  expect_failure_mentioning("kitti, nuscenes" ${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/o -f xyz)
  if(have_kitti)
    # One scan file, a folder of scans, a KITTI sequence folder (labels found).
    expect_quiet_success(${EXE} -i ${WORK_DIR}/scans/000000.bin -o ${WORK_DIR}/one -f kitti ${common})
    expect_quiet_success(${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/dir ${common})
    expect_success(${EXE} -i ${seq} -o ${WORK_DIR}/seq --max-frames 1)
    string(FIND "${last_output}" "protocol B" pos)
    if(pos EQUAL -1 OR NOT EXISTS ${WORK_DIR}/seq/000000.label OR NOT EXISTS ${WORK_DIR}/one/000000.label)
      message(FATAL_ERROR "a sequence folder's labels/ were not found:\n${last_output}")
    endif()
    expect_quiet_success(${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/all --max-frames 0 ${common})
    expect_file(${WORK_DIR}/all/000000.label)
    expect_failure_mentioning("${no_folder}/out" ${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/afile/out)
    # Two scans with one stem would write one .label twice: auto stops and suggests --format.
    file(COPY ${WORK_DIR}/scans/000000.bin DESTINATION ${WORK_DIR}/mixed)
    file(WRITE ${WORK_DIR}/mixed/000000.pcd "")
    expect_failure_mentioning("--format" ${EXE} -i ${WORK_DIR}/mixed -o ${WORK_DIR}/mixed_out)
    expect_quiet_success(${EXE} -i ${WORK_DIR}/mixed -o ${WORK_DIR}/mixed_out -f kitti ${common})
  endif()
  expect_failure_mentioning("${bad_max_frames}" ${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/o
                            --max-frames -1)
elseif(APP STREQUAL "travel-eval")
  expect_failure_mentioning("missing -o/--output" ${EXE} report -i ${seq})
  if(have_kitti)
    expect_quiet_success(${EXE} report -i ${seq} -o ${WORK_DIR}/eval --methods gpf -f kitti
                         --max-frames 1 ${common})
    expect_file(${WORK_DIR}/eval/report.md)
    expect_failure_mentioning("${no_folder}/eval" ${EXE} report -i ${seq} -o ${WORK_DIR}/afile/eval
                              --methods gpf --max-frames 1)
  endif()
  expect_failure_mentioning("${bad_max_frames}" ${EXE} report -i ${seq} -o ${WORK_DIR}/o
                            --max-frames -1)
elseif(APP STREQUAL "travel-view")
  expect_failure_mentioning("missing -o/--output" ${EXE} -i ${WORK_DIR}/scans)
  if(have_kitti)
    expect_quiet_success(${EXE} -i ${seq} --frame 0 -o ${WORK_DIR}/v.png -f kitti --mpp 0.1 ${common})
    expect_file(${WORK_DIR}/v.png)
    expect_failure_mentioning("${no_folder}" ${EXE} -i ${seq} --frame 0 -o ${WORK_DIR}/afile/v.png)
  endif()
elseif(APP STREQUAL "travel-map")
  expect_failure_mentioning("missing -o/--output" ${EXE} -i ${WORK_DIR}/scans)
  if(have_kitti)
    expect_quiet_success(${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/map -f kitti ${common}
                         --set map.resolution=0.5)
    expect_file(${WORK_DIR}/map/scans_traversability.png)
    expect_failure_mentioning("${no_folder}/map" ${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/afile/map)
  endif()
  expect_failure_mentioning("${bad_max_frames}" ${EXE} -i ${WORK_DIR}/scans -o ${WORK_DIR}/o
                            --max-frames -1)
  # -f names a scan format: a rawlog input takes only auto.
  expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street.rawlog)
  expect_failure_mentioning("only -f auto" ${EXE} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/o -f kitti)
elseif(APP STREQUAL "travel-rawlog")
  expect_failure_mentioning("missing -o/--output" ${EXE} -i ${WORK_DIR}/x.rawlog)
  expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street.rawlog)
  expect_failure_mentioning("only -f auto" ${EXE} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/o.rawlog -f pcd)
  expect_quiet_success(${EXE} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/out.rawlog -f auto
                       ${common} --png ${WORK_DIR}/png/f --mpp 0.1 --size 200)
  expect_file(${WORK_DIR}/out.rawlog)
  expect_failure_mentioning("${no_folder}" ${EXE} -i ${WORK_DIR}/street.rawlog
                            -o ${WORK_DIR}/afile/out.rawlog)
  # A failure while the outputs are being set up leaves no header-only CSV behind.
  expect_failure_mentioning("${no_folder}" ${EXE} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/o2.rawlog
                            --csv ${WORK_DIR}/frames.csv --png ${WORK_DIR}/afile/png/f)
  if(EXISTS ${WORK_DIR}/frames.csv)
    message(FATAL_ERROR "a failed run left ${WORK_DIR}/frames.csv behind")
  endif()
elseif(APP STREQUAL "travel-regress")
  expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street.rawlog)
  expect_failure_mentioning("missing --golden" ${EXE} -i ${WORK_DIR}/street.rawlog)
  expect_failure_mentioning("only -f auto" ${EXE} -i ${WORK_DIR}/street.rawlog
                            --golden ${WORK_DIR}/street.rawlog -f pcd)
  expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/golden.rawlog ${common})
  # -o is optional (the report folder); -q prints nothing when the comparison passes.
  expect_quiet_success(${EXE} -i ${WORK_DIR}/street.rawlog --golden ${WORK_DIR}/golden.rawlog
                       -f auto ${common})
  expect_quiet_success(${EXE} -i ${WORK_DIR}/street.rawlog --golden ${WORK_DIR}/golden.rawlog
                       -o ${WORK_DIR}/regress ${common})
  expect_file(${WORK_DIR}/regress/report.md)
  expect_failure_mentioning("${no_folder}" ${EXE} -i ${WORK_DIR}/street.rawlog
                            --golden ${WORK_DIR}/golden.rawlog -o ${WORK_DIR}/afile/regress)
elseif(APP STREQUAL "travel-nav-sim")
  expect_failure_mentioning("unknown flag -w; did you mean -i/--input?" ${EXE} -w flat_obstacles.world)
  expect_quiet_success(${EXE} -i flat_obstacles.world -o ${WORK_DIR}/nav --timeout 1 --no-navlog
                       -p hdl64 --set nav.max_step_height=0.1 -q)
  expect_file(${WORK_DIR}/nav/flat_obstacles_travel.csv)
  expect_failure_mentioning("${no_folder}/nav" ${EXE} -i flat_obstacles.world -o ${WORK_DIR}/afile/nav
                            --timeout 1 --no-navlog -q)
else()
  message(FATAL_ERROR "unknown APP '${APP}'")
endif()
