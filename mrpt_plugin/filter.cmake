# The TRAVEL observation filter (TravelFilter, its options and the motion estimator).
find_package(mrpt-config REQUIRED)
find_package(mrpt-system REQUIRED)
find_package(mrpt-containers REQUIRED)
target_sources(travel_mrpt PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/src/TravelFilterOptions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/MotionEstimator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/TravelFilter.cpp)
target_link_libraries(travel_mrpt PUBLIC mrpt::obs mrpt::config mrpt::system mrpt::containers)
