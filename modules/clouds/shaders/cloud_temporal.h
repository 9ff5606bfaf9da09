// Temporal reconstruction at the trace resolution, shared by reconstruct.comp (and readable by
// tests): which pixels are fresh this frame, the spatial estimate from this frame's fresh
// samples, reprojection of last frame's result through the cloud's depth and its resampling
// filter, and the clamp of that history to the fresh neighbourhood (so moving and relit clouds
// do not ghost).
#ifndef CLOUDS_CLOUD_TEMPORAL_H
#define CLOUDS_CLOUD_TEMPORAL_H

#include "cloud_math.h"
#include "cloud_types.h"
#include "cloud_vortex.h"

FX_SHADER_BEGIN(clouds::shader)

FX_INLINE bool isFreshPixel(uvec2 pixel, IN(CloudUniforms) u) {
  // k is a power of two: a mask, not a modulo (integer division is scalarised on a CPU).
  const uint mask = u.tileSize - 1u;
  return (pixel.x & mask) == u.tilePhase.x && (pixel.y & mask) == u.tilePhase.y;
}

// Where a tile's edge ray `ray` (0 or 1) keeps its sample in this frame's samples
// (kFlagEdgeRays): the tile's pixel half a tile away from its fresh one on both axes, or on x
// only (k a power of two, at least 2). The passes read only the fresh pixels of this frame's
// samples, so the tile's others are free.
FX_INLINE uvec2 edgeRaySlot(uvec2 freshPixel, uint ray, IN(CloudUniforms) u) {
  const uint halfTile = u.tileSize / 2u;
  return freshPixel ^ uvec2(halfTile, ray == 0u ? halfTile : 0u);
}

// Where edge ray `ray` sits in its trace pixel this frame (trace pixels, as subpixelOffset).
FX_INLINE vec2 edgeSubpixelOffset(uint ray, IN(CloudUniforms) u) {
  return ray == 0u ? vec2(u.edgeSubpixelOffsets.x, u.edgeSubpixelOffsets.y)
                   : vec2(u.edgeSubpixelOffsets.z, u.edgeSubpixelOffsets.w);
}

// What an edge ray's slot holds when its tile marched none: every bit set (unpacked, a NaN).
const uint kNoEdgeRay = 0xffffffffu;

// Bilinear weights and the four fresh pixels around `pixel` on this frame's k-grid.
FX_INLINE void freshNeighbours(uvec2 pixel, IN(CloudUniforms) u, OUT(ivec2) p00, OUT(vec2) f) {
  const float k = float(u.tileSize);
  const vec2 phase = vec2(float(u.tilePhase.x), float(u.tilePhase.y));
  const vec2 grid = (vec2(pixel) - phase) / k;
  const vec2 g0 = floor(grid);
  f = grid - g0;
  p00 = ivec2(g0 * k + phase);
}

// Blending cloud depths. A pixel without cloud has depth 0, which must not be averaged in:
// half a cloud at 20 km next to clear sky is a cloud at 20 km, not at 10 km. The blend keeps
// the nearest front depth of the contributing pixels (so "all of this cloud is behind that
// geometry" stays conservative) and the opacity-weighted mean of their weighted depths.
struct DepthBlend {
  float front;        // nearest front depth so far (m); 0 before any cloud
  float weightedSum;  // sum of weight x opacity x weighted depth
  float opacitySum;   // sum of weight x opacity
};

FX_INLINE DepthBlend depthBlendStart() {
  DepthBlend b;
  b.front = 0.0f;
  b.weightedSum = 0.0f;
  b.opacitySum = 0.0f;
  return b;
}

FX_INLINE void depthBlendAdd(INOUT(DepthBlend) b, float weight, float transmittance, vec2 depth) {
  if (weight > 0.0f && depth.x > 0.0f) b.front = b.front > 0.0f ? min(b.front, depth.x) : depth.x;
  const float opacity = weight * saturate(1.0f - transmittance);
  b.weightedSum += opacity * depth.y;
  b.opacitySum += opacity;
}

FX_INLINE vec2 depthBlendResult(DepthBlend b) {
  return vec2(b.front, b.opacitySum > 1e-6f ? b.weightedSum / b.opacitySum : 0.0f);
}

// The near field's clouds (Settings::nearFieldMetres: the ray up to the split) laid over the far
// part's (from the split on): radiance `near` + its transmittance x `far`, the transmittances
// multiplied; the depths blended by the opacity each part shows (the near front, where there is
// one, is the nearer).
FX_INLINE void layNearOverFar(vec4 near, vec2 nearDepth, INOUT(vec4) far, INOUT(vec2) farDepth) {
  DepthBlend blend = depthBlendStart();
  depthBlendAdd(blend, 1.0f, near.a, nearDepth);
  depthBlendAdd(blend, near.a, far.a, farDepth);
  far = vec4(vec3(near.r, near.g, near.b) + vec3(far.r, far.g, far.b) * near.a, near.a * far.a);
  farDepth = depthBlendResult(blend);
}

