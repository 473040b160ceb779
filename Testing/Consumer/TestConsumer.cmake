# Builds and runs Testing/Consumer against the build tree (vtkao_DIR=<build dir>) and against
# an install tree (cmake --install into a temporary prefix).
# -DSOURCE=<consumer source> -DBUILD_TREE=<vtkao build dir> -DWORK=<scratch> -DCONFIG=<config>
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
function(consume name dir)
  execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" --build-and-test "${SOURCE}" "${WORK}/${name}"
      --build-generator "${GENERATOR}" --build-options "-Dvtkao_DIR=${dir}" "-DCMAKE_BUILD_TYPE=${CONFIG}"
      --test-command "${WORK}/${name}/vtkaoConsumer"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer against the ${name} tree (vtkao_DIR=${dir}) failed:\n${out}\n${err}")
  endif ()
  message(STATUS "ok: consumer against the ${name} tree (vtkao_DIR=${dir})")
endfunction()
consume(build "${BUILD_TREE}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_TREE}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif ()
file(GLOB config "${WORK}/prefix/lib*/cmake/vtkao/vtkaoConfig.cmake")
if (NOT config)
  message(FATAL_ERROR "no vtkaoConfig.cmake under ${WORK}/prefix")
endif ()
get_filename_component(installed "${config}" DIRECTORY)
consume(install "${installed}")
