# travel-rawlog -j N writes what -j 1 writes (the TRAVEL labels' measured stage timings
# excepted): the same records, labels, clusters, track ids and velocities, the same label
# reference. Cases: MRPT's VLP-16 sample (also with sensor_height=auto, whose first frames are
# segmented in order before the workers take over), a synthetic rawlog with --track, and one of
# SensoryFrames (two LiDAR observations per record, odometry actions between).
# -DTRAVEL_RAWLOG -DCOMPARE -DMAKE_SYNTHETIC -DSAMPLE -DWORK_DIR
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# Runs travel-rawlog with -j 1 and each other -j, and compares the outputs.
# JOBS: the -j values besides 1 (default 2).
function(expect_same_outputs name input)
  cmake_parse_arguments(arg "" "" "JOBS" ${ARGN})
  if(NOT arg_JOBS)
    set(arg_JOBS 2)
  endif()
  foreach(j 1 ${arg_JOBS})
    expect_success(${TRAVEL_RAWLOG} -i ${input} -o ${WORK_DIR}/${name}_j${j}.rawlog -q -j ${j}
                   --label-reference ${WORK_DIR}/${name}_j${j}.txt ${arg_UNPARSED_ARGUMENTS})
  endforeach()
  foreach(j ${arg_JOBS})
    expect_success(${COMPARE} ${WORK_DIR}/${name}_j1.rawlog ${WORK_DIR}/${name}_j${j}.rawlog)
    file(READ ${WORK_DIR}/${name}_j1.txt one)
    file(READ ${WORK_DIR}/${name}_j${j}.txt other)
    if(NOT one STREQUAL other)
      message(FATAL_ERROR "${name}: -j ${j} label reference differs from -j 1's")
    endif()
  endforeach()
endfunction()

if(EXISTS ${SAMPLE})
  expect_same_outputs(vlp16 ${SAMPLE} -p vlp16)
  expect_same_outputs(vlp16_auto ${SAMPLE} -p vlp16 --set sensor_height=auto JOBS 2 3)
else()
  message(STATUS "${SAMPLE} not found: the VLP-16 cases skipped")
endif()
expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street.rawlog 8)
expect_same_outputs(street_track ${WORK_DIR}/street.rawlog --track)
expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street_sf.rawlog 6 --sensory-frames)
expect_same_outputs(street_sf ${WORK_DIR}/street_sf.rawlog --track)
