# The CMake package: after `cmake --install`, another project can
#   find_package(lrsvo REQUIRED [COMPONENTS graph ...])
#   target_link_libraries(app PRIVATE lrsvo::edges)
# Each library is exported as a component by lrsvo_add_library (LrsvoTargets.cmake), which also
# records the components and packages it needs; lrsvoComponents.cmake hands that to the config.
include(CMakePackageConfigHelpers)

set(LRSVO_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/lrsvo")

get_property(components GLOBAL PROPERTY LRSVO_COMPONENTS)
get_property(component_descriptions GLOBAL PROPERTY LRSVO_COMPONENT_DESCRIPTIONS)
file(WRITE "${PROJECT_BINARY_DIR}/lrsvoComponents.cmake"
  "# The components of lrsvo in build order, and what each needs (generated).\n"
  "set(_lrsvo_all_components ${components})\n" "${component_descriptions}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/lrsvoConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/lrsvoConfig.cmake"
  INSTALL_DESTINATION "${LRSVO_INSTALL_CMAKEDIR}")

# 0.x releases may break the API between minor versions.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/lrsvoConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)

install(FILES
    "${PROJECT_BINARY_DIR}/lrsvoConfig.cmake"
    "${PROJECT_BINARY_DIR}/lrsvoConfigVersion.cmake"
    "${PROJECT_BINARY_DIR}/lrsvoComponents.cmake"
    "${CMAKE_CURRENT_LIST_DIR}/FindCHOLMOD.cmake"
  DESTINATION "${LRSVO_INSTALL_CMAKEDIR}")
