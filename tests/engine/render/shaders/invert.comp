#version 460
// Test pass: samples the source (texelFetch) and writes 1 - rgb into the destination.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { uvec2 extent; };

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, extent))) return;
  const vec4 value = texelFetch(source, ivec2(p), 0);
  imageStore(target, ivec2(p), vec4(1.0f - value.rgb, 1.0f));
}
