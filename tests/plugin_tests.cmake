# CObservationTravelLabels and the MRPT plugin module (included from CMakeLists.txt inside
# if(TRAVEL_BUILD_MRPT), where travel_mrpt_test() exists).
find_package(mrpt-io REQUIRED)
find_package(mrpt-maps REQUIRED)
find_package(mrpt-obs REQUIRED)
find_package(mrpt-opengl REQUIRED)
find_package(mrpt-rtti REQUIRED)
find_package(mrpt-serialization REQUIRED)
find_package(mrpt-system REQUIRED)

# In process: filling, serialization round trips, corrupt streams, text and 3-D view.
travel_mrpt_test(test_labels_observation plugin/test_labels_observation.cpp)
# Serialized objects written by older versions (read-compatibility fixtures).
target_compile_definitions(test_labels_observation PRIVATE
  TRAVEL_PLUGIN_TEST_DATA="${CMAKE_CURRENT_SOURCE_DIR}/plugin/data")

# Separate-process round trip. The writer links travel_mrpt; the reader does NOT: it knows the
# class only through the plugin module it loads (its link proves the header alone suffices).
add_executable(travel_plugin_roundtrip_writer plugin/roundtrip_writer.cpp)
target_link_libraries(travel_plugin_roundtrip_writer PRIVATE travel::mrpt travel::travel
  mrpt::io mrpt::obs mrpt::serialization)
target_compile_options(travel_plugin_roundtrip_writer PRIVATE -Wall -Wextra -Wpedantic)

add_executable(travel_plugin_roundtrip_reader plugin/roundtrip_reader.cpp)
target_include_directories(travel_plugin_roundtrip_reader PRIVATE
  ${PROJECT_SOURCE_DIR}/mrpt_plugin/obs/include)
target_link_libraries(travel_plugin_roundtrip_reader PRIVATE travel::travel
  mrpt::io mrpt::maps mrpt::obs mrpt::opengl mrpt::rtti mrpt::serialization mrpt::system)
target_compile_options(travel_plugin_roundtrip_reader PRIVATE -Wall -Wextra -Wpedantic)
add_dependencies(travel_plugin_roundtrip_reader travel_mrpt_plugin)

set(TRAVEL_MRPT_SAMPLE_VLP16 /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog)
set(TRAVEL_MRPT_SAMPLE_ROTSCAN /usr/share/mrpt/datasets/rot_scan_velodyne.rawlog)
set(_travel_rt_dir ${CMAKE_CURRENT_BINARY_DIR}/plugin_roundtrip)
file(MAKE_DIRECTORY ${_travel_rt_dir})
set(_travel_rt_rawlog ${_travel_rt_dir}/mrpt_samples_travel_labels.rawlog)
set(_travel_rt_reference ${_travel_rt_dir}/mrpt_samples_travel_labels.reference)

if(EXISTS ${TRAVEL_MRPT_SAMPLE_VLP16})
  add_test(NAME plugin.roundtrip_write
    COMMAND travel_plugin_roundtrip_writer
      ${PROJECT_SOURCE_DIR}/share/configs/mrpt_sample_vlp16.yaml
      ${_travel_rt_rawlog} ${_travel_rt_reference}
      ${TRAVEL_MRPT_SAMPLE_VLP16} ${TRAVEL_MRPT_SAMPLE_ROTSCAN})
  set_tests_properties(plugin.roundtrip_write PROPERTIES
    FIXTURES_SETUP travel_plugin_rawlog SKIP_RETURN_CODE 77 TIMEOUT 120)

  add_test(NAME plugin.roundtrip_read_other_process
    COMMAND travel_plugin_roundtrip_reader
      $<TARGET_FILE:travel_mrpt_plugin> ${_travel_rt_rawlog} ${_travel_rt_reference})
  set_tests_properties(plugin.roundtrip_read_other_process PROPERTIES
    FIXTURES_REQUIRED travel_plugin_rawlog TIMEOUT 120)

endif()

# MRPT's own apps load the plugin into their (uninstrumented) processes: not possible with a
# sanitizer-built plugin, so these run in plain builds only.
if(EXISTS ${TRAVEL_MRPT_SAMPLE_VLP16} AND NOT TRAVEL_SANITIZE)
  # MRPT's own rawlog-edit reads the output with the plugin (-p) and fails without it.
  find_program(TRAVEL_RAWLOG_EDIT rawlog-edit)
  add_test(NAME plugin.rawlog_edit
    COMMAND ${CMAKE_COMMAND}
      -DRAWLOG_EDIT=${TRAVEL_RAWLOG_EDIT}
      -DPLUGIN=$<TARGET_FILE:travel_mrpt_plugin>
      -DRAWLOG=${_travel_rt_rawlog}
      -DWORK_DIR=${_travel_rt_dir}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/plugin/test_rawlog_edit.cmake)
  set_tests_properties(plugin.rawlog_edit PROPERTIES
    FIXTURES_REQUIRED travel_plugin_rawlog TIMEOUT 120 SKIP_REGULAR_EXPRESSION "SKIPPED:")

  # RawLogViewer opens the output with the plugin (-l) under a virtual X server.
  find_program(TRAVEL_RAWLOG_VIEWER RawLogViewer)
  find_program(TRAVEL_XVFB_RUN xvfb-run)
  add_test(NAME plugin.rawlogviewer_xvfb
    COMMAND ${CMAKE_COMMAND}
      -DRAWLOG_VIEWER=${TRAVEL_RAWLOG_VIEWER}
      -DXVFB_RUN=${TRAVEL_XVFB_RUN}
      -DPLUGIN=$<TARGET_FILE:travel_mrpt_plugin>
      -DRAWLOG=${_travel_rt_rawlog}
      -DWORK_DIR=${_travel_rt_dir}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/plugin/test_rawlogviewer.cmake)
  set_tests_properties(plugin.rawlogviewer_xvfb PROPERTIES
    FIXTURES_REQUIRED travel_plugin_rawlog TIMEOUT 120 SKIP_REGULAR_EXPRESSION "SKIPPED:")
endif()
if(NOT EXISTS ${TRAVEL_MRPT_SAMPLE_VLP16})
  message(STATUS "MRPT sample ${TRAVEL_MRPT_SAMPLE_VLP16} not found (mrpt-common): "
                 "plugin round-trip tests not registered")
endif()

# See mrpt_plugin/CMakeLists.txt: UBSan's alignment check misreads MRPT's opengl class layout.
if(TRAVEL_SANITIZE MATCHES "undefined|alignment")
  set_source_files_properties(plugin/test_labels_observation.cpp
    PROPERTIES COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
