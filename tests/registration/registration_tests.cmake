# An independent registration of the real drive (MRPT's ICP, mrpt::slam::CICP) and the check of
# travel-kitti --track's pose file against it (issue 19). Included from tests/CMakeLists.txt
# inside if(TRAVEL_BUILD_MRPT); optional: mrpt-slam (libmrpt-slam-dev, scripts/setup.sh).
find_package(mrpt-slam QUIET)
if(NOT mrpt-slam_FOUND)
  message(STATUS "mrpt-slam not found (libmrpt-slam-dev): no independent registration test")
  return()
endif()
add_library(travel_cicp_odometry STATIC ${CMAKE_CURRENT_LIST_DIR}/CicpOdometry.cpp)
target_link_libraries(travel_cicp_odometry PUBLIC travel::travel mrpt::slam mrpt::maps)

# KITTI poses of a drive by MRPT's ICP: build/tests/register_scans_mrpt DIR/*.pcd > poses.txt
add_executable(register_scans_mrpt ${CMAKE_CURRENT_LIST_DIR}/register_scans_mrpt.cpp)
target_link_libraries(register_scans_mrpt PRIVATE travel_cicp_odometry travel::io
  travel::traversability)
target_compile_options(register_scans_mrpt PRIVATE -Wall -Wextra)

if(TARGET travel-kitti)
  travel_test(test_independent_registration
    ${CMAKE_CURRENT_LIST_DIR}/test_independent_registration.cpp)
  target_link_libraries(test_independent_registration PRIVATE travel_cicp_odometry
    travel::traversability)
  target_compile_definitions(test_independent_registration PRIVATE
    TRAVEL_KITTI_EXE="$<TARGET_FILE:travel-kitti>")
  add_dependencies(test_independent_registration travel-kitti)
endif()
