# sensor_height: auto through travel-rawlog on MRPT's VLP-16 sample (2.24 m above the floor):
# the estimate is reported, the preset's wrong 0.5 m draws one warning with the value to set,
# -q prints neither, and the preset with the estimated height labels the points like the
# hand-made config (sensor_height 2.24, tgf_resolution 4, seed_search_radius 12): at most 1 % of
# the points differ in class (7.25 % differed with the preset's former 2 m cells).
cmake_minimum_required(VERSION 3.17)  # foreach(... IN ZIP_LISTS) below; the project itself needs 3.16
# Inputs: TRAVEL_RAWLOG, CONFIG (share/configs/mrpt_sample_vlp16.yaml), SAMPLE, WORK_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(MAKE_DIRECTORY ${WORK_DIR})

expect_success(${TRAVEL_RAWLOG} -i ${SAMPLE} -o ${WORK_DIR}/auto.rawlog -p vlp16
  --set sensor_height=auto --label-reference ${WORK_DIR}/auto.txt)
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
list(LENGTH auto_lines n_auto)
list(LENGTH hand_lines n_hand)
if(NOT n_auto EQUAL n_hand OR n_auto LESS 1000)
  message(FATAL_ERROR "label references differ in length: ${n_auto} vs ${n_hand}")
endif()
# Lines: a header, a frame line, then "class cluster" per point; compare the classes.
set(differ 0)
foreach(a h IN ZIP_LISTS auto_lines hand_lines)
  string(REGEX MATCH "^[0-9]+ [0-9]+$" is_point "${a}")  # not the header or frame lines
  if(is_point AND NOT a STREQUAL h)
    string(REGEX MATCH "^[0-9]+" a "${a}")
    string(REGEX MATCH "^[0-9]+" h "${h}")
    if(NOT a STREQUAL h)
      math(EXPR differ "${differ} + 1")
    endif()
  endif()
endforeach()
math(EXPR allowed "(${n_auto} - 2) / 100")
if(differ GREATER allowed)
  message(FATAL_ERROR "preset vlp16 + sensor_height auto: ${differ} points differ in class from "
    "the hand-made config (more than 1 %, ${allowed})")
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
