#version 460
// Depth-aware upsample (compute) from the trace resolution to the output: bilinear over the
// four nearest trace pixels, except that a trace pixel whose nearest cloud starts behind this
// output pixel's geometry contributes "no cloud" (no halos of cloud over mountain edges).
//
// With temporal upsampling (specialization constant kSpecTemporalUpsampling) it also keeps an
// output-resolution history of each pixel's own samples: the march moves its rays inside
// their trace pixels from one refresh to the next, so over the rounds every output pixel is
// hit by rays of its own. A pixel's result is then the mean of its own samples (up to
// CloudUniforms.upsamplingMaxSamples, then a running mean), reprojected like the trace history
// and blended with the bilinear estimate: on a silhouette until it holds two, elsewhere until
// the running mean takes over (main()); a pixel whose history is uncertain
// (parallax clamp) starts again from the bilinear estimate, as does every pixel of a frame
// without history. Static and turning views converge to full-resolution detail; a camera
// moving past near cloud sees what the trace resolution gives. Whether there is history, and
// whether anything moved, are per-frame variants (kSpecOutputHistory).
//
// With the near field (kSpecUpsampleNearField: Settings::nearFieldMetres, this frame), the clouds
// nearer than the split, marched apart every frame, are laid over all of that (layNearOverFar()),
// bilinear from the near field's pixels around like the spatial estimate; the histories keep the
// far part only.
//
// With the host's aerial perspective (kSpecAerialPerspective) the output is hazed: hazed().
// With god rays (kSpecUpsampleGodRays), the sky's pixels then get god_rays.comp's light, as
// much as the clouds let the sky through (fxcontracts/god_rays.h): the screen-space mask says
// nothing of the air in front of the host's geometry or of opaque cloud. The histories keep
// neither.
//
// Inputs: 0 CloudUniforms; 1 reconstructed samples (trace res, packed: cloud_temporal.h);
// 2 host depth; 5 this frame's marched samples (trace res); 6 last frame's output history;
// 8 the host's aerial perspective (3D); 9 the god rays' light (a quarter of the output res);
// 10 the clouds' lightning glow (trace res); 11 the resolved near field (nearFieldExtent).
// Outputs: 3 RGBA16F radiance + transmittance, 4 RG32F depths (output res; only with
// kSpecUpsampleDepthOutput: Settings::depthOutput, or the bolts' pass reads them); 7 this
// frame's output history (output res, RG32UI: packOutputHistory()).
// References: Karis 2014 (temporal accumulation, neighbourhood clamp); Schneider 2015.
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecTemporalUpsampling) const uint kTemporalUpsampling = 0u;
// Last frame's output history: 0 none (reset, resize, cut...), 1 the camera and
// the clouds held still (each pixel's history is where it was: no reprojection, one load,
// updated in place), 2 reprojected (kSpecOutputHistory).
layout(constant_id = kSpecOutputHistory) const uint kOutputHistory = 0u;
// 1: the host gave an aerial perspective; the output is hazed with it (kSpecAerialPerspective).
layout(constant_id = kSpecAerialPerspective) const uint kAerialPerspective = 0u;
// 1: god rays: the sky's pixels get their light (kSpecUpsampleGodRays).
layout(constant_id = kSpecUpsampleGodRays) const uint kGodRays = 0u;
// 1: lightning: the clouds glow with this frame's flashes (kSpecUpsampleLightning).
layout(constant_id = kSpecUpsampleLightning) const uint kLightning = 0u;
// 1: store the cloud depth output (kSpecUpsampleDepthOutput). A host that does not read it
// saves its store, about a quarter of the pass on lavapipe (an image store there is a loop
// over the lanes for each 32-bit word, and the depths are two).
layout(constant_id = kSpecUpsampleDepthOutput) const uint kDepthOutput = 1u;
// 1: the near field was marched apart this frame (kSpecUpsampleNearField).
layout(constant_id = kSpecUpsampleNearField) const uint kNearField = 0u;
#include "frame_uniforms.glsl"
// The superstorm's reprojection (cloud_temporal.h) runs when the frame has one (a 0-trip loop
// otherwise: CLOUDS_WHEN).
bool vortexCompiledIn() { return true; }
layout(binding = kUpsampleTraceSamples, rgba32ui) uniform readonly uimage2D traceSamples;
layout(binding = kUpsampleHostDepth) uniform sampler2D hostDepth;
layout(binding = kUpsampleRadianceOut, rgba16f) uniform writeonly image2D outRadiance;
layout(binding = kUpsampleDepthOut, rg32f) uniform writeonly image2D outDepth;
layout(binding = kUpsampleFresh, rgba32ui) uniform readonly uimage2D freshSamples;
layout(binding = kUpsampleHistory, rg32ui) uniform readonly uimage2D outputHistory;
layout(binding = kUpsampleHistoryOut, rg32ui) uniform writeonly uimage2D outputHistoryOut;
layout(binding = kUpsampleAerialPerspective) uniform sampler3D aerialPerspective;
layout(binding = kUpsampleGodRayLight) uniform sampler2D godRayLight;
layout(binding = kUpsampleLightningGlow) uniform sampler2D lightningGlow;
layout(binding = kUpsampleNearField, rgba32ui) uniform readonly uimage2D nearField;

