// The clouds' lightning glow per unit of cloud (GLSL only), for a pass that declares this
// frame's flashes as `lightning[]` (LightningUniforms, indexed like frame_uniforms.glsl's block)
// and has loaded `u`.
//
// Nubis Evolved's glow term (Schneider 2022: potential pow(1 - d / r, 12), times the height
// gradient d2 / height, less where the cloud is dense) and the flash's sky light
// (fxcontracts/lightning_light.h: the core's inverse square, the light that makes the whole deck
// flicker), at the clouds' transmittance-weighted depth along the pixel's ray. The local
// density of the seeds' pseudo-attenuation is that of the cloud the pixel sees into: its optical
// depth (at most 1: an opaque cloud shows its outer skin) over its depth span (twice the
// weighted depth past the front), exact for a thin uniform cloud. The height gradient is the
// cloud's height fraction in the layer (the seed's d2 / height): nothing at the base, all of it
// at the top, so a storm's flash lights up its towering body while its base only flickers with
// the flash's sky light. Hero clouds take it by their altitude in the layer too (Nubis' voxel
// clouds drop it; seen per pixel, a hero cloud is not told apart).
#ifndef CLOUDS_CLOUD_LIGHTNING_GLSL
#define CLOUDS_CLOUD_LIGHTNING_GLSL

#include "cloud_march.h"
#include "fxcontracts/lightning_light.h"

// `ray`: the pixel's world-space unit ray; `transmittance` and `depth` (front, weighted; m):
// the clouds it sees.
vec3 flashLightPerCloud(vec3 ray, float transmittance, vec2 depth) {
  vec3 glow = vec3(0.0f);
  if (depth.y <= 0.0f || transmittance >= 1.0f) return glow;
  const uint slot = CLOUDS_FRAME_UNIFORMS_INDEX;
  const vec3 cloud = ray * depth.y;  // camera-relative (m)
  const float span = max(2.0f * (depth.y - depth.x), 1.0f);
  const float opticalDepth = min(-log(max(transmittance, 1e-6f)), 1.0f);
  const float density = opticalDepth / span / max(u.extinctionPerMetre, 1e-12f);
  const float attenuation = 1.0f - saturate(density * 5.0f);
  const float altitude = altitudeAlongRay(depth.y, ray.y, u.cameraAltitudeMetres,
                                          u.planetRadiusMetres);
  const float heightGradient = saturate((altitude - u.layerBottomMetres) /
                                        max(u.layerTopMetres - u.layerBottomMetres, 1.0f));
  for (uint i = 0u; i < lightning[slot].count.x; ++i) {
    const vec4 flash = lightning[slot].flash[2u * i];
    const float distance = length(cloud - flash.xyz);
    const float core = flashGlow(distance, flash.w) * heightGradient * attenuation;
    glow += lightning[slot].flash[2u * i + 1u].rgb * (core + flashSkyLight(distance, flash.w));
  }
  return glow;
}

#endif
