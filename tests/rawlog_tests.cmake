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
target_link_libraries(test_rawlog_reader PRIVATE mrpt::obs mrpt::io mrpt::serialization)

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
