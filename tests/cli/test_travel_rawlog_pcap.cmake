# travel-rawlog on Velodyne .pcap captures (cmake -P): MRPT's HDL-32E and VLP-16 (GPS) samples
# become labelled rawlogs (>= 2 full rotations each), read back in another process through the
# plugin and compared label by label; ground shares are plausible for each scene; bad captures
# and a missing model fail naming the file. Skips (with a message) without ../shared/data.
# Variables: TRAVEL_RAWLOG, READER, PLUGIN, DATA_DIR, WORK_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

set(captures ${DATA_DIR}/velodyne_pcap)
if(NOT EXISTS ${captures}/sample_velodyne_hdl32.pcap)
  message(STATUS "SKIP: ${captures} is absent (real data in ../shared/data, see its README)")
  return()
endif()

# name preset min_frames min_ground_% max_ground_%
# The HDL-32E sample is a street (ground ~60 %); the VLP-16 sample a bench capture inside a
# ~1 m enclosure (little ground).
foreach(case "hdl32;hdl32;2;40;80" "vlp16_gps;vlp16;3;3;40")
  list(GET case 0 name)
  list(GET case 1 preset)
  list(GET case 2 min_frames)
  list(GET case 3 min_ground)
  list(GET case 4 max_ground)
  set(out ${WORK_DIR}/${name}.rawlog)
  expect_success(${TRAVEL_RAWLOG} -i ${captures}/sample_velodyne_${name}.pcap -o ${out}
                 --preset ${preset} --label-reference ${WORK_DIR}/${name}.reference)
  string(REGEX MATCH "LiDAR frames processed: ([0-9]+)" _ "${last_output}")
  set(frames ${CMAKE_MATCH_1})
  if(frames LESS min_frames)
    message(FATAL_ERROR "${name}: ${frames} frames, expected >= ${min_frames}:\n${last_output}")
  endif()
  string(REGEX MATCH "ground [0-9]+ \\(([0-9]+)\\.[0-9] %\\)" _ "${last_output}")
  set(ground ${CMAKE_MATCH_1})
  if(ground STREQUAL "" OR ground LESS min_ground OR ground GREATER max_ground)
    message(FATAL_ERROR "${name}: ground '${ground}' %, expected ${min_ground}-${max_ground} %:\n"
                        "${last_output}")
  endif()
  # Read back in a process that knows CObservationTravelLabels only through the plugin.
  execute_process(COMMAND ${READER} ${PLUGIN} ${out} ${WORK_DIR}/${name}.reference
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "plugin-only reader failed on ${out}:\n${o}${e}")
  endif()
  string(REGEX MATCH "([0-9]+) labelled frames and [0-9]+ points compared, 0 mismatches" _ "${o}")
  if(CMAKE_MATCH_1 STREQUAL "" OR CMAKE_MATCH_1 LESS 2)
    message(FATAL_ERROR "${out}: expected >= 2 labelled frames read back:\n${o}${e}")
  endif()
  message(STATUS "${name}: ${frames} frames, ground ${ground} %, ${CMAKE_MATCH_1} read back")
endforeach()

# The model: from --pcap-model when the preset names none; errors name the file and the flags.
set(vlp16 ${captures}/sample_velodyne_vlp16_gps.pcap)
expect_success(${TRAVEL_RAWLOG} -q -i ${vlp16} -o ${WORK_DIR}/model.rawlog --pcap-model VLP-16)
expect_failure_mentioning("--pcap-model" ${TRAVEL_RAWLOG} -i ${vlp16} -o ${WORK_DIR}/x.rawlog)
expect_failure_mentioning("not 'ouster'"
  ${TRAVEL_RAWLOG} -i ${vlp16} -o ${WORK_DIR}/x.rawlog --pcap-model ouster)
expect_failure_mentioning("--pcap-calibration"
  ${TRAVEL_RAWLOG} -i ${vlp16} -o ${WORK_DIR}/x.rawlog --pcap-model HDL64)
expect_failure_mentioning("${WORK_DIR}/missing.xml: no such file"
  ${TRAVEL_RAWLOG} -i ${vlp16} -o ${WORK_DIR}/x.rawlog --pcap-model HDL64
  --pcap-calibration ${WORK_DIR}/missing.xml)
# Bad captures: a text file named .pcap, a pcap header without packets, a missing file.
file(WRITE ${WORK_DIR}/text.pcap "not a capture\n")
expect_failure_mentioning("${WORK_DIR}/text.pcap: not a pcap capture"
  ${TRAVEL_RAWLOG} -i ${WORK_DIR}/text.pcap -o ${WORK_DIR}/x.rawlog --preset vlp16)
file(DOWNLOAD "file://${vlp16}" ${WORK_DIR}/header_only.pcap RANGE_START 0 RANGE_END 23)
expect_failure_mentioning("${WORK_DIR}/header_only.pcap: no Velodyne data packets"
  ${TRAVEL_RAWLOG} -i ${WORK_DIR}/header_only.pcap -o ${WORK_DIR}/x.rawlog --preset vlp16)
expect_failure_mentioning("${WORK_DIR}/missing.pcap: no such file"
  ${TRAVEL_RAWLOG} -i ${WORK_DIR}/missing.pcap -o ${WORK_DIR}/x.rawlog --preset vlp16)
foreach(f x.rawlog x.rawlog.part)
  if(EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "${f} written although every run failed")
  endif()
endforeach()
