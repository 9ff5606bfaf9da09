#version 460
// Temporal reconstruction (compute) at the trace resolution. For each pixel:
//  - fresh this frame (marched): the fresh sample, blended with its reprojected history;
//  - not fresh: last frame's result reprojected through the cloud's weighted depth (camera
//    motion and wind drift), clamped to the range of this frame's fresh samples around it as
//    far as the reprojection is uncertain;
//  - no usable history (off-screen, not finite): bilinear from this frame's fresh samples
//    (never black, never a smear);
//  - a frame without history (reset, cut, resize, jump, relight: kHistoryNone): bilinear
//    from this frame's fresh samples too; but in or near the layer, where thin cloud all
//    around makes each ray's result depend much on where it started, a tent over them that
//    averages their jitter and keeps the edges of the scene behind the clouds
//    (insideCloudEstimate).
// With lightning (kSpecReconstructLightning) it also writes the clouds' glow with this frame's
// flashes per unit of cloud (cloud_lightning.glsl), which the upsample adds: made from the
// result but kept out of it, so no flash enters a history.
// Inputs: 0 CloudUniforms; 1 this frame's marched samples; 2 last frame's result; 4 this
// frame's flashes (LightningUniforms); 6 the scene distance each trace pixel was marched to.
// Outputs: 3 this frame's result (read by upsample.comp and next frame), all trace-resolution
// packed samples (cloud_temporal.h); 5 the glow (RGBA16F).
// (Computing the glow here rather than in a pass of its own saves that pass's invocations,
// which cost on lavapipe whatever they do: 0.2 ms at 640x360, Medium.)
// Reference: Schneider 2015 (1-in-16 reprojection); Karis 2014 (neighbourhood clamp).
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
// Last frame's result (kSpecHistory): 0 none (reset, cut, resize...), 1 nothing moved
// (read and updated in place, unclamped: exact), 2 reprojected. Every path of a shader costs
// on lavapipe, which runs both sides of a branch, so what a frame does not need is compiled
// out.
layout(constant_id = kSpecHistory) const uint kHistory = 2u;
// 1: lightning: the glow with this frame's flashes is written too.
layout(constant_id = kSpecReconstructLightning) const uint kLightning = 0u;
#include "frame_uniforms.glsl"
// The superstorm's reprojection (cloud_temporal.h) runs when the frame has one (a 0-trip loop
// otherwise: CLOUDS_WHEN).
bool vortexCompiledIn() { return true; }
layout(binding = kReconstructFresh, rgba32ui) uniform readonly uimage2D freshSamples;
layout(binding = kReconstructHistory, rgba32ui) uniform readonly uimage2D history;
layout(binding = kReconstructOut, rgba32ui) uniform writeonly uimage2D outSamples;
// Indexed like frame_uniforms.glsl's block, for the same reason (the flash loop's bound).
layout(binding = kReconstructFlashes, std140) uniform Lightning { LightningUniforms lightning[1]; };
layout(binding = kReconstructGlow, rgba16f) uniform writeonly image2D glowOut;
layout(binding = kReconstructSceneDistance, r32f) uniform readonly image2D sceneDistance;

#include "cloud_march.h"
#include "cloud_lightning.glsl"

ivec2 clampPixel(ivec2 p) { return clamp(p, ivec2(0), ivec2(u.traceExtent) - 1); }

// A fresh sample on this frame's grid, clamped to the image (edge tiles may lack one).
ivec2 freshAt(ivec2 p) {
  const ivec2 last = ivec2(int(u.lastFreshPixel & 0xffffu), int(u.lastFreshPixel >> 16u));
  return clamp(p, ivec2(u.tilePhase), last);
}

// Last frame's radiance at `position` (Catmull-Rom over 4 x 4 texels, catmullRomWeights(): at
// 320x180 it costs this pass about 0.2 ms over bilinear, on frames that reproject) and its
// cloud depths at the nearest texel (depths are not filtered: a blend of two clouds' depths is
// neither's).
vec4 historyAt(vec2 position, out vec2 depth) {
  const vec2 p = position - 0.5f;
  const vec2 f = p - floor(p);
  const ivec2 i = ivec2(floor(p));
  const vec4 wx = catmullRomWeights(f.x);
  const vec4 wy = catmullRomWeights(f.y);
  // The nearest texel is one of the middle 2 x 2 of the 16: its depths come from that load.
  const int nearest = (f.y < 0.5f ? 4 : 8) + (f.x < 0.5f ? 1 : 2);
  vec4 radiance = vec4(0.0f);
  for (int t = 0; t < 16; ++t) {
    const uvec4 h = imageLoad(history, clampPixel(i + ivec2((t & 3) - 1, (t >> 2) - 1)));
    radiance += wx[t & 3] * wy[t >> 2] * unpackCloudRadiance(h);
    if (t == nearest) depth = unpackCloudDepth(h);
  }
  return vec4(max(radiance.rgb, vec3(0.0f)), saturate(radiance.a));
}

