# The consumer_find_package test, run as `cmake -D... -P check_find_package.cmake`:
# installs lrsvo from its build tree into a scratch prefix, then configures, builds
# and runs the consumer projects against that prefix, as a user of the package would:
# one links every component and compiles every installed header (so a public header
# that includes an internal one fails), one finds the component graph alone where no
# other component's packages can be found.
# Also checks that nothing installed holds a path into the source or build tree.
# Needs LRSVO_SOURCE_DIR, LRSVO_BUILD_DIR (a complete build), CONFIG, WORK_DIR,
# CONSUMER_SOURCE_DIR, GENERATOR and CXX_COMPILER.
foreach(var LRSVO_SOURCE_DIR LRSVO_BUILD_DIR CONFIG WORK_DIR CONSUMER_SOURCE_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "consumer test: ${var} is not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/build")
# Start from nothing each run, so that no file a previous build installed (or a
# cached path) can hide a packaging error.
set(graph_consumer_build "${WORK_DIR}/build_graph_only")
set(header_check_dir "${WORK_DIR}/header_check")
file(REMOVE_RECURSE "${prefix}" "${consumer_build}" "${graph_consumer_build}" "${header_check_dir}")
set(config_args "")
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "consumer test: ${step} failed (${result})")
  endif()
endfunction()

run("installing lrsvo into ${prefix} (is the build in ${LRSVO_BUILD_DIR} complete?)"
  "${CMAKE_COMMAND}" --install "${LRSVO_BUILD_DIR}" ${config_args} --prefix "${prefix}")
# An installed program or library must not depend on where it was built: no
# path into the source tree (../shared beside it included) or the build tree.
file(GLOB_RECURSE installed_binaries "${prefix}/bin/*" "${prefix}/lib/*.so*" "${prefix}/lib/*.a")
foreach(binary IN LISTS installed_binaries)
  file(STRINGS "${binary}" texts LENGTH_MINIMUM 8)
  string(JOIN "\n" text ${texts})
  foreach(tree "${LRSVO_SOURCE_DIR}" "${LRSVO_BUILD_DIR}")
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "consumer test: ${binary} holds the path ${tree}")
    endif()
  endforeach()
endforeach()

# Only public headers are installed, and they include nothing that is not: one source per
# library includes all of that library's installed headers.
file(GLOB libraries RELATIVE "${prefix}/include/lrsvo" "${prefix}/include/lrsvo/*")
foreach(library IN LISTS libraries)
  file(GLOB_RECURSE headers RELATIVE "${prefix}/include" "${prefix}/include/lrsvo/${library}/*.h")
  set(text "")
  foreach(header IN LISTS headers)
    string(APPEND text "#include <${header}>\n")
  endforeach()
  file(WRITE "${header_check_dir}/${library}_headers.cpp" "${text}")
endforeach()

run("configuring the consumer against ${prefix}"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}" -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${CONFIG}" "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DLRSVO_HEADER_CHECK_DIR=${header_check_dir}" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)

# The package must come from the scratch prefix, not from another installed copy.
file(STRINGS "${consumer_build}/CMakeCache.txt" found_dir REGEX "^lrsvo_DIR:")
string(REGEX REPLACE "^lrsvo_DIR:[A-Z]*=" "" found_dir "${found_dir}")
cmake_path(IS_PREFIX prefix "${found_dir}" NORMALIZE from_prefix)
if(NOT from_prefix)
  message(FATAL_ERROR "consumer test: lrsvo was found in '${found_dir}', not under '${prefix}'")
endif()

run("building the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}" ${config_args})
run("running the consumer" "${consumer_build}/lrsvo_consumer")

# The graph alone: configuring fails if the component looks for a package it does not need.
run("configuring the graph-only consumer against ${prefix}"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}/graph_only" -B "${graph_consumer_build}" -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${CONFIG}" "-DCMAKE_PREFIX_PATH=${prefix}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_DISABLE_FIND_PACKAGE_OpenCV=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_NLopt=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON)
run("building the graph-only consumer" "${CMAKE_COMMAND}" --build "${graph_consumer_build}" ${config_args})
run("running the graph-only consumer" "${graph_consumer_build}/lrsvo_graph_consumer")
