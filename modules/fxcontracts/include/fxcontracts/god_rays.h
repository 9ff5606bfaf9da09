// God rays, the contract between the module that makes their mask (the clouds) and the passes
// that apply it (the clouds' own upsample, into its radiance output, or a host's post process):
// one definition of the mask's meaning and of how it is made and used, as GLSL and as C++.
//
// After Mitchell (GPU Gems 3, ch. 13, "Volumetric Light Scattering as a Post-Process"): a radial
// blur, towards the sun's position on screen, of an occlusion image of what hides the sun (the
// clouds, by their transmittance, and the host's geometry, by its depth). As Nubis (2017) does,
// the result is a mask on the haze's single scattering of the sun, not light pasted over the
// picture: shafts show in the air, not over near scenery.
//
// The occlusion image: at a quarter of the render extent per axis, each texel the mean over its
// 4 x 4 pixels of the clouds' transmittance where the host's depth is the far plane (sky) and 0
// on the host's geometry (the clouds module makes it from its trace resolution, before its
// upsample). The mask, at the same extent (GodRayParameters::extent): texel value M
// in [0, 1], the weighted mean of the occlusion image at `samples` points on the way from the
// texel towards the sun (a fraction `length` of the way, weights falling by `decay` per point):
// 1 where the air along the pixel's ray sees the sun past everything on screen, lower in the
// shadows that clouds and mountains cast through the air. Read it with linear filtering,
// clamped. Samples past the screen's edge read the edge.
//
// The fade f (sun.z): 1 with the sun on screen and above the horizon, falling to 0 as it leaves
// the screen by half of it, goes behind the camera or sets: off screen the mask knows nothing of
// what hides the sun. Every use below is nothing at f = 0 (and the producer may then skip the
// blur and clear the mask to 1).
//
// Use, on pixels that show the sky (weighted by the clouds' transmittance T: the screen-space
// mask says nothing of the air in front of geometry or of opaque cloud), with a haze (an aerial
// perspective giving the in-scattered radiance L_haze towards the sky):
//   colour -= T f (1 - M) godRayMieShare(...) L_haze
// The Mie share of the single scattering towards the camera (godRayMieShare) is where the shafts
// show: towards the sun, where the forward Mie lobe outshines the Rayleigh scattering. It treats
// all of L_haze as single scattering and takes the coefficients' ratio at the ground: an
// approximation (the haze's multiple scattering is not shadowed, and Mie thins faster with
// altitude than Rayleigh), bounded because the correction never exceeds the Mie share of the
// haze the pixel has.
// Without a haze, a glow along the clear paths, the classic post process (documented fallback):
//   colour += T f M godRayGlow(cosTheta) sunIlluminance
// The clouds module adds either to its radiance output's rgb for the sky's pixels (so rgb may
// be negative there; its composite clamps at 0); a host that composites itself gets them too.
#ifndef FX_GOD_RAYS_H
#define FX_GOD_RAYS_H

#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(fxcontracts::shader)

// The mask is this many times smaller than the render extent per axis.
const uint kGodRayDownsample = 4u;

// std140 / push constants: 2 vec4s.
struct GodRayParameters {
  // xy the sun's position in the mask's uv ([0, 1] on screen, clamped to [-4, 5]), z the fade
  // f, w the number of samples along each texel's way towards the sun.
  vec4 sun;
  // x the fraction of the way towards the sun the samples cover, y the weight's decay per
  // sample, zw the mask's extent in texels.
  vec4 blur;
};
FX_STATIC_ASSERT(sizeof(GodRayParameters) == 2 * 16);

// Prototype: the includer implements the filtered read of the occlusion image at `uv` (GLSL:
// textureLod on a linear, clamped sampler; C++: its own).
float fetchGodRayOcclusion(vec2 uv);

// The mask's value at `uv` (the texel's centre in the mask's uv).
FX_INLINE float godRayMaskAt(vec2 uv, IN(GodRayParameters) p) {
  const vec2 toSun = vec2(p.sun.x, p.sun.y) - uv;
  const int samples = int(p.sun.w);
  float sum = 0.0f;
  float weights = 0.0f;
  float weight = 1.0f;
  for (int i = 0; i < samples; ++i) {
    const float t = (float(i) + 0.5f) / float(samples) * p.blur.x;
    sum += weight * fetchGodRayOcclusion(uv + toSun * t);
    weights += weight;
    weight *= p.blur.y;
  }
  return weights > 0.0f ? sum / weights : 1.0f;
}

// Henyey-Greenstein's and Rayleigh's phase functions (1/sr) at cos(angle to the sun).
FX_INLINE float godRayHenyeyGreenstein(float cosTheta, float g) {
  const float denominator = max(1.0f + g * g - 2.0f * g * cosTheta, 1e-6f);
  return (1.0f - g * g) / (4.0f * 3.14159265f * denominator * sqrt(denominator));
}

FX_INLINE float godRayRayleighPhase(float cosTheta) {
  return 3.0f / (16.0f * 3.14159265f) * (1.0f + cosTheta * cosTheta);
}

// The Mie share of the sun's single scattering towards the camera, per channel, for air with
// these scattering coefficients (per metre, at the ground) and Mie asymmetry g, at cos(angle
// between the view ray and the sun).
FX_INLINE vec3 godRayMieShare(vec3 rayleighPerMetre, vec3 miePerMetre, float g, float cosTheta) {
  const vec3 mie = miePerMetre * godRayHenyeyGreenstein(cosTheta, g);
  const vec3 rayleigh = rayleighPerMetre * godRayRayleighPhase(cosTheta);
  return mie / max(mie + rayleigh, vec3(1e-30f));
}

// The fallback's glow (per steradian, times the sun's illuminance): a forward lobe around the
// sun, strength * HG(cosTheta, 0.9).
FX_INLINE float godRayGlow(float cosTheta, float strength) {
  return strength * godRayHenyeyGreenstein(cosTheta, 0.9f);
}

FX_SHADER_END

#endif  // FX_GOD_RAYS_H
