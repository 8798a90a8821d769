# The TRAVEL observation filter and the synthetic moving-robot rawlog (included from
# tests/CMakeLists.txt inside if(TRAVEL_BUILD_MRPT), where travel_mrpt_test() exists).
find_package(mrpt-io REQUIRED)
find_package(mrpt-serialization REQUIRED)

# The synthetic rawlog generator, shared by the tests and the command-line tests.
add_library(travel_synthetic_rawlog STATIC ${CMAKE_CURRENT_LIST_DIR}/SyntheticRawlog.cpp)
target_include_directories(travel_synthetic_rawlog PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(travel_synthetic_rawlog
  PUBLIC travel::travel travel::sim
  PRIVATE mrpt::maps mrpt::obs mrpt::io mrpt::serialization mrpt::poses)
target_compile_options(travel_synthetic_rawlog PRIVATE -Wall -Wextra -Wpedantic)

add_executable(make_synthetic_rawlog ${CMAKE_CURRENT_LIST_DIR}/make_synthetic_rawlog.cpp)
target_link_libraries(make_synthetic_rawlog PRIVATE travel_synthetic_rawlog mrpt::maps mrpt::obs)
target_compile_options(make_synthetic_rawlog PRIVATE -Wall -Wextra -Wpedantic)

travel_mrpt_test(test_travel_filter test_travel_filter.cpp)
target_link_libraries(test_travel_filter PRIVATE mrpt::maps mrpt::obs mrpt::io mrpt::serialization)

# TravelFilter's object tracking (track_objects) on the synthetic street rawlog.
travel_mrpt_test(test_filter_tracking test_filter_tracking.cpp)
target_link_libraries(test_filter_tracking PRIVATE travel_synthetic_rawlog mrpt::obs)

travel_mrpt_test(test_moving_robot test_moving_robot.cpp)
target_link_libraries(test_moving_robot
  PRIVATE travel_synthetic_rawlog mrpt::maps mrpt::obs mrpt::io mrpt::serialization)
target_compile_definitions(test_travel_filter PRIVATE
  TRAVEL_MRPT_SAMPLE_VLP16_FOR_FILTER="/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog")
