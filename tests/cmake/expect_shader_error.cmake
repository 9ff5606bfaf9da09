# Configures and builds the broken-shader project; passes only when the build fails and the
# output names broken.comp:3.
file(REMOVE_RECURSE ${BINARY_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} -G Ninja
                        -DSHADER_CMAKE=${SHADER_CMAKE} -DSHADER_FUNCTION=${SHADER_FUNCTION}
                RESULT_VARIABLE configure_result OUTPUT_QUIET)
if(NOT configure_result EQUAL 0)
  message(FATAL_ERROR "configuring the check project failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR}
                RESULT_VARIABLE build_result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(build_result EQUAL 0)
  message(FATAL_ERROR "the build succeeded although the shader is broken")
endif()
if(NOT "${out}${err}" MATCHES "broken\\.comp:3")
  message(FATAL_ERROR "the build failed but did not name broken.comp:3:\n${out}${err}")
endif()
message(STATUS "shader error reported as expected")