#include "fxcontracts/aerial_perspective.glsl"

#include "cloud_march.h"

// Whether all of a cloud sample (front and weighted depth, m) lies behind this pixel's
// geometry (at `scene` m).
bool behindGeometry(float scene, vec2 depth) { return depth.x > 0.0f && scene < depth.x; }

// A cloud sample seen through this pixel's geometry: none of it when it is behind it.
void occlude(float scene, inout vec4 radiance, inout vec2 depth) {
  if (behindGeometry(scene, depth)) {
    radiance = vec4(0.0f, 0.0f, 0.0f, 1.0f);
    depth = vec2(0.0f);
  }
}

// Last frame's output history at `position` (output pixels): radiance bilinear over the taps
// that hold own samples (a tap without is a placeholder, not "no cloud"), the front depth and
// the own-sample count of the valid tap with the largest weight; no count when none is valid.
vec4 outputHistoryAt(vec2 position, out float front, out uint ownSamples) {
  const vec2 p = position - 0.5f;
  const ivec2 i = ivec2(floor(p));
  const vec2 f = p - floor(p);
  const ivec2 last = ivec2(u.outputExtent) - 1;
  vec4 radiance = vec4(0.0f);
  float weightSum = 0.0f;
  float bestWeight = 0.0f;
  front = 0.0f;
  ownSamples = 0u;
  for (int tap = 0; tap < 4; ++tap) {
    const ivec2 offset = ivec2(tap & 1, tap >> 1);
    const uvec2 h = imageLoad(outputHistory, clamp(i + offset, ivec2(0), last)).xy;
    const uint count = ownSampleCount(h);
    const float bilinear = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
    const float w = count > 0u ? bilinear : 0.0f;
    radiance += w * unpackOutputHistory(h);
    weightSum += w;
    if (w > bestWeight) {
      bestWeight = w;
      front = outputHistoryFrontDepth(h);
      ownSamples = count;
    }
  }
  return weightSum > 0.0f ? radiance / weightSum : vec4(0.0f, 0.0f, 0.0f, 1.0f);
}

// The clouds seen through the air in front of them (Hillaire 2016; Schneider 2022): their
// radiance attenuated and the haze in front added at their transmittance-weighted depth, as
// much of it as the clouds cover, rgb * T_air + L_air * (1 - T_clouds); the host's background
// behind the clouds carries its own haze. The histories keep the unhazed clouds (the haze moves
// with the camera, the clouds do not).
vec4 hazed(uvec2 pixel, vec4 radiance, vec2 depth) {
  if (kAerialPerspective == 0u) return radiance;
  const vec2 uv = (vec2(pixel) + 0.5f) / vec2(u.outputExtent);
  const vec4 air = aerialPerspectiveAt(aerialPerspective, uv, depth.y, u.aerialPerspectiveRange,
                                       u.aerialPerspectiveSlices);
  const vec3 inScattered = air.rgb * u.aerialPerspectiveScale * (1.0f - radiance.a);
  return vec4(radiance.rgb * air.a + inScattered, radiance.a);
}

