# travel-map -j N: with -j 2 (and 3) every output (.bt, .gridmap.gz, .travelmap, pictures,
# .3Dscene) is byte-identical to -j 1's: scans are read, segmented and fused into the grid on
# one thread and the OctoMap is updated on the other, each stage in frame order. Generated
# scans (no real data); the HDL-64E drive kitti_raw_pcd (first 6 frames, its pose file) when
# present. Variables: TRAVEL_MAP, MAKE_SCANS, POSES, WORK_DIR, DATA_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
expect_success(${MAKE_SCANS} ${WORK_DIR}/scans 5)

# Maps `input` with -j 1, 2 and 3 (extra flags after it) and compares every file written.
function(expect_same_maps name input)
  foreach(j 1 2 3)
    expect_success(${TRAVEL_MAP} -i ${input} -o ${WORK_DIR}/${name}_j${j} -q -j ${j} ${ARGN})
  endforeach()
  file(GLOB written RELATIVE ${WORK_DIR}/${name}_j1 ${WORK_DIR}/${name}_j1/*)
  list(LENGTH written count)
  if(count LESS 8)
    message(FATAL_ERROR "${name}: -j 1 wrote only [${written}]")
  endif()
  foreach(j 2 3)
    file(GLOB other RELATIVE ${WORK_DIR}/${name}_j${j} ${WORK_DIR}/${name}_j${j}/*)
    if(NOT other STREQUAL written)
      message(FATAL_ERROR "${name}: -j ${j} wrote [${other}], -j 1 wrote [${written}]")
    endif()
    foreach(file ${written})
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                      ${WORK_DIR}/${name}_j1/${file} ${WORK_DIR}/${name}_j${j}/${file}
                      RESULT_VARIABLE differ)
      if(differ)
        message(FATAL_ERROR "${name}: ${file} differs between -j 1 and -j ${j}")
      endif()
    endforeach()
  endforeach()
endfunction()

expect_same_maps(synthetic ${WORK_DIR}/scans --extent " -30,30,-30,30")
# --max-frames stops both threads at the same frame.
expect_same_maps(synthetic_max ${WORK_DIR}/scans --extent " -30,30,-30,30" --max-frames 3)

if(EXISTS ${DATA_DIR}/kitti_raw_pcd/0000000000.pcd)
  expect_same_maps(kitti_raw_pcd ${DATA_DIR}/kitti_raw_pcd --poses ${POSES} --max-frames 6)
else()
  message(STATUS "${DATA_DIR}/kitti_raw_pcd not found: real-scan part skipped")
endif()