// reconstruct.comp's reprojection: history whose cloud front lay within this many camera moves
// of the camera is of air the camera flew through.
const float kFlownThroughMoves = 2.0f;

// The pixel's result, and with lightning its glow. Read in place (nothing moved: the history
// and the output are one image, TemporalState), a result that did not `change` is already
// there, bit for bit: only the others (fresh pixels, and any whose history was unusable) are
// packed and stored, in a loop of 0 or 1 trips that rows of 8 lanes without one skip (3 in 4
// at a 1-in-16 refresh).
void writeResult(uvec2 pixel, vec4 result, vec2 resultDepth, bool changed) {
  CLOUDS_WHEN(kHistory != kHistoryInPlace || changed) {
    imageStore(outSamples, ivec2(pixel), packCloudSample(result, resultDepth));
  }
  if (kLightning != 0u) {
    const vec3 ray = pixelRayDirection(vec2(pixel) + 0.5f, vec2(u.traceExtent), u);
    imageStore(glowOut, ivec2(pixel), vec4(flashLightPerCloud(ray, result.a, resultDepth), 0.0f));
  }
}

// How much a fresh sample marched to `there` (m, the scene distance of its trace pixel) tells of a
// pixel whose scene lies at `here`: 1 for the same distance, falling off past a tenth of it
// apart (a ray that stopped at a ridge says little of the cloud in front of the valley beyond).
// The sky is kInfiniteDistance, as far from any geometry as can be.
float sceneSimilarity(float here, float there) {
  const float apart = abs(here - there) / max(min(here, there), 1.0f);
  return 1.0f / (1.0f + 100.0f * apart * apart);
}

// A frame without history inside the layer has only its fresh samples (1 in 4 trace pixels),
// each a single ray started at one of four offsets, alternating along each axis (rayJitter):
// where thin cloud surrounds the camera, bilinear between the nearest four keeps each sample's
// error as it is, a pattern of dots 16 px apart at Medium, 640x360. Instead this is a tent two
// fresh-sample spacings wide along x and y, over the 4 x 4 fresh samples around the pixel:
// wherever the pixel lies it weighs the samples at even and odd places along each axis equally
// (the tent sums to a half over each), so the jitter's pattern cancels; and each sample counts
// as far as it was marched to this pixel's scene distance (sceneSimilarity), so the scene's
// edges seen through the clouds stay sharp. (Elsewhere the samples' errors are small and the
// tent's blur costs more than it saves: 25.6 against 31.3 dB for a frame of cumulus seen from
// the ground at 160x90, High.)
void insideCloudEstimate(uvec2 pixel, out vec4 radiance, out vec2 depth) {
  ivec2 p00;
  vec2 f;
  freshNeighbours(pixel, u, p00, f);
  const int k = int(u.tileSize);
  const float here = imageLoad(sceneDistance, ivec2(pixel)).r;
  // The tent at the samples -1, 0, 1 and 2 spacings from p00.
  const vec4 wx = vec4(1.0f - f.x, 2.0f - f.x, 1.0f + f.x, f.x) * 0.25f;
  const vec4 wy = vec4(1.0f - f.y, 2.0f - f.y, 1.0f + f.y, f.y) * 0.25f;
  // The weights are normalised before the depth blend, which ignores tiny opacity sums.
  uvec4 samples[16];
  float weights[16];
  float weightSum = 0.0f;
  for (int t = 0; t < 16; ++t) {
    const ivec2 q = freshAt(p00 + ivec2((t & 3) - 1, (t >> 2) - 1) * k);
    samples[t] = imageLoad(freshSamples, q);
    // A floor keeps a pixel unlike all of its samples (a thin spire) from having none.
    weights[t] = wx[t & 3] * wy[t >> 2] *
                 (sceneSimilarity(here, imageLoad(sceneDistance, q).r) + 1e-4f);
    weightSum += weights[t];
  }
  radiance = vec4(0.0f);
  DepthBlend blend = depthBlendStart();
  for (int t = 0; t < 16; ++t) {
    const float w = weights[t] / weightSum;
    const vec4 r = unpackCloudRadiance(samples[t]);
    radiance += w * r;
    depthBlendAdd(blend, w, r.a, unpackCloudDepth(samples[t]));
  }
  depth = depthBlendResult(blend);
}

