# travel-rawlog end to end (cmake -P):
#  1. the README's main job on mrpt-common's VLP-16 sample: summary, CSV, PNG, PLY, label
#     reference; the output rawlog is read back in ANOTHER process that only knows our class
#     through the plugin (travel_plugin_roundtrip_reader) and every label is compared;
#  2. a second run on that output replaces the earlier outputs instead of duplicating them;
#  3. the synthetic moving, tilted robot rawlog (VLP-16 rotating scans + IMU + odometry): every
#     frame is levelled and deskewed from the IMU/odometry records, and none when disabled;
#     with --track every frame is tracked with the odometry as ego-motion.
# Variables: TRAVEL_RAWLOG, READER, PLUGIN, MAKE_SYNTHETIC, CONFIG, SAMPLE, WORK_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(expect_in text needle)
  string(FIND "${text}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "expected '${needle}' in:\n${text}")
  endif()
endfunction()

# Reads `rawlog` in the plugin-only reader (another process) and compares every label with
# `reference`; each further argument must appear in the reader's output.
function(expect_read_back_through_plugin rawlog reference)
  execute_process(COMMAND ${READER} ${PLUGIN} ${rawlog} ${reference}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "plugin-only reader failed on ${rawlog}:\n${o}${e}")
  endif()
  foreach(needle ${ARGN})
    expect_in("${o}" "${needle}")
  endforeach()
endfunction()

if(EXISTS ${SAMPLE})
  set(out ${WORK_DIR}/vlp16_travel.rawlog)
  expect_success(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${out} --config ${CONFIG}
                 --csv ${WORK_DIR}/vlp16.csv --png ${WORK_DIR}/png/vlp16
                 --label-reference ${WORK_DIR}/vlp16.reference)
  expect_in("${last_output}" "LiDAR frames processed: 1")
  expect_in("${last_output}" "clusters: ")
  foreach(f vlp16.csv png/vlp16_000000.png png/vlp16_000000.ply vlp16.reference)
    if(NOT EXISTS ${WORK_DIR}/${f})
      message(FATAL_ERROR "travel-rawlog did not write ${f}")
    endif()
  endforeach()
  file(STRINGS ${WORK_DIR}/vlp16.csv csv)
  list(LENGTH csv csv_lines)
  if(NOT csv_lines EQUAL 2)
    message(FATAL_ERROR "vlp16.csv: expected a header and one frame, got ${csv_lines} lines")
  endif()

  expect_read_back_through_plugin(${out} ${WORK_DIR}/vlp16.reference
    "1 labelled frames and 11305 points compared, 0 mismatches")

  # Re-running on the output: the old _travel/_ground/... observations are replaced.
  expect_success(${TRAVEL_RAWLOG} -i ${out} -o ${WORK_DIR}/again.rawlog --config ${CONFIG}
                 --label-reference ${WORK_DIR}/again.reference)
  expect_in("${last_output}" "replacing the TRAVEL outputs of an earlier run")
  expect_in("${last_output}" "LiDAR frames processed: 1")
  expect_read_back_through_plugin(${WORK_DIR}/again.rawlog ${WORK_DIR}/again.reference
    "1 labelled frames" " 0 mismatches")
else()
  message(STATUS "${SAMPLE} not found (mrpt-common): sample cases skipped")
endif()

# The moving robot: 10 VLP-16 frames, IMU at 100 Hz, odometry at 50 Hz.
execute_process(COMMAND ${MAKE_SYNTHETIC} ${WORK_DIR}/moving.rawlog 10 RESULT_VARIABLE rc
                OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_synthetic_rawlog failed:\n${o}${e}")
endif()
set(moving_config --preset vlp16 --set sensor_height=1.8 --set min_range=2 --set max_range=60)
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog -o ${WORK_DIR}/moving_out.rawlog
               ${moving_config})
expect_in("${last_output}" "LiDAR frames processed: 10")
expect_in("${last_output}" "frames levelled 10, deskewed 10")
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog -o ${WORK_DIR}/moving_plain.rawlog
               ${moving_config} --set use_robot_attitude=false --set velocity_source=none)
