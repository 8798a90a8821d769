# Reactive navigation on TRAVEL obstacles (included from tests/CMakeLists.txt inside
# if(TRAVEL_BUILD_MRPT)): obstacle sources on single scans, then closed-loop runs.
if(TARGET travel_nav_sim_lib)
  travel_mrpt_test(test_nav_sources test_nav_sources.cpp)
  target_link_libraries(test_nav_sources PRIVATE travel_nav_sim_lib)
  travel_mrpt_test(test_map_source test_map_source.cpp)
  target_link_libraries(test_map_source PRIVATE travel_nav_sim_lib)
  if(TRAVEL_BUILD_FIGURE_TESTS)
    travel_mrpt_test(test_nav_closed_loop test_nav_closed_loop.cpp)
    target_link_libraries(test_nav_closed_loop PRIVATE travel_nav_sim_lib mrpt::io mrpt::serialization)
    if(TRAVEL_SANITIZE)
      target_compile_definitions(test_nav_closed_loop PRIVATE TRAVEL_SANITIZED)
    endif()
  endif()

  add_test(NAME apps.travel_nav_sim_cli
    COMMAND ${CMAKE_COMMAND}
      -DTRAVEL_NAV_SIM=$<TARGET_FILE:travel-nav-sim>
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_nav_sim
      -DSHARE_DIR=${PROJECT_SOURCE_DIR}/share
      -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_travel_nav_sim.cmake)
endif()
