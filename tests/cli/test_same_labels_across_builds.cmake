# The Release build (-O3, what users run) writes the same labels and cluster ids, byte for byte,
# as the sanitizer build (-Og, ASan + UBSan), in which scripts/run-tests.sh runs the unit tests.
# The unit tests themselves do not run on the Release library: this comparison is what shows
# that their thresholds carry over, on one scan of every scene they use (make_synthetic_scans
# --scenes), not on every pose, seed and parameter set they try.
# Run by scripts/run-tests.sh after both builds:
#   cmake -DRELEASE_KITTI=build/apps/travel-kitti -DCHECKED_KITTI=build-asan/apps/travel-kitti \
#         -DMAKE_SCANS=build/tests/make_synthetic_scans -DWORK_DIR=DIR [-DDATA_DIR=../shared/data] \
#         -P tests/cli/test_same_labels_across_builds.cmake
# Cases: generated HDL-64E scans of the mixed scene and the scene catalogue under three presets
# (the default, os64 with the face rule under every ground point, os128 with its elevation
# table), then, when DATA_DIR holds them, the three SemanticKITTI dev frames, the 128-beam scan
# and the 22-frame drive (also with --track).
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
foreach(var RELEASE_KITTI CHECKED_KITTI MAKE_SCANS WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "test_same_labels_across_builds.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
expect_success(${MAKE_SCANS} ${WORK_DIR}/scans 3)
expect_success(${MAKE_SCANS} --scenes ${WORK_DIR}/scenes)

set(compared 0)
# Runs both builds' travel-kitti on `input` (extra flags after it) and compares every .label file.
function(expect_same_labels name input)
  foreach(build release checked)
    string(TOUPPER ${build} upper)
    expect_success(${${upper}_KITTI} -i ${input} -o ${WORK_DIR}/${name}_${build} -q ${ARGN})
  endforeach()
  file(GLOB labels RELATIVE ${WORK_DIR}/${name}_release ${WORK_DIR}/${name}_release/*.label)
  file(GLOB other RELATIVE ${WORK_DIR}/${name}_checked ${WORK_DIR}/${name}_checked/*.label)
  list(LENGTH labels count)
  if(count EQUAL 0)
    message(FATAL_ERROR "${name}: the Release build wrote no .label file for ${input}")
  endif()
  if(NOT other STREQUAL labels)
    message(FATAL_ERROR "${name}: the sanitizer build wrote [${other}], the Release build [${labels}]")
  endif()
  foreach(label ${labels})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                    ${WORK_DIR}/${name}_release/${label} ${WORK_DIR}/${name}_checked/${label}
                    RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${name}: ${label} differs between the Release build (${RELEASE_KITTI}) "
                          "and the sanitizer build (${CHECKED_KITTI})")
    endif()
  endforeach()
  math(EXPR total "${compared} + ${count}")
  set(compared ${total} PARENT_SCOPE)
  message(STATUS "${name}: ${count} label files identical")
endfunction()

expect_same_labels(synthetic ${WORK_DIR}/scans)
expect_same_labels(synthetic_os64 ${WORK_DIR}/scans -p os64)
expect_same_labels(synthetic_os128 ${WORK_DIR}/scans -p os128)
expect_same_labels(scenes ${WORK_DIR}/scenes)
expect_same_labels(scenes_os64 ${WORK_DIR}/scenes -p os64)
expect_same_labels(scenes_os128 ${WORK_DIR}/scenes -p os128)

if(DEFINED DATA_DIR AND IS_DIRECTORY ${DATA_DIR}/semantickitti/sequences/00/velodyne)
  expect_same_labels(kitti_dev ${DATA_DIR}/semantickitti/sequences/00/velodyne)
  if(EXISTS ${DATA_DIR}/ouster128/000000.bin)
    expect_same_labels(ouster128 ${DATA_DIR}/ouster128/000000.bin -p os128)
  endif()
  if(IS_DIRECTORY ${DATA_DIR}/kitti_raw_pcd)
    expect_same_labels(kitti_raw_pcd ${DATA_DIR}/kitti_raw_pcd)
    expect_same_labels(kitti_raw_pcd_track ${DATA_DIR}/kitti_raw_pcd --track)
  endif()
else()
  message(STATUS "real scans skipped: no SemanticKITTI frames under '${DATA_DIR}' "
                 "(../shared/data beside the repository)")
endif()
message(STATUS "Release and sanitizer builds: ${compared} label files identical")
