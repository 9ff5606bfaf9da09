#version 460
// Depth-aware upsample (compute) from the trace resolution to the output: bilinear over the
// four nearest trace pixels, except that a trace pixel whose nearest cloud starts behind this
// output pixel's geometry contributes "no cloud" (no halos of cloud over mountain edges).
// Inputs: 0 CloudUniforms; 1 reconstructed samples (trace res, packed: cloud_temporal.h);
// 2 host depth. Outputs: 3 RGBA16F radiance + transmittance, 4 RG32F depths (output res).
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = 8, local_size_y = 8) in;
#include "frame_uniforms.glsl"
layout(binding = 1, rgba32ui) uniform readonly uimage2D traceSamples;
layout(binding = 2) uniform sampler2D hostDepth;
layout(binding = 3, rgba16f) uniform writeonly image2D outRadiance;
layout(binding = 4, rg32f) uniform writeonly image2D outDepth;

#include "cloud_march.h"

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  const uvec2 full = u.extent.zw;
  if (any(greaterThanEqual(pixel, full))) return;
  const float scene = sceneDistanceFromDepth(texelFetch(hostDepth, ivec2(pixel), 0).r,
                                             vec2(pixel) + 0.5f, vec2(full), u);
  const vec2 p = (vec2(pixel) + 0.5f) * vec2(u.extent.xy) / vec2(full) - 0.5f;
  const ivec2 i = ivec2(floor(p));
  const vec2 f = p - floor(p);
  vec4 radiance = vec4(0.0f);
  DepthBlend blend = depthBlendStart();
  for (int tap = 0; tap < 4; ++tap) {
    const ivec2 offset = ivec2(tap & 1, tap >> 1);
    const ivec2 q = clamp(i + offset, ivec2(0), ivec2(u.extent.xy) - 1);
    const float w = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
    const uvec4 packed = imageLoad(traceSamples, q);
    vec4 r = unpackCloudRadiance(packed);
    vec2 d = unpackCloudDepth(packed);
    if (d.x > 0.0f && scene < d.x) {
      r = vec4(0.0f, 0.0f, 0.0f, 1.0f);  // all of that cloud is behind this pixel's geometry
      d = vec2(0.0f);
    }
    radiance += r * w;
    depthBlendAdd(blend, w, r.a, d);
  }
  imageStore(outRadiance, ivec2(pixel), radiance);
  imageStore(outDepth, ivec2(pixel), vec4(depthBlendResult(blend), 0.0f, 0.0f));
}
