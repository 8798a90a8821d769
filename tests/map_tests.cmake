# The traversability map layer (included from tests/CMakeLists.txt inside if(TRAVEL_BUILD_MRPT),
# after plugin_tests.cmake, so travel_mrpt_plugin exists).
find_package(octomap REQUIRED)

# The synthetic scene of the map tests, shared by the in-process tests and the plugin host
# (which must not link travel_mrpt): travel::sim + MRPT observations only.
add_library(travel_map_test_scene STATIC ${CMAKE_CURRENT_LIST_DIR}/map/MapTestScene.cpp)
target_include_directories(travel_map_test_scene PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(travel_map_test_scene PUBLIC travel::travel travel::sim mrpt::maps mrpt::obs)
target_compile_options(travel_map_test_scene PRIVATE -Wall -Wextra -Wpedantic)

travel_mrpt_test(test_map_fusion test_map_fusion.cpp)
target_link_libraries(test_map_fusion PRIVATE travel_map_test_scene octomap octomath)

# Moving objects (tracker flag) stay out of the static map.
travel_mrpt_test(test_map_moving test_map_moving.cpp)
target_link_libraries(test_map_moving PRIVATE octomap octomath)

travel_mrpt_test(test_map_options test_map_options.cpp)
target_link_libraries(test_map_options PRIVATE travel_map_test_scene)

# CMultiMetricMap from an .ini in a process that knows the map only through the plugin module.
add_executable(travel_map_plugin_host map/plugin_host.cpp)
target_link_libraries(travel_map_plugin_host PRIVATE travel_map_test_scene
  mrpt::maps mrpt::obs mrpt::system)
target_compile_options(travel_map_plugin_host PRIVATE -Wall -Wextra -Wpedantic)
add_dependencies(travel_map_plugin_host travel_mrpt_plugin)
add_test(NAME map.multimetricmap_plugin_by_path
  COMMAND travel_map_plugin_host $<TARGET_FILE:travel_mrpt_plugin>
    ${CMAKE_CURRENT_BINARY_DIR}/map_plugin_host)
set_tests_properties(map.multimetricmap_plugin_by_path PROPERTIES TIMEOUT 120)

if(TARGET travel-map)
  add_test(NAME apps.travel_map_cli
    COMMAND ${CMAKE_COMMAND}
      -DTRAVEL_MAP=$<TARGET_FILE:travel-map>
      -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
      -DMAKE_SYNTHETIC=$<TARGET_FILE:make_synthetic_rawlog>
      -DSAMPLE=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
      -DCONFIG=${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml
      -DDATA_DIR=${TRAVEL_DATA_DIR}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_map
      -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_map.cmake)
  set_tests_properties(apps.travel_map_cli PROPERTIES TIMEOUT 300)
  # -j 2: byte-identical outputs to -j 1 (generated scans; the HDL-64E drive when present).
  # make_synthetic_scans is defined later in tests/CMakeLists.txt (same if(TRAVEL_BUILD_MRPT)).
  add_test(NAME apps.travel_map_jobs
    COMMAND ${CMAKE_COMMAND}
      -DTRAVEL_MAP=$<TARGET_FILE:travel-map>
      -DMAKE_SCANS=$<TARGET_FILE:make_synthetic_scans>
      -DPOSES=${PROJECT_SOURCE_DIR}/share/bench/kitti_raw_pcd_poses.txt
      -DDATA_DIR=${TRAVEL_DATA_DIR}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_map_jobs
      -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_map_jobs.cmake)
  set_tests_properties(apps.travel_map_jobs PROPERTIES TIMEOUT 300)
endif()

# See mrpt_plugin/CMakeLists.txt: UBSan's alignment check misreads MRPT's opengl class layout.
if(TRAVEL_SANITIZE MATCHES "undefined|alignment")
  set_source_files_properties(test_map_fusion.cpp map/plugin_host.cpp
    PROPERTIES COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
