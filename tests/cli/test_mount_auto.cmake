# sensor_height: auto through travel-rawlog on MRPT's VLP-16 sample (2.24 m above the floor):
# the estimate is reported, the preset's wrong 0.5 m draws one warning with the value to set,
# -q prints neither, and with the hand-made config's cell size the estimated height labels every
# point like the hand-made config (the height is the only thing `auto` replaces).
# Inputs: TRAVEL_RAWLOG, CONFIG (share/configs/mrpt_sample_vlp16.yaml), SAMPLE, WORK_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(MAKE_DIRECTORY ${WORK_DIR})

expect_success(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/auto.rawlog -p vlp16
  --set sensor_height=auto --set tgf_resolution=4 --label-reference ${WORK_DIR}/auto.txt)
string(REGEX MATCH "sensor_height auto: 2\\.2[0-9] m \\(from frame 0, [0-9,]+ ground points\\)"
  found "${last_output}")
if(NOT found)
  message(FATAL_ERROR "no 'sensor_height auto: 2.2x m' report:\n${last_output}")
endif()

expect_success(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/hand.rawlog -c ${CONFIG}
  --label-reference ${WORK_DIR}/hand.txt)
string(FIND "${last_output}" "sensor_height" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "the measured height 2.24 m drew a report:\n${last_output}")
endif()
file(STRINGS ${WORK_DIR}/auto.txt auto_lines)
file(STRINGS ${WORK_DIR}/hand.txt hand_lines)
if(NOT auto_lines STREQUAL hand_lines)
  message(FATAL_ERROR "sensor_height auto labels differ from sensor_height 2.24")
endif()

expect_success(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/preset.rawlog -p vlp16)
string(REGEX MATCH "warning: [^\n]*sensor_height is 0\\.50 m but the ground is 2\\.2[0-9] m below the sensor: set sensor_height: 2\\.2[0-9] or auto"
  found "${last_output}")
if(NOT found)
  message(FATAL_ERROR "no warning about sensor_height 0.5 m:\n${last_output}")
endif()
string(REGEX MATCHALL "sensor_height is" all "${last_output}")
list(LENGTH all count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "the warning is not printed once:\n${last_output}")
endif()

expect_success(${TRAVEL_RAWLOG} -q -i ${SAMPLE} -o ${WORK_DIR}/quiet.rawlog -p vlp16
  --set sensor_height=auto)
if(NOT last_output STREQUAL "")
  message(FATAL_ERROR "-q printed:\n${last_output}")
endif()
