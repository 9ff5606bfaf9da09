# cloudscape_add_shaders(<target> NAMESPACE <dir> SOURCES <glsl...> [INCLUDE_DIRS <dirs...>])
#
# Compiles each GLSL source with glslangValidator at build time into a C header holding the
# SPIR-V words (`static const uint32_t <stem>_<stage>_spv[]`) under
# ${CMAKE_CURRENT_BINARY_DIR}/shaders/<NAMESPACE>/<file>.spv.h, and makes <target> depend on
# them and see them as `#include "<NAMESPACE>/<file>.spv.h"`. A compile error fails the build
# and glslangValidator prints it as `ERROR: <file>:<line>: <message>`. No .spv is committed.
# Included headers are tracked through glslangValidator's depfile.
function(cloudscape_add_shaders target)
  cmake_parse_arguments(ARG "" "NAMESPACE" "SOURCES;INCLUDE_DIRS" ${ARGN})
  if(NOT ARG_NAMESPACE)
    message(FATAL_ERROR "cloudscape_add_shaders(${target}): NAMESPACE is required")
  endif()
  set(out_root ${CMAKE_CURRENT_BINARY_DIR}/shaders)
  set(out_dir ${out_root}/${ARG_NAMESPACE})
  file(MAKE_DIRECTORY ${out_dir})
  set(include_flags "")
  foreach(dir IN LISTS ARG_INCLUDE_DIRS)
    list(APPEND include_flags "-I${dir}")
  endforeach()
  set(outputs "")
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(src_abs ${src} ABSOLUTE)
    get_filename_component(src_name ${src} NAME)
    string(MAKE_C_IDENTIFIER "${src_name}_spv" symbol)
    set(out ${out_dir}/${src_name}.spv.h)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.3 ${include_flags}
              --depfile ${out}.d --vn ${symbol} -o ${out} ${src_abs}
      DEPENDS ${src_abs}
      DEPFILE ${out}.d
      COMMENT "GLSL ${ARG_NAMESPACE}/${src_name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target}_shaders DEPENDS ${outputs})
  add_dependencies(${target} ${target}_shaders)
  target_include_directories(${target} PRIVATE ${out_root})
endfunction()