// A marched or reconstructed pixel in one RGBA32UI texel, so the passes that read several
// neighbours (reconstruction, upsample) take one image load per neighbour instead of two:
// x = half2(r, g), y = half2(b, transmittance), z = front depth, w = weighted depth (float).
FX_INLINE uvec4 packCloudSample(vec4 radiance, vec2 depth) {
  return uvec4(packHalf2x16(vec2(radiance.x, radiance.y)),
               packHalf2x16(vec2(radiance.z, radiance.w)), floatBitsToUint(depth.x),
               floatBitsToUint(depth.y));
}

FX_INLINE vec4 unpackCloudRadiance(uvec4 texel) {
  const vec2 rg = unpackHalf2x16(texel.x);
  const vec2 ba = unpackHalf2x16(texel.y);
  return vec4(rg.x, rg.y, ba.x, ba.y);
}

FX_INLINE vec2 unpackCloudDepth(uvec4 texel) {
  return vec2(uintBitsToFloat(texel.z), uintBitsToFloat(texel.w));
}

// The exponent of a positive normal float, floor(log2(x)), read from its bits: exact, where a
// CPU driver's log2 is a polynomial (and costs like one).
FX_INLINE int floorLog2(float x) {
  return int((floatBitsToUint(x) >> 23u) & 0xffu) - 127;
}

// 2^e for an integer e in [-126, 127], made from its bits: exact and cheap, as above.
FX_INLINE float exp2Integer(int e) {
  return uintBitsToFloat(uint(e + 127) << 23u);
}

// Shared-exponent RGB (the RGB9E5 of texture formats): three 9-bit mantissas and one 5-bit
// exponent in 32 bits, for non-negative radiance up to 65408; each channel to within 1/512 of
// the largest. Round trips are exact: a value read back packs to the same bits. (Every output
// pixel may pack one a frame: bit operations, not log2, exp2 and divisions, which took
// 1.1 ms of High's 6.8 ms upsample at 640x360 on lavapipe.)
FX_INLINE uint packSharedExponent(vec3 rgb) {
  const float largest = 65408.0f;  // (2^9 - 1) / 2^9 x 2^(31 - 15)
  const vec3 c = clamp(rgb, vec3(0.0f), vec3(largest));
  const float maximum = max(c.x, max(c.y, c.z));
  int exponent = max(-16, floorLog2(max(maximum, 1e-30f))) + 16;
  float perUnit = exp2Integer(24 - exponent);  // mantissa units per unit of radiance
  // Rounding the largest channel up to 512 units carries into the next exponent.
  const bool carry = floor(maximum * perUnit + 0.5f) >= 512.0f;
  exponent += carry ? 1 : 0;
  perUnit *= carry ? 0.5f : 1.0f;
  const vec3 mantissa = floor(c * perUnit + 0.5f);
  return uint(mantissa.x) | (uint(mantissa.y) << 9u) | (uint(mantissa.z) << 18u) |
         (uint(exponent) << 27u);
}

FX_INLINE vec3 unpackSharedExponent(uint texel) {
  const vec3 mantissa =
      vec3(float(texel & 511u), float((texel >> 9u) & 511u), float((texel >> 18u) & 511u));
  return mantissa * exp2Integer(int(texel >> 27u) - 24);
}

// The output-resolution history of temporal upsampling: the mean of a pixel's own samples, the
// nearest front depth among them, and how many there are, in one RG32UI texel (8 bytes: on
// lavapipe an image store costs about in proportion to its bytes, and this one is written at
// every output pixel of every frame): x = the radiance in shared-exponent RGB, y = the front
// depth as a half float (m, up to 65 km) | the transmittance in 12 bits << 16 | the own-sample
// count (0 to 15) << 28.
FX_INLINE uvec2 packOutputHistory(vec4 radiance, float frontDepth, uint ownSamples) {
  const uint transmittance = uint(saturate(radiance.w) * 4095.0f + 0.5f);
  return uvec2(packSharedExponent(vec3(radiance)),
               (packHalf2x16(vec2(min(frontDepth, 65000.0f), 0.0f)) & 0xffffu) |
                   (transmittance << 16u) | (min(ownSamples, 15u) << 28u));
}

FX_INLINE vec4 unpackOutputHistory(uvec2 texel) {
  return vec4(unpackSharedExponent(texel.x), float((texel.y >> 16u) & 0xfffu) / 4095.0f);
}

// The front depth (m) kept with the own samples; 0 without cloud, NaN when the texel is not one
// this pass wrote (a poisoned history is caught by it).
FX_INLINE float outputHistoryFrontDepth(uvec2 texel) {
  return unpackHalf2x16(texel.y & 0xffffu).x;
}

FX_INLINE uint ownSampleCount(uvec2 texel) {
  return texel.y >> 28u;
}