// What the output pixel shows: the clouds (glowing with lightning), hazed, and with god rays
// the light the air in front of the sky behind them gains or loses (`scene` m: the host's
// geometry, infinite for sky).
vec4 outputRadiance(uvec2 pixel, vec4 radiance, vec2 depth, float scene) {
  if (kLightning != 0u) {
    // The glow per unit of cloud, at the trace resolution (smooth), times this pixel's cloud.
    const vec2 trace = (vec2(pixel) + 0.5f) * vec2(u.traceExtent) / vec2(u.outputExtent);
    const vec2 uv = trace / vec2(textureSize(lightningGlow, 0));
    radiance.rgb += (1.0f - radiance.a) * textureLod(lightningGlow, uv, 0.0f).rgb;
  }
  vec4 result = hazed(pixel, radiance, depth);
  if (kGodRays != 0u && scene >= kInfiniteDistance) {
    // The light image is a quarter of the output, rounded up: kGodRayDownsample pixels a texel.
    const vec2 texels = vec2(textureSize(godRayLight, 0));
    const vec2 uv = (vec2(pixel) + 0.5f) / (texels * float(kGodRayDownsample));
    result.rgb += radiance.a * textureLod(godRayLight, uv, 0.0f).rgb;
  }
  return result;
}

// Whether a ray through `trace` (trace pixels) went through output pixel `pixel`.
bool hitsPixel(vec2 trace, vec2 scale, uvec2 pixel) {
  return all(equal(uvec2(floor(trace / scale)), pixel));
}

// Tap `tap` (0-3) of the bilinear filter over the trace pixels around output pixel `pixel`:
// its trace pixel, and its weight.
ivec2 bilinearTap(uvec2 pixel, uvec2 extent, int tap, out float weight) {
  const vec2 p = (vec2(pixel) + 0.5f) * vec2(extent) / vec2(u.outputExtent) - 0.5f;
  const vec2 f = p - floor(p);
  const ivec2 offset = ivec2(tap & 1, tap >> 1);
  weight = (offset.x == 1 ? f.x : 1.0f - f.x) * (offset.y == 1 ? f.y : 1.0f - f.y);
  return clamp(ivec2(floor(p)) + offset, ivec2(0), ivec2(extent) - 1);
}

// The depth-aware bilinear estimate from the four trace pixels around this one.
void spatialEstimate(uvec2 pixel, float scene, out vec4 radiance, out vec2 depth, out vec4 lo,
                     out vec4 hi) {
  radiance = vec4(0.0f);
  lo = vec4(1e30f);
  hi = vec4(-1e30f);
  DepthBlend blend = depthBlendStart();
  for (int tap = 0; tap < 4; ++tap) {
    float w;
    const ivec2 q = bilinearTap(pixel, u.traceExtent, tap, w);
    const uvec4 packed = imageLoad(traceSamples, q);
    vec4 r = unpackCloudRadiance(packed);
    vec2 d = unpackCloudDepth(packed);
    occlude(scene, r, d);
    radiance += r * w;
    lo = min(lo, r);
    hi = max(hi, r);
    depthBlendAdd(blend, w, r.a, d);
  }
  depth = depthBlendResult(blend);
}

