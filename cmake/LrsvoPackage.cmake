# The CMake package: after `cmake --install`, another project can
#   find_package(lrsvo REQUIRED)
#   target_link_libraries(app PRIVATE lrsvo::edges)
# The libraries join the export set lrsvoTargets in lrsvo_add_library (LrsvoTargets.cmake).
include(CMakePackageConfigHelpers)

set(LRSVO_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/lrsvo")

install(EXPORT lrsvoTargets
  NAMESPACE lrsvo::
  FILE lrsvoTargets.cmake
  DESTINATION "${LRSVO_INSTALL_CMAKEDIR}")

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
    "${CMAKE_CURRENT_LIST_DIR}/FindCHOLMOD.cmake"
  DESTINATION "${LRSVO_INSTALL_CMAKEDIR}")