// Reprojection: where points along this frame's view ray were on last frame's image. A point
// at distance d along the ray was at direction * d + reprojection.xyz from last frame's
// camera, so its clip position is d * along + origin: one matrix product per pixel
// (CloudUniforms.previousClipFromView), then a few operations per distance.
struct PreviousRay {
  vec4 along;   // last frame's clip-space image of the unit view direction (w = 0)
  vec4 origin;  // and of the camera offset (w = 1)
  vec3 world;   // the unit view direction in the world's axes
};

// `viewDirection`: the pixel's unit ray direction in this frame's view space.
FX_INLINE PreviousRay previousRay(vec3 viewDirection, IN(CloudUniforms) u) {
  PreviousRay r;
  r.along = u.previousClipFromView * vec4(viewDirection, 0.0f);
  r.origin = u.previousClipOrigin;
  r.world = vec3(u.viewToWorld * vec4(viewDirection, 0.0f));
  return r;
}

// In a superstorm, how far the cloud at the point `distance` metres along the ray moved since
// the history's frame, in last frame's clip space (w = 0): the storm turned it about the eye
// (cloud_vortex.h), so its previous place is the point turned back by the interval's turn.
// Zero elsewhere, without a storm, or with Settings::vortexReprojection off.
FX_INLINE vec4 vortexClipShift(PreviousRay ray, float distance, IN(CloudUniforms) u) {
  vec4 shift = vec4(0.0f);
  CLOUDS_WHEN(hasVortex(u) && u.vortexHistorySeconds != 0.0f) {
    const vec2 here = vec2(ray.world.x, ray.world.z) * distance;
    const vec2 before =
        vortexTurnedBack(here, u.vortexHistorySeconds, weatherRegion(u, u.vortexRegion));
    shift = u.previousClipFromWorld * vec4(before.x - here.x, 0.0f, before.y - here.y, 0.0f);
  }
  return shift;
}

// Image position (pixels of an image of `extent`) of the point `distance` metres along the
// ray last frame, moved by `shift` (clip space, w = 0: the cloud's own motion besides the
// wind's); far off-screen when it was behind last frame's camera.
FX_INLINE vec2 previousPosition(PreviousRay ray, float distance, vec4 shift, vec2 extent) {
  const vec4 clip = ray.along * distance + ray.origin + shift;
  if (clip.w <= 0.0f) return vec2(-1e6f);
  return (vec2(clip) / clip.w * 0.5f + 0.5f) * extent;
}

// Where a pixel's cloud was on last frame's image (pixels of an image of `extent`): through
// its weighted depth, or, without cloud, the far distance (empty sky reprojects like the
// horizon), moved back by a superstorm's turn there. `spread`: how far apart (pixels) its
// nearest cloud front and the far distance reproject under the same motion, i.e. how much the
// answer depends on the depth: zero for a still or only turning camera (exact), pixels when the
// camera moves past near cloud (parallax, disocclusion).
struct Reprojection {
  vec2 position;
  float spread;
  bool onScreen;
};

// `viewDirection`: the pixel's unit ray direction in this frame's view space; `cloudDepth`:
// front and weighted depth (m), 0 without cloud.
FX_INLINE Reprojection reprojectPixel(vec3 viewDirection, vec2 cloudDepth, vec2 extent,
                                      IN(CloudUniforms) u) {
  const PreviousRay ray = previousRay(viewDirection, u);
  const float far = u.maxDistanceMetres;
  Reprojection r;
  const float weighted = cloudDepth.y > 0.0f ? cloudDepth.y : far;
  const vec4 shift = vortexClipShift(ray, weighted, u);
  r.position = previousPosition(ray, weighted, shift, extent);
  const float nearest = cloudDepth.x > 0.0f ? cloudDepth.x : far;
  r.spread = length(previousPosition(ray, nearest, shift, extent) -
                    previousPosition(ray, far, shift, extent));
  r.onScreen = all(greaterThanEqual(r.position, vec2(0.0f))) && all(lessThan(r.position, extent));
  return r;
}

// Catmull-Rom weights of the four texels around a point at fraction `f` (in [0, 1)) past the
// second, along one axis. Reprojected history is resampled at a fraction of a pixel off at every
// frame between refreshes: bilinear weights blur it a little each time, these keep it sharp
// (they interpolate, and reproduce quadratics exactly). They dip below zero beside an edge: the
// caller clamps what they give to the values it can take.
FX_INLINE vec4 catmullRomWeights(float f) {
  return vec4(f * (-0.5f + f * (1.0f - 0.5f * f)), 1.0f + f * f * (-2.5f + 1.5f * f),
              f * (0.5f + f * (2.0f - 1.5f * f)), f * f * (-0.5f + 0.5f * f));
}

FX_INLINE bool finiteVec4(vec4 v) {
  return !(any(isnan(v)) || any(isinf(v)));
}

FX_SHADER_END

#endif
