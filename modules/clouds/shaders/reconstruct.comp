#version 460
// Temporal reconstruction (compute) at the trace resolution. For each pixel:
//  - fresh this frame (marched): the fresh sample, blended with its reprojected history;
//  - not fresh: last frame's result reprojected through the cloud's weighted depth (camera
//    motion and wind drift), clamped to the range of this frame's fresh samples around it;
//  - no usable history (reset, cut, resize, jump, relight, inside the layer, off-screen,
//    not finite): bilinear from this frame's fresh samples (never black, never a smear).
// Inputs: 0 CloudUniforms; 1-2 fresh trace radiance/depth; 3-4 last frame's history.
// Outputs: 5-6 this frame's history (read by upsample.comp and next frame).
// Reference: Schneider 2015 (1-in-16 reprojection); Karis 2014 (neighbourhood clamp).
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = 8, local_size_y = 8) in;
#include "frame_uniforms.glsl"
layout(binding = 1, rgba16f) uniform readonly image2D freshRadiance;
layout(binding = 2, rg32f) uniform readonly image2D freshDepth;
layout(binding = 3, rgba16f) uniform readonly image2D historyRadiance;
layout(binding = 4, rg32f) uniform readonly image2D historyDepth;
layout(binding = 5, rgba16f) uniform writeonly image2D outRadiance;
layout(binding = 6, rg32f) uniform writeonly image2D outDepth;

#include "cloud_march.h"

ivec2 clampPixel(ivec2 p) { return clamp(p, ivec2(0), ivec2(u.extent.xy) - 1); }

// A fresh sample on this frame's grid, clamped to the image (edge tiles may lack one).
ivec2 freshAt(ivec2 p) {
  const int k = int(u.pattern.x);
  const ivec2 last = ((ivec2(u.extent.xy) - 1 - ivec2(u.pattern.yz)) / k) * k + ivec2(u.pattern.yz);
  return clamp(p, ivec2(u.pattern.yz), last);
}

// Where a point `distance` metres along this frame's `direction` was on last frame's trace
// image (pixels): camera motion and wind drift, through last frame's view and projection.
// Behind last frame's camera is far off-screen.
vec2 previousPosition(vec3 direction, float distance) {
  const vec3 then = direction * distance + vec3(u.reprojection);
  const vec4 clip = u.previousViewProjection * vec4(then, 1.0f);
  if (clip.w <= 0.0f) return vec2(-1e6f);
  return (clip.xy / clip.w * 0.5f + 0.5f) * vec2(u.extent.xy);
}

vec4 bilinearHistory(vec2 position, out vec2 depth) {
  const vec2 p = position - 0.5f;
  const vec2 f = p - floor(p);
  const ivec2 i = ivec2(floor(p));
  vec4 radiance = vec4(0.0f);
  DepthBlend blend = depthBlendStart();
  for (int tap = 0; tap < 4; ++tap) {
    const ivec2 offset = ivec2(tap & 1, tap >> 1);
    const ivec2 q = clampPixel(i + offset);
    const float w = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
    const vec4 r = imageLoad(historyRadiance, q);
    radiance += r * w;
    depthBlendAdd(blend, w, r.a, imageLoad(historyDepth, q).xy);
  }
  depth = depthBlendResult(blend);
  return radiance;
}

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.extent.xy))) return;
  const int k = int(u.pattern.x);

  // This frame's estimate: the fresh sample, or bilinear between the fresh ones around it.
  ivec2 p00;
  vec2 f;
  freshNeighbours(pixel, u, p00, f);
  const bool fresh = isFreshPixel(pixel, u);
  vec4 current = vec4(0.0f);
  DepthBlend blend = depthBlendStart();
  for (int tap = 0; tap < 4; ++tap) {
    const ivec2 offset = ivec2(tap & 1, tap >> 1);
    const ivec2 q = freshAt(p00 + offset * k);
    const float w = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
    const vec4 r = imageLoad(freshRadiance, q);
    current += r * w;
    depthBlendAdd(blend, w, r.a, imageLoad(freshDepth, q).xy);
  }
  vec2 currentDepth = depthBlendResult(blend);
  if (fresh) {
    current = imageLoad(freshRadiance, ivec2(pixel));
    currentDepth = imageLoad(freshDepth, ivec2(pixel)).xy;
  }

  vec4 result = current;
  vec2 resultDepth = currentDepth;
  if (u.reprojection.w > 0.5f) {
    // Where was this pixel's cloud last frame? Through its weighted depth (or, without cloud,
    // the far distance: empty sky reprojects like the horizon).
    const vec3 direction = pixelRayDirection(vec2(pixel) + 0.5f, vec2(u.extent.xy), u);
    const float far = u.march.z;
    const vec2 position = previousPosition(direction, currentDepth.y > 0.0f ? currentDepth.y : far);
    // How much the answer depends on the depth: the nearest cloud front around this pixel and
    // the far distance reproject this far apart. Zero for a static or only turning camera
    // (exact reprojection: keep the history whole, so small clouds seen by few fresh samples
    // survive); pixels apart when the camera moves past near cloud (parallax, disocclusion:
    // trust this frame's fresh neighbourhood instead).
    const float nearest = currentDepth.x > 0.0f ? currentDepth.x : far;
    const float spread = length(previousPosition(direction, nearest) - previousPosition(direction, far));
    const bool onScreen = all(greaterThanEqual(position, vec2(0.0f))) &&
                          all(lessThan(position, vec2(u.extent.xy)));
    vec2 historyDepthValue;
    const vec4 history = bilinearHistory(position, historyDepthValue);
    if (onScreen && finiteVec4(history) && !any(isnan(historyDepthValue))) {
      // Clamp to the fresh samples of the 3 x 3 surrounding tiles (Karis-style box), as far as
      // the reprojection is uncertain.
      vec4 lo = vec4(1e30f);
      vec4 hi = vec4(-1e30f);
      for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
          const vec4 s = imageLoad(freshRadiance, freshAt(p00 + ivec2(x, y) * k));
          lo = min(lo, s);
          hi = max(hi, s);
        }
      }
      const vec4 margin = (hi - lo) * u.temporal.y + vec4(0.002f);
      const float clampStrength = saturate(spread / u.temporal.w);
      const vec4 trusted = mix(history, clamp(history, lo - margin, hi + margin), clampStrength);
      result = fresh ? mix(trusted, current, u.temporal.x) : trusted;
      resultDepth = fresh ? currentDepth : historyDepthValue;
    }
  }
  imageStore(outRadiance, ivec2(pixel), result);
  imageStore(outDepth, ivec2(pixel), vec4(resultDepth, 0.0f, 0.0f));
}
