#version 460
// Test reduction: counts output texels that are NaN, infinite or negative (radiance and
// transmittance outside [0, 1] count too), per channel kind, with atomics.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform readonly image2D radiance;
layout(binding = 1, rg32f) uniform readonly image2D depth;
layout(binding = 2, std430) buffer Counters {
  uint nonFinite;
  uint negative;
  uint transmittanceOutOfRange;
  uint pixels;
};
layout(push_constant) uniform Constants { uvec2 extent; };

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, extent))) return;
  const vec4 r = imageLoad(radiance, ivec2(p));
  const vec2 d = imageLoad(depth, ivec2(p)).xy;
  const bool finite = !any(isnan(r)) && !any(isinf(r)) && !any(isnan(d)) && !any(isinf(d));
  if (!finite) atomicAdd(nonFinite, 1u);
  if (any(lessThan(r, vec4(0.0f))) || any(lessThan(d, vec2(0.0f)))) atomicAdd(negative, 1u);
  if (r.a > 1.0f) atomicAdd(transmittanceOutOfRange, 1u);
  atomicAdd(pixels, 1u);
}