// Image loads dominate this pass on lavapipe (each is a gather), so the estimate and the clamp
// range come from the same 2 x 2 fresh samples around the pixel.
void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.traceExtent))) return;
  const int k = int(u.tileSize);

  if (kHistory == kHistoryNone && (u.flags & kFlagRebuiltInsideCloud) != 0u) {
    vec4 result;
    vec2 resultDepth;
    insideCloudEstimate(pixel, result, resultDepth);
    writeResult(pixel, result, resultDepth, true);
    return;
  }
  // This frame's estimate: bilinear between the fresh samples around the pixel (exactly the
  // pixel's own sample when it is fresh: then p00 is the pixel and f is 0).
  ivec2 p00;
  vec2 f;
  freshNeighbours(pixel, u, p00, f);
  const uvec4 s00 = imageLoad(freshSamples, freshAt(p00));
  const uvec4 s10 = imageLoad(freshSamples, freshAt(p00 + ivec2(k, 0)));
  const uvec4 s01 = imageLoad(freshSamples, freshAt(p00 + ivec2(0, k)));
  const uvec4 s11 = imageLoad(freshSamples, freshAt(p00 + ivec2(k, k)));
  const vec4 r00 = unpackCloudRadiance(s00), r10 = unpackCloudRadiance(s10);
  const vec4 r01 = unpackCloudRadiance(s01), r11 = unpackCloudRadiance(s11);
  const vec4 current = mix(mix(r00, r10, f.x), mix(r01, r11, f.x), f.y);
  DepthBlend blend = depthBlendStart();
  depthBlendAdd(blend, (1.0f - f.x) * (1.0f - f.y), r00.a, unpackCloudDepth(s00));
  depthBlendAdd(blend, f.x * (1.0f - f.y), r10.a, unpackCloudDepth(s10));
  depthBlendAdd(blend, (1.0f - f.x) * f.y, r01.a, unpackCloudDepth(s01));
  depthBlendAdd(blend, f.x * f.y, r11.a, unpackCloudDepth(s11));
  const vec2 currentDepth = depthBlendResult(blend);
  const bool fresh = isFreshPixel(pixel, u);

  // Last frame's result for this pixel, and whether it can be used.
  vec4 previous = current;
  vec2 historyDepth = currentDepth;
  bool usable = false;
  if (kHistory == kHistoryInPlace) {
    const uvec4 texel = imageLoad(history, ivec2(pixel));
    previous = unpackCloudRadiance(texel);
    historyDepth = unpackCloudDepth(texel);
    usable = finiteVec4(previous) && !any(isnan(historyDepth));
  } else if (kHistory == kHistoryReprojected) {
    // Where was this pixel's cloud last frame (cloud_temporal.h)? Where the reprojection
    // depends on the depth (spread), the history is clamped to the range of the fresh
    // samples around the pixel (Karis-style box); a static or only turning camera keeps it
    // whole, so small clouds seen by few fresh samples survive.
    const Reprojection reprojected = reprojectPixel(
        viewRayDirection(vec2(pixel) + 0.5f, vec2(u.traceExtent), u), currentDepth,
        vec2(u.traceExtent), u);
    previous = historyAt(reprojected.position, historyDepth);
    usable = reprojected.onScreen && finiteVec4(previous) && !any(isnan(historyDepth));
    // The box is as wide as the fresh samples' range but centred on this pixel's own
    // estimate (bilinear between them): the range of the four is the same for every pixel
    // between them, and history clamped to it took one value per tile, which showed as
    // blocks of k x k pixels (ground seen through near cloud, with the wind blowing).
    const vec4 lo = min(min(r00, r10), min(r01, r11));
    const vec4 hi = max(max(r00, r10), max(r01, r11));
    const vec4 halfRange = (hi - lo) * (0.5f + u.historyClampMargin) + vec4(0.002f);
    // History whose cloud began within kFlownThroughMoves camera moves of last frame's camera
    // is of the air the camera has since flown through (leaving a cloud, every pixel's): its
    // front now lies beside or behind the camera, so it is clamped fully. (Left to the
    // spread, which this frame's depths give, a flight out of a cloud kept the cloud's grey
    // in pixels not yet refreshed: 0.017 of transmittance two frames out.)
    const bool flownThrough =
        historyDepth.x > 0.0f && historyDepth.x < kFlownThroughMoves * u.cameraMovedMetres;
    const float clampStrength =
        flownThrough ? 1.0f : saturate(reprojected.spread / u.historyClampSpreadPixels);
    previous =
        mix(previous, clamp(previous, current - halfRange, current + halfRange), clampStrength);
  }
  vec4 result = current;
  vec2 resultDepth = currentDepth;
  if (usable) {
    result = fresh ? mix(previous, current, u.temporalFreshWeight) : previous;
    resultDepth = fresh ? currentDepth : historyDepth;
  }
  writeResult(pixel, result, resultDepth, fresh || !usable);
}
