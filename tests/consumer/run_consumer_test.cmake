# Install the build tree into WORK_DIR/prefix, then build and run the consumer against it (its
# programs of travel::travel and travel::config; with WITH_MRPT=ON, also one program per MRPT
# library: travel::mrpt_obs, _maps, _nav, and the consumer's rawlog regression test: a golden
# rawlog written by the installed travel-rawlog, compared by the installed
# travel_add_rawlog_regression, run through ctest), then the consumer of travel::travel alone as
# on a machine without yaml-cpp. Also: the installed apps use the prefix's share/travel, and no
# installed binary holds a source path.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
# The installed apps find the share directory of the prefix they are installed in (here not the
# configured CMAKE_INSTALL_PREFIX): a preset and a world that only this prefix has.
if(WITH_MRPT)
  set(share ${WORK_DIR}/prefix/share/travel)
  configure_file(${share}/presets/vlp16.yaml ${share}/presets/installed_only.yaml COPYONLY)
  configure_file(${share}/worlds/flat_obstacles.world ${share}/worlds/installed_only.world
                 COPYONLY)
  file(GLOB apps ${WORK_DIR}/prefix/bin/travel-*)
  foreach(app IN LISTS apps)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=TRAVEL_SHARE_DIR
                            ${app} -p installed_only --print-config
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
    if(rc)
      message(FATAL_ERROR "${app} -p installed_only: ${rc} ${err}")
    endif()
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=TRAVEL_SHARE_DIR
                          ${WORK_DIR}/prefix/bin/travel-nav-sim -i installed_only.world -t 0.5
                          --no-navlog -q -o ${WORK_DIR}/nav
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "travel-nav-sim -i installed_only.world: ${rc} ${err}")
  endif()
endif()
# No path of the source tree in the installed binaries' constant data (__FILE__ in messages),
# but its share/, the lookup of runs from the build tree. Debug information is not looked at.
find_program(READELF readelf)
if(READELF AND TRAVEL_SOURCE_DIR)
  file(GLOB_RECURSE binaries ${WORK_DIR}/prefix/bin/* ${WORK_DIR}/prefix/lib/*.so)
  foreach(binary IN LISTS binaries)
    execute_process(COMMAND ${READELF} -p .rodata ${binary} OUTPUT_VARIABLE rodata ERROR_QUIET)
    string(REPLACE "${TRAVEL_SOURCE_DIR}/share" "" rodata "${rodata}")
    string(FIND "${rodata}" "${TRAVEL_SOURCE_DIR}/" pos)
    if(NOT pos EQUAL -1)
      string(SUBSTRING "${rodata}" ${pos} 200 where)
      message(FATAL_ERROR "${binary} holds a source path: ${where}")
    endif()
  endforeach()
endif()
# A sanitized libtravel.a needs the sanitizer runtime in the consumer's link too.
set(flags "")
if(SANITIZE)
  set(flags "-fsanitize=${SANITIZE}")
endif()
set(regression "")
set(sample /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog)
if(WITH_MRPT AND EXISTS ${sample})
  execute_process(COMMAND ${WORK_DIR}/prefix/bin/travel-rawlog -i ${sample}
                          -o ${WORK_DIR}/golden.rawlog -p vlp16 -q RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "the installed travel-rawlog failed: ${rc}")
  endif()
  set(regression -DRAWLOG=${sample} -DGOLDEN=${WORK_DIR}/golden.rawlog)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
                        ${regression}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                        "-DCMAKE_CXX_FLAGS=${flags}" "-DCMAKE_EXE_LINKER_FLAGS=${flags}"
                        -DWITH_MRPT=${WITH_MRPT}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
set(programs consumer consumer_config)
if(WITH_MRPT)
  list(APPEND programs consumer_mrpt_obs consumer_mrpt_maps consumer_mrpt_nav)
endif()
foreach(program IN LISTS programs)
  execute_process(COMMAND ${WORK_DIR}/build/${program} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${program} failed: ${rc}")
  endif()
endforeach()
# The core alone needs Eigen alone: the same consumer without the config component, configured
# as on a machine without yaml-cpp, finds the package, builds and runs.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build_core -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                        "-DCMAKE_CXX_FLAGS=${flags}" "-DCMAKE_EXE_LINKER_FLAGS=${flags}"
                        -DWITH_CONFIG=OFF -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer of travel::travel alone without yaml-cpp failed: "
                      "${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build_core RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer of travel::travel alone failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build_core/consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "consumer (travel::travel alone) failed: ${rc}")
endif()
if(regression)
  execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --output-on-failure --no-tests=error -R consumer.rawlog_regression
                  WORKING_DIRECTORY ${WORK_DIR}/build RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "the consumer's rawlog regression test failed: ${rc}")
  endif()
  if(NOT EXISTS ${WORK_DIR}/build/regression/report.md)
    message(FATAL_ERROR "the consumer's rawlog regression wrote no report")
  endif()
endif()
