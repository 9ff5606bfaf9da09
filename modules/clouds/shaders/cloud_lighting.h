// The Nubis lighting terms (Schneider 2017, 2022), written to stay physically bounded where
// the tests check physics: light energy = direct scattering + ambient scattering.
//  - direct: sun illuminance x phase x transmittance towards the sun, with a multiple-
//    scattering approximation (Wrenninge 2013 octaves: extinction scaled by a^n, contribution
//    by b^n, eccentricity by c^n) and the in-scatter probability that darkens edges and bases;
//  - ambient: sky radiance blended from base to top, attenuated inside dense cloud.
// The art terms (in-scatter probability, ambient occlusion) are strengths in [0, 1], so a
// white-furnace configuration can switch them off and test the integrator alone.
#ifndef CLOUDS_CLOUD_LIGHTING_H
#define CLOUDS_CLOUD_LIGHTING_H

#include "cloud_math.h"
#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// The phase of each multiple-scattering octave (1/sr): octave n scatters with the lobes'
// eccentricities scaled by c^n. The angle to the sun is the same all along a ray, so a march
// computes these once per ray, and a sample pays one exponential per octave, not two phase
// functions. Octaves 0-3 in `low`, 4-7 in `high`; `cosToSun` is the cosine they were made for.
struct OctavePhases {
  vec4 low;
  vec4 high;
  float cosToSun;
};

FX_INLINE OctavePhases octavePhases(float cosTheta, IN(CloudUniforms) u) {
  OctavePhases phases;
  phases.low = vec4(0.0f);
  phases.high = vec4(0.0f);
  phases.cosToSun = cosTheta;
  const int octaves = int(clamp(u.msOctaves, 1.0f, 8.0f));
  float eccentricity = 1.0f;
  for (int n = 0; n < octaves; ++n) {
    const float normaliserInverse =
        n < 4 ? u.phaseNormaliserInverseLow[n] : u.phaseNormaliserInverseHigh[n - 4];
    const float phase = silverLiningPhase(
        cosTheta, u.phaseForwardG * eccentricity, u.phaseBackwardG * eccentricity,
        u.phaseBackwardWeight, u.silverG * eccentricity, u.silverIntensity, normaliserInverse);
    if (n < 4) {
      phases.low[n] = phase;
    } else {
      phases.high[n - 4] = phase;
    }
    eccentricity *= u.msEccentricityScale;
  }
  return phases;
}

// Sun light reaching a sample and scattered towards the viewer (1/sr), per unit illuminance.
// With multiple scattering, Wrenninge's octaves: octave n sees the light's optical depth scaled
// by a^n and contributes b^n (the defaults are tuned so that a thick sunlit cloud reflects
// most of the sun, as measured clouds do: march_gpu_test's sunlit slab).
FX_INLINE float directScattering(float lightOpticalDepth, IN(OctavePhases) phases,
                                 IN(CloudUniforms) u, uint multipleScattering) {
  if (multipleScattering == 0u) return beerLambert(lightOpticalDepth) * phases.low.x;
  const int octaves = int(clamp(u.msOctaves, 1.0f, 8.0f));
  float extinctionScale = 1.0f;
  float contribution = 1.0f;
  float sum = 0.0f;
  for (int n = 0; n < octaves; ++n) {
    const float phase = n < 4 ? phases.low[n] : phases.high[n - 4];
    sum += contribution * beerLambert(lightOpticalDepth * extinctionScale) * phase;
    extinctionScale *= u.msExtinctionScale;
    contribution *= u.msContribution;
  }
  return sum;
}

// Nubis 2017 in-scatter probability, in [0, 1]: a sample sees few scattering contributors
// where the cloud around it is thin (its edges) and near the base (nothing bright below).
//  - `core` is the coarse shape relative to a cloud's core, in [0, 1] (0 at the edge): the role
//    of Nubis 2017's low-LOD density and 2022's dimensional profile (coarseShape()).
//  - Directional refinement (2017 talk): the dark edges belong to faces seen with the sun behind
//    or beside the viewer (the "powdered sugar" look); looking towards the sun, light scattered
//    forward through thin edges makes them bright (the silver lining). So the edge term fades as
//    the view ray turns towards the sun (`cosToSun`, the cosine between them): fully there at
//    90 degrees and beyond, gone looking into the sun. The dark base stays in every direction.
FX_INLINE float inScatterProbability(float core, float heightFraction, float cosToSun) {
  const float edgeProbability =
      0.05f + pow(saturate(core), remapClamped(heightFraction, 0.3f, 0.85f, 0.5f, 2.0f));
  const float depthProbability = mix(saturate(edgeProbability), 1.0f, saturate(cosToSun));
  const float verticalProbability =
      pow(remapClamped(heightFraction, 0.07f, 0.14f, 0.1f, 1.0f), 0.8f);
  return saturate(depthProbability * verticalProbability);
}

