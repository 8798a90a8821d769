# TravelFilter and travel-rawlog on the rawlogs of mrpt-common (included from CMakeLists.txt
# inside if(TRAVEL_BUILD_MRPT); needs plugin_tests.cmake and filter_tests.cmake first).
travel_mrpt_test(test_mrpt_rawlogs test_mrpt_rawlogs.cpp)
target_include_directories(test_mrpt_rawlogs PRIVATE ${CMAKE_CURRENT_LIST_DIR})

# travel-rawlog end to end: the README's main job read back through the plugin in another
# process, re-runs on its own output, and the moving-robot rawlog (levelling + deskew).
add_test(NAME apps.travel_rawlog_cli
  COMMAND ${CMAKE_COMMAND}
    -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
    -DREADER=$<TARGET_FILE:travel_plugin_roundtrip_reader>
    -DPLUGIN=$<TARGET_FILE:travel_mrpt_plugin>
    -DMAKE_SYNTHETIC=$<TARGET_FILE:make_synthetic_rawlog>
    -DCONFIG=${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml
    -DSAMPLE=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_rawlog
    -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_rawlog.cmake)
set_tests_properties(apps.travel_rawlog_cli PROPERTIES TIMEOUT 300)

# travel-rawlog -j N: the same output as -j 1 (compared record by record, timings excepted).
add_executable(compare_travel_rawlogs ${CMAKE_CURRENT_LIST_DIR}/compare_travel_rawlogs.cpp)
target_link_libraries(compare_travel_rawlogs PRIVATE travel::mrpt mrpt::io mrpt::serialization)
target_compile_options(compare_travel_rawlogs PRIVATE -Wall -Wextra)
add_test(NAME apps.travel_rawlog_jobs
  COMMAND ${CMAKE_COMMAND}
    -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
    -DCOMPARE=$<TARGET_FILE:compare_travel_rawlogs>
    -DMAKE_SYNTHETIC=$<TARGET_FILE:make_synthetic_rawlog>
    -DSAMPLE=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_rawlog_jobs
    -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_rawlog_jobs.cmake)
set_tests_properties(apps.travel_rawlog_jobs PROPERTIES TIMEOUT 300)

# sensor_height: auto on MRPT's sample: reported, the preset's wrong height warned once.
add_test(NAME apps.travel_rawlog_mount_auto
  COMMAND ${CMAKE_COMMAND}
    -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
    -DCONFIG=${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml
    -DSAMPLE=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_mount_auto
    -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_mount_auto.cmake)
set_tests_properties(apps.travel_rawlog_mount_auto PROPERTIES TIMEOUT 120)

# The one rawlog reader of travel-rawlog and travel-map: records, exact error messages, motion.
travel_mrpt_test(test_rawlog_reader test_rawlog_reader.cpp)
target_link_libraries(test_rawlog_reader PRIVATE mrpt::obs mrpt::maps mrpt::img mrpt::io
  mrpt::serialization)

# Velodyne .pcap captures (MRPT's CVelodyneScanner) when mrpt-hwdrivers is installed.
if(TARGET travel_mrpt_hwdrivers)
  travel_mrpt_test(test_pcap_source test_pcap_source.cpp)
  target_link_libraries(test_pcap_source PRIVATE travel::mrpt_hwdrivers)
endif()
if(TARGET travel_mrpt_hwdrivers)
  add_test(NAME apps.travel_rawlog_pcap_cli
    COMMAND ${CMAKE_COMMAND}
      -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
      -DREADER=$<TARGET_FILE:travel_plugin_roundtrip_reader>
      -DPLUGIN=$<TARGET_FILE:travel_mrpt_plugin>
      -DDATA_DIR=${TRAVEL_DATA_DIR}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_rawlog_pcap
      -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_rawlog_pcap.cmake)
  set_tests_properties(apps.travel_rawlog_pcap_cli PROPERTIES TIMEOUT 300)
endif()

# travel-regress (docs/regression.md): exit codes, reports and errors ...
add_test(NAME apps.travel_regress_cli
  COMMAND ${CMAKE_COMMAND}
    -DTRAVEL_RAWLOG=$<TARGET_FILE:travel-rawlog>
    -DTRAVEL_REGRESS=$<TARGET_FILE:travel-regress>
    -DSAMPLE=/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_regress
    -P ${CMAKE_CURRENT_LIST_DIR}/cli/test_travel_regress.cmake)
set_tests_properties(apps.travel_regress_cli PROPERTIES TIMEOUT 300)
# ... and the project's own rawlog regressions through travel_add_rawlog_regression, the function
# users call: the golden rawlogs are written by travel-rawlog first (fixture), then replayed.
include(${PROJECT_SOURCE_DIR}/cmake/TravelRegression.cmake)
set(regress_dir ${CMAKE_CURRENT_BINARY_DIR}/rawlog_regression)
add_test(NAME apps.rawlog_regression_golden
  COMMAND travel-rawlog -i /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
    -o ${regress_dir}/vlp16_golden.rawlog -c ${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml -q)
set_tests_properties(apps.rawlog_regression_golden PROPERTIES FIXTURES_SETUP rawlog_regression)
travel_add_rawlog_regression(NAME apps.rawlog_regression_vlp16
  RAWLOG /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog
  GOLDEN ${regress_dir}/vlp16_golden.rawlog
  CONFIG ${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml
  REPORT_DIR ${regress_dir}/vlp16 TIMEOUT 120)
set_tests_properties(apps.rawlog_regression_vlp16 PROPERTIES FIXTURES_REQUIRED rawlog_regression)
