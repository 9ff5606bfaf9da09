// Lightning's light, the contract between the module that glows with a flash (the clouds) and
// the host that lights its scene with it (the sample's terrain): one definition, as GLSL and as
// C++, of how far a flash's light reaches and how it falls off.
//
// A flash (clouds::LightningFlash) is a charge glowing inside the cloud with radiance L and a
// reach r. Three terms light the scene with it:
// - The glow (Nubis Evolved, Schneider 2022): cloud at distance d from the charge glows with
//   L flashGlow(d, r), pow(1 - d / r, 12), less where the cloud is dense (the light cannot get
//   out): the bright core of the flash.
// - The direct light: the glowing core, a sphere of radius flashCoreMetres(r) (a sixth of the
//   reach, where the glow is still a tenth) and radiance L, gives a surface facing it at
//   distance d the irradiance pi L (core / d)^2; a Lambertian surface of albedo a sends back
//   a L (core / d)^2 cos(theta).
// - The sky light: the same core lights the cloud around it, which lights everything under it
//   from all of the sky. The flash's light in the sky at a point d from the charge is
//   L flashSkyLight(d, r) = L s core^2 / (core^2 + d^2): the core's inverse square, finite at
//   the charge, times the share s = kFlashSkyShare of it that the cloud sends on (the core is
//   mostly hidden in its own cloud; a cloud lit from one side sends back only part of what it
//   gets). The clouds add it to every cloud pixel (so the whole deck flickers with a
//   flash, not only its core); the host adds a (1 + n.y) / 2 of it to its ground (the sky
//   light of the hemisphere above, whichever way the ground faces the flash).
// Nothing of a flash is kept from frame to frame: each frame's light is its flashes' alone.
#ifndef FX_LIGHTNING_LIGHT_H
#define FX_LIGHTNING_LIGHT_H

#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(fxcontracts::shader)

// The glowing core's radius (m) for a flash of reach `reachMetres`.
FX_INLINE float flashCoreMetres(float reachMetres) {
  return reachMetres / 6.0f;
}

// The glow's falloff at `distance` (m) from the charge: pow(1 - d / r, 12), 0 past the reach.
FX_INLINE float flashGlow(float distance, float reachMetres) {
  const float reach = clamp(1.0f - distance / reachMetres, 0.0f, 1.0f);
  const float reach4 = (reach * reach) * (reach * reach);
  return reach4 * reach4 * reach4;
}

// The share of the core's light the cloud around it sends on as sky light.
const float kFlashSkyShare = 0.05f;

// The flash's light in the sky at a squared distance `distanceSquared` (m^2) from the charge,
// per unit of its radiance (no square root: for a host's per-vertex or per-fragment use).
FX_INLINE float flashSkyLightSquared(float distanceSquared, float reachMetres) {
  const float core = flashCoreMetres(reachMetres);
  return kFlashSkyShare * core * core / (core * core + distanceSquared);
}

// The same at `distance` (m).
FX_INLINE float flashSkyLight(float distance, float reachMetres) {
  return flashSkyLightSquared(distance * distance, reachMetres);
}

FX_SHADER_END

#endif
