# The labelled observation CObservationTravelLabels, class registration, and the MRPT plugin
# module libtravel_mrpt_plugin.so (included from CMakeLists.txt, where travel_mrpt exists).
find_package(mrpt-opengl REQUIRED)
find_package(mrpt-serialization REQUIRED)
find_package(mrpt-rtti REQUIRED)

target_sources(travel_mrpt PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/src/CObservationTravelLabels.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/Registration.cpp)
# CObservationTravelLabels.hpp includes CObservation.h and Visualizable.h: users need them.
target_link_libraries(travel_mrpt PUBLIC mrpt::obs mrpt::opengl mrpt::serialization mrpt::rtti)

# The plugin: a MODULE (dlopen only) holding travel_mrpt and libtravel.
add_library(travel_mrpt_plugin MODULE ${CMAKE_CURRENT_LIST_DIR}/src/Plugin.cpp)
target_link_libraries(travel_mrpt_plugin PRIVATE travel_mrpt)
target_compile_options(travel_mrpt_plugin PRIVATE -Wall -Wextra -Wpedantic)
# Plugin.cpp -> registerClasses() -> the class's RTTI entry pulls the class in from the static
# library. --no-undefined: a missing symbol fails the link here, not later at dlopen time.
target_link_options(travel_mrpt_plugin PRIVATE -Wl,--no-undefined)
install(TARGETS travel_mrpt_plugin LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})

# UBSan false positive in MRPT's class hierarchy: mrpt::opengl classes have a 32-byte aligned
# virtual base (CRenderizable), so alignof(CRenderizableShaderWireFrame) is 32, but as a base
# subobject of CBox it legitimately sits at offset 248 (the Itanium ABI places non-virtual bases
# by their non-virtual alignment). -fsanitize=alignment then flags every call on it.
if(TRAVEL_SANITIZE MATCHES "undefined|alignment")
  set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/src/CObservationTravelLabels.cpp
    PROPERTIES COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
