# travel-map: rawlog or KITTI sequence in, traversability map exports out (included from
# apps/CMakeLists.txt).
find_package(octomap REQUIRED)
add_executable(travel-map travel_map.cpp MapSources.cpp MemoryLimit.cpp)
target_link_libraries(travel-map PRIVATE
  travel::mrpt travel::eval mrpt::tclap mrpt::maps mrpt::obs mrpt::io mrpt::serialization octomap octomath
  travel_app_support)
target_compile_options(travel-map PRIVATE ${TRAVEL_APP_WARNINGS})
install(TARGETS travel-map RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
