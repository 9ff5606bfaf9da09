#version 460
// The near field's temporal resolve (compute, at the near field's resolution, half the trace's;
// Settings::nearFieldMetres). Every pixel marched the near part of its ray this frame
// (cloud_march.comp's near field pass), one ray each, whose steps start at another place every
// frame: alone, its noise shows (a flight through dense layer at High, 160x90: 42.6 dB against
// 42.9 with this resolve). Each pixel is blended with its own history, reprojected through its
// near cloud's depth, and clamped to the range of this frame's 3 x 3 fresh samples around it
// (Karis 2014). With every pixel fresh, the box is each pixel's own, so the clamp leaves no
// blocks (the far part's, one fresh pixel per tile, is the same for a whole tile); and near
// cloud the camera has flown out of is clear in every fresh sample around, so none of it
// survives the clamp.
// Inputs: 0 CloudUniforms; 1 this frame's near field; 2 last frame's resolved near field.
// Output: 3 this frame's resolved near field (upsample.comp lays it over the far part).
// All packed samples (cloud_temporal.h), CloudUniforms.nearFieldExtent.
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
// 1: last frame's resolved near field is usable (kSpecNearHistory); 0 on frames without
// history (cut, resize, the near field just turned on...).
layout(constant_id = kSpecNearHistory) const uint kHistory = 1u;
#include "frame_uniforms.glsl"
// The superstorm's reprojection (cloud_temporal.h) runs when the frame has one (a 0-trip loop
// otherwise: CLOUDS_WHEN).
bool vortexCompiledIn() { return true; }
layout(binding = kNearResolveFresh, rgba32ui) uniform readonly uimage2D fresh;
layout(binding = kNearResolveHistory, rgba32ui) uniform readonly uimage2D history;
layout(binding = kNearResolveOut, rgba32ui) uniform writeonly uimage2D resolved;

#include "cloud_march.h"

// The weight of this frame's sample over the clamped history: an exponential mean of about
// the last four frames (the clamp, not the weight, bounds the lag).
const float kNearFreshWeight = 0.25f;

ivec2 clampPixel(ivec2 p) { return clamp(p, ivec2(0), ivec2(u.nearFieldExtent) - 1); }

// Last frame's resolved near field at `position` (trace pixels), bilinear; its depths at the
// nearest texel (a blend of two clouds' depths is neither's).
vec4 historyAt(vec2 position, out vec2 depth) {
  const vec2 p = position - 0.5f;
  const vec2 f = p - floor(p);
  const ivec2 i = ivec2(floor(p));
  vec4 radiance = vec4(0.0f);
  const int nearest = (f.y < 0.5f ? 0 : 2) + (f.x < 0.5f ? 0 : 1);
  for (int t = 0; t < 4; ++t) {
    const ivec2 offset = ivec2(t & 1, t >> 1);
    const uvec4 h = imageLoad(history, clampPixel(i + offset));
    const float w = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
    radiance += w * unpackCloudRadiance(h);
    if (t == nearest) depth = unpackCloudDepth(h);
  }
  return radiance;
}

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.nearFieldExtent))) return;
  const uvec4 own = imageLoad(fresh, ivec2(pixel));
  const vec4 current = unpackCloudRadiance(own);
  const vec2 currentDepth = unpackCloudDepth(own);
  vec4 result = current;
  vec2 resultDepth = currentDepth;
  if (kHistory != 0u) {
    vec4 lo = current;
    vec4 hi = current;
    for (int t = 0; t < 9; ++t) {
      if (t == 4) continue;  // the pixel's own
      const ivec2 q = clampPixel(ivec2(pixel) + ivec2(t % 3 - 1, t / 3 - 1));
      const vec4 r = unpackCloudRadiance(imageLoad(fresh, q));
      lo = min(lo, r);
      hi = max(hi, r);
    }
    // Without near cloud in this pixel's ray, its history is of clear air too wherever it was:
    // the split's distance stands in for the depth.
    const vec2 depth = currentDepth.y > 0.0f ? currentDepth : vec2(u.nearFieldMetres);
    const Reprojection reprojected =
        reprojectPixel(viewRayDirection(vec2(pixel) + 0.5f, vec2(u.nearFieldExtent), u), depth,
                       vec2(u.nearFieldExtent), u);
    vec2 historyDepth;
    const vec4 previous = historyAt(reprojected.position, historyDepth);
    if (reprojected.onScreen && finiteVec4(previous) && !any(isnan(historyDepth))) {
      const vec4 kept = clamp(previous, lo, hi);
      result = mix(kept, current, kNearFreshWeight);
      DepthBlend blend = depthBlendStart();
      depthBlendAdd(blend, 1.0f - kNearFreshWeight, kept.a, historyDepth);
      depthBlendAdd(blend, kNearFreshWeight, current.a, currentDepth);
      resultDepth = depthBlendResult(blend);
    }
  }
  imageStore(resolved, ivec2(pixel), packCloudSample(result, resultDepth));
}
