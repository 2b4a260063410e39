# lrsvo_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Builds the library lrsvo_<name>, aliased and exported as lrsvo::<name>.
# Headers live beside the sources and are included as "<name>/<file>.h".
function(lrsvo_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  set(target lrsvo_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(lrsvo::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME lrsvo_${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/lrsvo>)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  lrsvo_set_warnings(${target})
  install(TARGETS ${target} EXPORT lrsvoTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  file(GLOB headers "${CMAKE_CURRENT_SOURCE_DIR}/*.h")
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lrsvo/${name})
endfunction()

function(lrsvo_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wno-deprecated-copy)
  if(LRSVO_SANITIZE)
    # UBSan's null, alignment and object-size checks double the compile time of Eigen-heavy files;
    # ASan already reports what they would (null dereferences as SEGV with a stack, out-of-bounds
    # accesses), so they are left out. Every other UBSan check stays on.
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize=null,alignment,object-size -fno-omit-frame-pointer)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()
