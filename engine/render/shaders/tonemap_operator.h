// The display transform, shared by the GPU tonemap pass and CPU tools: exposure, then the
// ACES filmic fit of Narkowicz (2015). Output is linear [0, 1]; sRGB encoding is left to the
// sRGB render target (GPU) or to the PNG writer's caller (CPU).
#ifndef ENGINE_SHADERS_TONEMAP_OPERATOR_H
#define ENGINE_SHADERS_TONEMAP_OPERATOR_H

#include "interop.h"

SHADER_NAMESPACE_BEGIN

// The pass's one descriptor: the HDR image it reads (tonemap.frag, Tonemapper).
const uint kTonemapHdrBinding = 0;

struct TonemapConstants {
  float exposure;  // linear multiplier applied to HDR radiance before the curve
  uint debugView;  // 0: tonemapped; 1: raw HDR clamped (for debugging)
  float pad0;
  float pad1;
};
SHADER_STATIC_ASSERT(sizeof(TonemapConstants) == 16);

SHADER_INLINE vec3 acesFilmic(vec3 x) {
  const float a = 2.51f;
  const float b = 0.03f;
  const float c = 2.43f;
  const float d = 0.59f;
  const float e = 0.14f;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), vec3(0.0f), vec3(1.0f));
}

SHADER_INLINE vec3 tonemap(vec3 hdr, float exposure) {
  // max() also maps NaN to 0 on GPUs (IEEE maxNum) so a bad texel cannot blacken a block.
  return acesFilmic(max(hdr * exposure, vec3(0.0f)));
}

SHADER_INLINE float linearToSrgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

SHADER_NAMESPACE_END

#endif
