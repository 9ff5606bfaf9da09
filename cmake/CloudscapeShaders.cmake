# cloudscape_add_shaders(...): build-time GLSL -> embedded SPIR-V. The implementation lives
# with the clouds module (modules/clouds/cmake/GlslEmbed.cmake) so the module is self-contained.
include(${PROJECT_SOURCE_DIR}/modules/clouds/cmake/GlslEmbed.cmake)

function(cloudscape_add_shaders target)
  glsl_embed_shaders(${target} ${ARGN})
endfunction()
