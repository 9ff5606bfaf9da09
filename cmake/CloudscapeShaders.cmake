# cloudscape_add_shaders(<target> NAMESPACE <dir> SOURCES <glsl...> [INCLUDE_DIRS <dirs...>]
#                        [TARGET_ENV vulkan1.2|vulkan1.3])
#
# The engine's and the sample's build-time GLSL: each source is compiled by glslangValidator
# into SPIR-V words in ${CMAKE_CURRENT_BINARY_DIR}/shaders/<NAMESPACE>/<file>.spv.h
# (`const uint32_t <file>_<stage>_spv[]`), which <target> includes as
# "<NAMESPACE>/<file>.spv.h". A compile error fails the build as `ERROR: <file>:<line>: ...`;
# included headers are tracked through glslangValidator's depfile; no .spv is committed.
#
# The effect modules have their own (modules/vkfx/cmake/VkfxShaders.cmake) because they must
# build without the engine, and the engine must not reach into a module.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)

function(cloudscape_add_shaders target)
  cmake_parse_arguments(ARG "" "NAMESPACE;TARGET_ENV" "SOURCES;INCLUDE_DIRS" ${ARGN})
  if(NOT ARG_NAMESPACE)
    message(FATAL_ERROR "cloudscape_add_shaders(${target}): NAMESPACE is required")
  endif()
  if(NOT ARG_TARGET_ENV)
    set(ARG_TARGET_ENV vulkan1.3)
  endif()
  set(root ${CMAKE_CURRENT_BINARY_DIR}/shaders)
  file(MAKE_DIRECTORY ${root}/${ARG_NAMESPACE})
  list(TRANSFORM ARG_INCLUDE_DIRS PREPEND "-I" OUTPUT_VARIABLE includes)
  set(headers "")
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(path ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    string(MAKE_C_IDENTIFIER "${name}_spv" symbol)
    # glslangValidator writes a bare initializer list; the header wraps it once, at configure
    # time, with what makes it self-contained.
    set(words ${root}/${ARG_NAMESPACE}/${name}.spv.inc)
    file(CONFIGURE OUTPUT ${root}/${ARG_NAMESPACE}/${name}.spv.h CONTENT
         "// Generated from ${src} by cloudscape_add_shaders.\n#pragma once\n#include <cstdint>\n#include \"${name}.spv.inc\"\n")
    add_custom_command(
      OUTPUT ${words}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env ${ARG_TARGET_ENV} ${includes}
              --depfile ${words}.d --vn ${symbol} -o ${words} ${path}
      DEPENDS ${path}
      DEPFILE ${words}.d
      COMMENT "GLSL ${ARG_NAMESPACE}/${name}"
      VERBATIM)
    list(APPEND headers ${words})
  endforeach()
  add_custom_target(${target}_shaders DEPENDS ${headers})
  add_dependencies(${target} ${target}_shaders)
  target_include_directories(${target} PRIVATE ${root})
endfunction()
