# The traversability map layer (CTraversabilityMap: 2-D traversability grid + OctoMap) and its
# exports (included from CMakeLists.txt, where travel_mrpt exists). The plugin module registers
# the map class so that CMultiMetricMap creates it from an .ini (traversabilityMap_count=1).
find_package(mrpt-maps REQUIRED)
find_package(mrpt-opengl REQUIRED)
find_package(mrpt-io REQUIRED)
find_package(octomap REQUIRED)

target_sources(travel_mrpt PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/src/TraversabilityMapOptions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/CTraversabilityMap.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/MapExport.cpp)
# CTraversabilityMap.hpp derives from CMetricMap (mrpt-maps); tests and apps read the OctoMap.
target_link_libraries(travel_mrpt PUBLIC travel::traversability mrpt::maps mrpt::opengl mrpt::io octomap octomath)
target_include_directories(travel_mrpt PUBLIC ${OCTOMAP_INCLUDE_DIRS})

# See labels.cmake: UBSan's alignment check misreads MRPT's opengl class layout.
if(TRAVEL_SANITIZE MATCHES "undefined|alignment")
  set_source_files_properties(
    ${CMAKE_CURRENT_LIST_DIR}/src/CTraversabilityMap.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/MapExport.cpp
    PROPERTIES COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
