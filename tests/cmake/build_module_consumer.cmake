# Configures, builds and runs the outside consumer of an effect module (module_consumer/), one
# way: CONSUME=subdirectory, or CONSUME=package after configuring the module on its own and
# installing it into a prefix. The consumer must render frames and write its picture.
# -DMODULE=clouds|atmosphere -DMODULE_DIR=<its folder> -DSOURCE_DIR -DBINARY_DIR -DCONSUME.
file(REMOVE_RECURSE ${BINARY_DIR})
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n${out}${err}")
  endif()
endfunction()

string(TOUPPER ${MODULE} prefix_name)
set(consumer_args -DMODULE=${MODULE} -DMODULE_DIR=${MODULE_DIR} -DMODULE_CONSUME=${CONSUME})
if(CONSUME STREQUAL "package")
  set(prefix ${BINARY_DIR}/prefix)
  run("configuring the module on its own"
      ${CMAKE_COMMAND} -S ${MODULE_DIR} -B ${BINARY_DIR}/module -G Ninja
      -DCMAKE_BUILD_TYPE=Release -D${prefix_name}_BUILD_EXAMPLES=OFF)
  run("building the module" ${CMAKE_COMMAND} --build ${BINARY_DIR}/module)
  run("installing the module" ${CMAKE_COMMAND} --install ${BINARY_DIR}/module --prefix ${prefix})
  foreach(file include/${MODULE}/${MODULE}.h lib/cmake/${MODULE}/${MODULE}Config.cmake
               lib/cmake/${MODULE}/${MODULE}ConfigVersion.cmake
               include/fxcontracts/cloud_shadow.h lib/cmake/fxcontracts/fxcontractsConfig.cmake)
    if(NOT EXISTS ${prefix}/${file})
      message(FATAL_ERROR "the install is missing ${file}")
    endif()
  endforeach()
  list(APPEND consumer_args -DCMAKE_PREFIX_PATH=${prefix})
endif()
run("configuring the consumer"
    ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR}/consumer -G Ninja
    -DCMAKE_BUILD_TYPE=Release ${consumer_args})
run("building the consumer" ${CMAKE_COMMAND} --build ${BINARY_DIR}/consumer)
run("running the consumer" ${BINARY_DIR}/consumer/consumer --width 64 --height 36 --frames 2
    --output ${BINARY_DIR}/consumer.ppm)
if(NOT EXISTS ${BINARY_DIR}/consumer.ppm)
  message(FATAL_ERROR "the consumer wrote no picture")
endif()
message(STATUS "the ${MODULE} module works from an outside project (${CONSUME})")
