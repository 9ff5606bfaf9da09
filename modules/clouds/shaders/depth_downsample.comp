#version 460
// Conservative scene distance at the trace resolution: each trace pixel keeps the farthest
// host geometry among the output pixels it covers (the sky is "infinitely far"), so clouds are
// marched wherever any covered pixel could see them; the upsample pass then hides them again,
// per output pixel, behind nearer geometry. Without a host depth every distance is infinite.
// Inputs: binding 0 CloudUniforms, 1 host depth (texelFetch). Output: 2 R32F distance (m).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "frame_uniforms.glsl"
layout(binding = kSceneDistanceHostDepth) uniform sampler2D hostDepth;
layout(binding = kSceneDistanceOut, r32f) uniform writeonly image2D outDistance;

#include "cloud_march.h"

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.traceExtent))) return;
  const uvec2 full = u.outputExtent;
  // The output pixels whose centres fall in this trace pixel.
  const uvec2 first = uvec2(floor(vec2(pixel) * vec2(full) / vec2(u.traceExtent)));
  const uvec2 last =
      min(uvec2(ceil(vec2(pixel + 1u) * vec2(full) / vec2(u.traceExtent))), full) - 1u;
  // The farthest depth value first, converted once: within a footprint of a few pixels the
  // distance for a depth changes with the ray's angle by well under 3%, which the margin covers.
  const bool reversed = (u.flags & kFlagReversedZ) != 0u;
  float farthestDepth = reversed ? 1.0f : 0.0f;
  for (uint y = first.y; y <= last.y; ++y) {
    for (uint x = first.x; x <= last.x; ++x) {
      const float depth = texelFetch(hostDepth, ivec2(x, y), 0).r;
      farthestDepth = reversed ? min(farthestDepth, depth) : max(farthestDepth, depth);
    }
  }
  const vec2 centre = 0.5f * (vec2(first) + vec2(last + 1u));
  const float margin = all(equal(first, last)) ? 1.0f : 1.03f;
  const float farthest = sceneDistanceFromDepth(farthestDepth, centre, vec2(full), u) * margin;
  imageStore(outDistance, ivec2(pixel), vec4(farthest, 0.0f, 0.0f, 0.0f));
}
