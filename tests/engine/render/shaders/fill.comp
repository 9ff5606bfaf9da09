#version 460
// Test pass: fills an RGBA8 storage image with (x, y, 10, 255) / 255.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { uvec2 extent; };

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, extent))) return;
  imageStore(target, ivec2(p), vec4(vec3(p, 10.0f) / 255.0f, 1.0f));
}
