# lrsvo_add_library(<name> SOURCES ... PUBLIC_HEADERS ...
#                   [PUBLIC_DEPS ...] [PRIVATE_DEPS ...]
#                   [PACKAGES "<find_package args>" ...] [PRIVATE_PACKAGES "<find_package args>" ...])
# Builds the library lrsvo_<name>, aliased and exported as lrsvo::<name>, the package component <name>.
#
# Headers are included as "lrsvo/<folder>/<file>.h" in the build tree and in an installation alike:
# the build tree's include/lrsvo is a link to the source tree. Only PUBLIC_HEADERS (paths relative to
# the library's folder) are installed, under include/lrsvo/<folder>/; the rest stay internal.
# PACKAGES are the find_package arguments of what PUBLIC_DEPS and the public headers need; a consumer's
# find_package(lrsvo COMPONENTS <name>) looks for them and for nothing else. PRIVATE_PACKAGES are
# looked for only when the libraries are static (their link needs them then).

set(LRSVO_INCLUDE_ROOT "${PROJECT_BINARY_DIR}/include")
file(MAKE_DIRECTORY "${LRSVO_INCLUDE_ROOT}")
if(NOT EXISTS "${LRSVO_INCLUDE_ROOT}/lrsvo")
  file(CREATE_LINK "${PROJECT_SOURCE_DIR}" "${LRSVO_INCLUDE_ROOT}/lrsvo" SYMBOLIC)
endif()

function(lrsvo_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_HEADERS;PUBLIC_DEPS;PRIVATE_DEPS;PACKAGES;PRIVATE_PACKAGES"
                        ${ARGN})
  set(target lrsvo_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(lrsvo::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME lrsvo_${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${LRSVO_INCLUDE_ROOT}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  lrsvo_set_warnings(${target})

  install(TARGETS ${target} EXPORT lrsvo_${name}Targets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT lrsvo_${name}Targets NAMESPACE lrsvo:: FILE lrsvo_${name}Targets.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lrsvo)
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  foreach(header IN LISTS ARG_PUBLIC_HEADERS)
    if(NOT EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${header}")
      message(FATAL_ERROR "lrsvo_add_library(${name}): public header ${header} does not exist")
    endif()
    get_filename_component(subfolder "${header}" DIRECTORY)
    install(FILES "${header}" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/lrsvo/${folder}/${subfolder}")
  endforeach()

  # What the package configuration needs to know of this component (LrsvoPackage.cmake).
  set(components "")
  foreach(dep IN LISTS ARG_PUBLIC_DEPS ARG_PRIVATE_DEPS)
    if(dep MATCHES "^lrsvo::(.+)$")
      list(APPEND components ${CMAKE_MATCH_1})
    endif()
  endforeach()
  set(packages ${ARG_PACKAGES})
  if(NOT BUILD_SHARED_LIBS)
    list(APPEND packages ${ARG_PRIVATE_PACKAGES})
  endif()
  set(description "set(_lrsvo_${name}_components ${components})\n")
  string(APPEND description "set(_lrsvo_${name}_packages")
  foreach(package IN LISTS packages)
    string(APPEND description " \"${package}\"")
  endforeach()
  string(APPEND description ")\n")
  set_property(GLOBAL APPEND PROPERTY LRSVO_COMPONENTS ${name})
  set_property(GLOBAL APPEND_STRING PROPERTY LRSVO_COMPONENT_DESCRIPTIONS "${description}")
endfunction()

function(lrsvo_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wno-deprecated-copy)
  if(LRSVO_SANITIZE)
    # UBSan's null, alignment and object-size checks add half again to the compile time of Eigen-heavy
    # files with clang (they double g++'s); ASan already reports what they would (null dereferences as
    # SEGV with a stack, out-of-bounds accesses), so they are left out. Every other UBSan check stays on.
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize=null,alignment,object-size -fno-omit-frame-pointer)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()