// The share of the lower hemisphere (by solid angle) more than 10 degrees below the horizon:
// there a cloud base sees the ground; nearer the horizon it looks through so much air that it
// sees the horizon's haze instead. 1 - sin(10 degrees).
const float kGroundShareOfLowerHemisphere = 0.82635182f;

// The radiance of a Lambertian ground of `groundAlbedo` lit by the sun (illuminance
// `sunIlluminance` at `sunUp`, the sine of its elevation, a share `groundSunlit` of the ground
// out of the clouds' shadow) and the sky (irradiance pi `skyTop`, `skyTop` the cosine-weighted
// mean radiance of the upper hemisphere).
FX_INLINE vec3 groundRadiance(vec3 skyTop, vec3 groundAlbedo, vec3 sunIlluminance, float sunUp,
                              float groundSunlit) {
  const vec3 irradiance =
      sunIlluminance * (max(sunUp, 0.0f) * saturate(groundSunlit)) + kPi * skyTop;
  return groundAlbedo * irradiance / kPi;
}

// The radiance that lights cloud bases from below (ambientBottom) when the ground is known: the
// ground's, a Lambertian surface of `groundAlbedo` lit by the sun (illuminance `sunIlluminance`
// at `sunUp`, the sine of its elevation, a share `groundSunlit` of the ground out of the
// clouds' shadow) and the sky (irradiance pi `skyTop`, `skyTop` the cosine-weighted mean
// radiance of the upper hemisphere), seen over most of the lower hemisphere, and the horizon's
// radiance over the rest.
FX_INLINE vec3 groundLitBaseRadiance(vec3 horizon, vec3 skyTop, vec3 groundAlbedo,
                                     vec3 sunIlluminance, float sunUp, float groundSunlit) {
  const vec3 ground = groundRadiance(skyTop, groundAlbedo, sunIlluminance, sunUp, groundSunlit);
  return mix(horizon, ground, kGroundShareOfLowerHemisphere);
}

// Radiance scattered towards the viewer at a sample, per unit scattering coefficient (before
// the albedo). `profile` is the coarse shape in [0, 1] (coarseShape()); `sunLight` in [0, 1]
// the share of the sun not hidden by the terrain.
FX_INLINE vec3 sampleRadiance(float lightOpticalDepth, float sunLight, IN(OctavePhases) phases,
                              float profile, float heightFraction, IN(CloudUniforms) u,
                              uint multipleScattering) {
  const float core = profile / max(u.inScatterCoreProfile, 1e-3f);
  const float inScatter = mix(1.0f, inScatterProbability(core, heightFraction, phases.cosToSun),
                              saturate(u.inScatterStrength));
  const float direct = directScattering(lightOpticalDepth, phases, u, multipleScattering);
  const vec3 sun = u.sunIlluminance * (direct * inScatter * sunLight * u.sunStrength);
  const vec3 sky = mix(u.ambientBottom, u.ambientTop, saturate(heightFraction));
  // Nubis 2022 ambient scattering: pow(1 - profile, 0.5) darkens the inside of dense cloud.
  const float occlusion = sqrt(saturate(1.0f - profile));
  const vec3 ambient =
      sky * (u.ambientStrength * mix(1.0f, occlusion, saturate(u.ambientOcclusionStrength)));
  return sun + ambient;
}

// The altitude (m) the sky light's rays start from: the camera's, or, for a camera in or above
// the layer, just below the layer straight under it. The sky light lights the ground (and what
// lies under the clouds), which sees the layer from below whatever the camera's altitude. The
// march's flat offsets are the camera's (x, z): only the altitude moves. Hero clouds, placed
// relative to the camera, are seen from the camera's altitude still.
FX_INLINE float skyLightAltitude(IN(CloudUniforms) u) {
  return min(u.cameraAltitudeMetres, u.layerBottomMetres - 10.0f);
}

FX_SHADER_END

#endif
