# Reactive navigation on TRAVEL obstacles: the obstacle sources for CRobot2NavInterface
# (included from CMakeLists.txt, where travel_mrpt exists).
find_package(mrpt-nav REQUIRED)
find_package(mrpt-kinematics REQUIRED)
target_sources(travel_mrpt PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/src/ObstacleSource.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/ObstacleSources.cpp)
# ObstacleSource.hpp includes <mrpt/core/Clock.h>; latest() fills a CSimplePointsMap; the
# obstacle rules are travel::TravelObstacles.
target_link_libraries(travel_mrpt PUBLIC travel::traversability mrpt::maps mrpt::nav mrpt::kinematics)
