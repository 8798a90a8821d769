# travel-nav-sim: closed-loop reactive navigation on TRAVEL obstacles (included from
# apps/CMakeLists.txt). The simulation itself is a static library so that the tests run the
# same loop.
find_package(mrpt-nav REQUIRED)
find_package(mrpt-kinematics REQUIRED)

add_library(travel_nav_sim_lib STATIC
  ${CMAKE_CURRENT_LIST_DIR}/nav/World.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nav/Collision.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nav/Simulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nav/TopView.cpp)
target_include_directories(travel_nav_sim_lib PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(travel_nav_sim_lib
  PUBLIC travel::mrpt travel::sim mrpt::nav mrpt::kinematics mrpt::img mrpt::config travel_app_support
  PRIVATE travel::io)
target_compile_options(travel_nav_sim_lib PRIVATE ${TRAVEL_APP_WARNINGS})

add_executable(travel-nav-sim ${CMAKE_CURRENT_LIST_DIR}/travel_nav_sim.cpp)
target_link_libraries(travel-nav-sim PRIVATE travel_nav_sim_lib travel::io mrpt::tclap)
target_compile_options(travel-nav-sim PRIVATE ${TRAVEL_APP_WARNINGS})
install(TARGETS travel-nav-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
