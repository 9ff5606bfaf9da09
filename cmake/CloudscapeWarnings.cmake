# cloudscape_set_warnings(<target>): the project's warning set, applied to first-party code only.
# Third-party headers come from /usr/include and are treated as system headers by the compiler.
function(cloudscape_set_warnings target)
  # -Wno-missing-field-initializers: Vulkan structs are initialised as
  # `VkFooInfo info{VK_STRUCTURE_TYPE_FOO_INFO};`, which value-initialises every other member by
  # the language rules; spelling out a dozen zero members per struct would hide the ones set.
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wconversion -Wsign-conversion
                                           -Wnon-virtual-dtor -Wpedantic
                                           -Wno-missing-field-initializers)
  if(CLOUDSCAPE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
