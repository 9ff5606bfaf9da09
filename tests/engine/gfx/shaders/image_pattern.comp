#version 460
// Test probe: writes a deterministic RGBA8 pattern into a storage image.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { uvec2 extent; };

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, extent))) return;
  imageStore(target, ivec2(p), vec4(float(p.x) / 255.0f, float(p.y) / 255.0f,
                                    float((p.x ^ p.y) & 255u) / 255.0f, 1.0f));
}
