# travel_library(<target> EXPORT_NAME <name> EXPORT <export-set> INCLUDE_DIR <dir>
#                SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# One library of the project: <target> with the alias travel::<name>, headers in <dir> (used from
# the build tree, installed with the library), warnings on, installed into <export-set>.
function(travel_library target)
  cmake_parse_arguments(L "" "EXPORT_NAME;EXPORT;INCLUDE_DIR" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS"
                        ${ARGN})
  add_library(${target} ${L_SOURCES})
  add_library(travel::${L_EXPORT_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${L_EXPORT_NAME})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${L_INCLUDE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${L_PUBLIC_DEPS} PRIVATE ${L_PRIVATE_DEPS})
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  install(TARGETS ${target} EXPORT ${L_EXPORT}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${L_INCLUDE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