// The near field's clouds in front of this frame's far part (`radiance`, `depth`), the same
// depth-aware bilinear estimate from its trace pixels; nothing without a near field.
void layNearField(uvec2 pixel, float scene, inout vec4 radiance, inout vec2 depth) {
  if (kNearField == 0u) return;
  vec4 near = vec4(0.0f);
  DepthBlend blend = depthBlendStart();
  for (int tap = 0; tap < 4; ++tap) {
    float w;
    const ivec2 q = bilinearTap(pixel, u.nearFieldExtent, tap, w);
    const uvec4 packed = imageLoad(nearField, q);
    vec4 r = unpackCloudRadiance(packed);
    vec2 d = unpackCloudDepth(packed);
    occlude(scene, r, d);
    near += r * w;
    depthBlendAdd(blend, w, r.a, d);
  }
  layNearOverFar(near, depthBlendResult(blend), radiance, depth);
}

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  const uvec2 full = u.outputExtent;
  if (any(greaterThanEqual(pixel, full))) return;
  const float scene = sceneDistanceFromDepth(texelFetch(hostDepth, ivec2(pixel), 0).r,
                                             vec2(pixel) + 0.5f, vec2(full), u);
  const vec2 scale = vec2(u.traceExtent) / vec2(full);  // trace pixels per output pixel
  // The spatial estimate, and the range of the trace pixels it comes from.
  vec4 spatial, lo, hi;
  vec2 spatialDepth;
  spatialEstimate(pixel, scene, spatial, spatialDepth, lo, hi);
  if (kTemporalUpsampling == 0u) {
    layNearField(pixel, scene, spatial, spatialDepth);
    imageStore(outRadiance, ivec2(pixel), outputRadiance(pixel, spatial, spatialDepth, scene));
    if (kDepthOutput != 0u) imageStore(outDepth, ivec2(pixel), vec4(spatialDepth, 0.0f, 0.0f));
    return;
  }

  // The trace pixel under this one: this frame's fresh sample is there when its ray went
  // through this pixel.
  const uvec2 trace = min(uvec2((vec2(pixel) + 0.5f) * scale), u.traceExtent - 1u);
  // The mean of this pixel's own samples so far, the nearest front depth among them, and how
  // many there are.
  vec4 own = vec4(0.0f, 0.0f, 0.0f, 1.0f);
  float ownFront = 0.0f;
  uint ownSamples = 0u;
  bool tookFresh = false;  // this frame's fresh sample was added to the own samples
  // (Every path of a shader costs on lavapipe, which runs both sides of a branch for all
  // lanes: what a frame does not need is compiled out by specialization instead.)
  if (kOutputHistory != 0u) {
    vec4 history;
    float historyFront;
    uint historySamples;
    bool certain = true;
    if (kOutputHistory == 1u) {
      const uvec2 here = imageLoad(outputHistory, ivec2(pixel)).xy;
      history = unpackOutputHistory(here);
      historyFront = outputHistoryFrontDepth(here);
      historySamples = ownSampleCount(here);
    } else {
      // Reprojected through the cloud's weighted depth (as the trace history is,
      // cloud_temporal.h; this frame's reconstructed trace pixel under this one gives the
      // depths) and kept only where the reprojection is certain: on screen, below half the
      // parallax that fully clamps the trace history. Resampled every frame, the history
      // blurs a little between own samples under motion (and under wind drift).
      const Reprojection reprojected = reprojectPixel(
          viewRayDirection(vec2(pixel) + 0.5f, vec2(full), u),
          unpackCloudDepth(imageLoad(traceSamples, ivec2(trace))), vec2(full), u);
      certain = reprojected.onScreen &&
                reprojected.spread * scale.x < 0.5f * u.historyClampSpreadPixels;
      history = outputHistoryAt(reprojected.position, historyFront, historySamples);
      // Something moved (the camera, or the clouds' detail with the wind): the own samples
      // may be stale; keep them within the range of this frame's trace pixels around.
      const vec4 margin = (hi - lo) * u.historyClampMargin + vec4(0.002f);
      history = clamp(history, lo - margin, hi + margin);
    }
    // Kept where no geometry now stands in front of it and it is finite; anything else starts
    // again from the spatial estimate.
    if (certain && historySamples > 0u && !behindGeometry(scene, vec2(historyFront, 0.0f)) &&
        finiteVec4(history) && !isnan(historyFront)) {
      own = history;
      ownFront = historyFront;
      ownSamples = historySamples;
    }

    // This frame's fresh sample, when its ray (moved inside its trace pixel by u.subpixelOffset)
    // went through this output pixel: one pixel in (k / scale)^2 has one; or one of its trace
    // pixel's edge rays, when that went through it (kFlagEdgeRays; each through another output
    // pixel of the trace pixel) and was marched (its slot holds kNoEdgeRay when not). Samples
    // hidden by geometry are not kept (the geometry may move away).
    // (The two edge rays a tile may have are tested in straight-line code: as a loop over
    // u.edgeRaysPerTile they cost 0.65 ms of High's upsample at 640x360 on lavapipe.)
    const bool freshPixel = isFreshPixel(trace, u);
    const vec2 centre = vec2(trace) + 0.5f;
    const bool fresh = freshPixel && hitsPixel(centre + u.subpixelOffset, scale, pixel);
    const uint edgeRays = (u.flags & kFlagEdgeRays) != 0u ? u.edgeRaysPerTile : 0u;
    const bool edge0 = edgeRays > 0u && hitsPixel(centre + edgeSubpixelOffset(0u, u), scale, pixel);
    const bool edge1 = edgeRays > 1u && hitsPixel(centre + edgeSubpixelOffset(1u, u), scale, pixel);
    const bool edge = freshPixel && (edge0 || edge1) &&
                      all(lessThan(edgeRaySlot(trace, 0u, u), u.traceExtent));
    const uvec2 at = edge ? edgeRaySlot(trace, edge1 ? 1u : 0u, u) : trace;
    const uvec4 packed = imageLoad(freshSamples, ivec2(at));
    if (fresh || (edge && packed.x != kNoEdgeRay)) {
      const vec4 r = unpackCloudRadiance(packed);
      const vec2 d = unpackCloudDepth(packed);
      if (!behindGeometry(scene, d) && finiteVec4(r) && !any(isnan(d))) {
        // The mean of the own samples so far, then a running mean over the last few.
        const float weight = 1.0f / min(float(ownSamples) + 1.0f, u.upsamplingMaxSamples);
        own = mix(own, r, weight);
        if (d.x > 0.0f) ownFront = ownFront > 0.0f ? min(ownFront, d.x) : d.x;
        ownSamples = min(ownSamples + 1u, uint(u.upsamplingMaxSamples));
        tookFresh = true;
      }
    }
  }

  // The result: the own samples' mean, blended with the spatial estimate. A few rays are a
  // noisy point sample of the pixel: shown alone next to pixels without one, the first round
  // of own samples would read as a dither pattern. On a silhouette (the trace pixels around
  // range from cloud to clear) the spatial estimate smears the edge, so two own samples are
  // trusted alone; where the trace pixels agree on the cover, it is the better half of the
  // estimate while the own samples are a plain mean of n (n / (n + 1) of the trust; High's
  // static views: +0.5 dB above the layer, +0.6 to +1.7 on four others, against the trace
  // pixels' agreement ignored; 0.5 or 2 times this edge measure scored lower above the layer).
  // A running mean (n at upsamplingMaxSamples: Ultra's refresh every 4th frame) averages more
  // rays than n and is trusted alone: blending in the spatial estimate cost Ultra 2.2 dB
  // pooled. The history keeps the own samples' front only: their weighted depth is this
  // frame's trace's.
  const float silhouette = hi.a - lo.a;  // transmittances: in [0, 1]
  const float n = float(ownSamples);
  const float settled = n >= u.upsamplingMaxSamples ? 1.0f : n / (n + 1.0f);
  const float trust = mix(settled, min(n * 0.5f, 1.0f), silhouette);
  vec4 radiance = mix(spatial, own, trust);
  DepthBlend blend = depthBlendStart();
  depthBlendAdd(blend, 1.0f - trust, spatial.a, spatialDepth);
  const float ownWeighted = spatialDepth.y > 0.0f ? spatialDepth.y : ownFront;
  depthBlendAdd(blend, trust, own.a, vec2(ownFront, ownWeighted));
  vec2 depth = depthBlendResult(blend);
  layNearField(pixel, scene, radiance, depth);
  // Nothing moved (kOutputHistory 1): the history is updated in place (TemporalState), and
  // only pixels with a fresh sample (1 in 64 at High) pack and store, in a loop that rows of 8
  // without one skip (7 in 8). The others would store the bits they read, or, where this
  // frame set the history aside (geometry now in front, not finite), keep what is still the
  // clouds' own samples for when the geometry has gone (a fresh sample replaces a poisoned
  // one: its mean starts again from the sample alone).
  CLOUDS_WHEN(kOutputHistory != 1u || tookFresh) {
    const uvec2 history = packOutputHistory(own, ownFront, ownSamples);
    imageStore(outputHistoryOut, ivec2(pixel), uvec4(history, 0u, 0u));
  }
  imageStore(outRadiance, ivec2(pixel), outputRadiance(pixel, radiance, depth, scene));
  if (kDepthOutput != 0u) imageStore(outDepth, ivec2(pixel), vec4(depth, 0.0f, 0.0f));
}