expect_in("${last_output}" "frames levelled 0, deskewed 0")
# A filter key with a bad value is rejected naming the key.
expect_failure_mentioning("velocity_source" ${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog
                          -o ${WORK_DIR}/x.rawlog --set velocity_source=gps)

# The same robot in the SensoryFrame format (action collection + sensory frame per sweep): the
# labels go into each frame's SensoryFrame and read back through the plugin.
execute_process(COMMAND ${MAKE_SYNTHETIC} ${WORK_DIR}/moving_sf.rawlog 10 --sensory-frames
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_synthetic_rawlog --sensory-frames failed:\n${o}${e}")
endif()
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving_sf.rawlog -o ${WORK_DIR}/moving_sf_out.rawlog
               ${moving_config} --label-reference ${WORK_DIR}/moving_sf.reference)
expect_in("${last_output}" "records: 20, LiDAR frames processed: 10")
expect_in("${last_output}" "frames levelled 10, deskewed 10")
expect_read_back_through_plugin(${WORK_DIR}/moving_sf_out.rawlog ${WORK_DIR}/moving_sf.reference
  "10 labelled frames" " 0 mismatches")

# --track: the clusters tracked across the 10 frames with the odometry records as ego-motion;
# the labelled observations (version 1, with track ids) read back through the plugin.
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog -o ${WORK_DIR}/moving_track.rawlog
               ${moving_config} --track --label-reference ${WORK_DIR}/moving_track.reference)
expect_in("${last_output}"
  "tracking: frames tracked 10 (ego-motion from poses 10, from scan registration 0), tracks ")
expect_read_back_through_plugin(${WORK_DIR}/moving_track.rawlog
  ${WORK_DIR}/moving_track.reference "10 labelled frames" " 0 mismatches")

# Bad inputs: a class this build does not know (a renamed class in an uncompressed copy of the
# sample), a rawlog without any LiDAR observation, a config with an unknown key.
if(EXISTS ${SAMPLE})
  execute_process(COMMAND sh -c "gzip -dc '${SAMPLE}' | LC_ALL=C sed 's/CObservationVelodyneScan/CObservationVelodyneScaX/' > '${WORK_DIR}/unknown_class.rawlog'"
                  RESULT_VARIABLE rc)
  expect_failure_mentioning("unknown_class.rawlog: record 0" ${TRAVEL_RAWLOG}
                            -i ${WORK_DIR}/unknown_class.rawlog -o ${WORK_DIR}/x.rawlog)
  expect_failure_mentioning("CObservationVelodyneScaX' which is not registered" ${TRAVEL_RAWLOG}
                            -i ${WORK_DIR}/unknown_class.rawlog -o ${WORK_DIR}/x.rawlog)
  if(EXISTS ${WORK_DIR}/x.rawlog)
    message(FATAL_ERROR "a failed run left an output rawlog behind")
  endif()
endif()
# LiDAR observations without points (two, after frames 2 and 4): skipped and counted, and one
# note naming the first record and why (as travel-map's notes), not one per frame.
expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/unusable.rawlog 5 --unusable-frames)
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/unusable.rawlog -o ${WORK_DIR}/unusable_out.rawlog
               ${moving_config})
expect_in("${last_output}" "LiDAR frames processed: 5, skipped: 2")
string(REGEX MATCHALL "unusable.rawlog: record [0-9]+: skipped: 'VLP16': empty point cloud \\(not repeated"
       notes "${last_output}")
list(LENGTH notes count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "skipped frames: ${count} notes naming the record (want 1):\n${last_output}")
endif()

# Only IMU / odometry: the sensor label regex selects nothing LiDAR.
expect_failure_mentioning("no LiDAR observation processed" ${TRAVEL_RAWLOG}
                          -i ${WORK_DIR}/moving.rawlog -o ${WORK_DIR}/x.rawlog ${moving_config}
                          --sensor-label IMU)
# --sensor-label, a flag for a configuration key, comes before each --set (docs/cli.md).
expect_success(${TRAVEL_RAWLOG} --sensor-label A --set filter.sensor_label=B --print-config)
if(NOT last_output MATCHES "\n  sensor_label: B\n")
  message(FATAL_ERROR "--set filter.sensor_label=B does not override --sensor-label A")
endif()
# --mpp / --size without --png would be ignored: named instead.
expect_failure_mentioning("--mpp and --size need --png" ${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog
                          -o ${WORK_DIR}/x.rawlog --mpp 0.05)
file(WRITE ${WORK_DIR}/typo.yaml "preset: vlp16\nsensor_heigth: 1.8\n")
expect_failure_mentioning("sensor_heigth" ${TRAVEL_RAWLOG} -i ${WORK_DIR}/moving.rawlog
                          -o ${WORK_DIR}/x.rawlog --config ${WORK_DIR}/typo.yaml)
