// GPU structs of the sample's scene passes (sky and terrain), shared by shaders and C++.
#ifndef SAMPLE_SHADERS_SCENE_CONSTANTS_H
#define SAMPLE_SHADERS_SCENE_CONSTANTS_H

#include "interop.h"
#include "terrain_material.h"
#include "terrain_sunlight_map.h"
#include "water_surface.h"

SHADER_NAMESPACE_BEGIN

// Per-frame lighting and camera for the scene passes (a uniform buffer).
struct SceneFrame {
  mat4 viewProjection;  // camera-relative world -> clip (reversed-Z)
  vec4 cameraPosition;  // xyz world position (m), w unused
  vec4 cameraRight;     // xyz; w = tan(horizontal fov / 2)
  vec4 cameraUp;        // xyz; w = tan(vertical fov / 2)
  vec4 cameraForward;   // xyz; w unused
  vec4 sunDirection;    // xyz towards the sun; w = sun disc radiance scale
  vec4 sunIlluminance;  // rgb
  vec4 skyZenith;       // rgb sky radiance straight up
  vec4 skyHorizon;      // rgb at the horizon
  vec4 skyGround;       // rgb bounced light from below
  vec4 fog;             // x density (1/m) of the fog alternative; y the aerial perspective's
                        //   range (m), z its slices (fxcontracts/aerial_perspective.glsl); w unused
  vec4 sunAboveAir;     // rgb the sun's illuminance above the air (the haze's radiance scale)
  uvec4 extent;         // xy output size (px)
  TerrainMaterials terrain;  // rock and snow over the terrain mesh's colours
  vec4 sunlightMap;          // the terrain's sunlight map: xy the camera's place in it ([0, 1]),
                             //   zw its reciprocal size (1/m) (terrain_sunlight_map.h)
  // The brightest lightning flash in progress: xyz its place (camera-relative, m), w the
  // radius (m) of the glowing cloud around it; and that cloud's radiance (rgb; 0: no flash).
  vec4 flash;
  vec4 flashRadiance;
  // The water (a scene's lake or sea; water_surface.h): x its level (m above sea level), y its
  // clarity (the share of the bed seen straight down), z how far from the camera the bed shows
  // (m: waterBedReachMetres()), w unused; its body's albedo (rgb); where
  // a bed lies under it (the terrain's extent: xy the lowest x and z, zw the highest; beyond it
  // the sea is deep and shows none); each ripple's phase at the camera (radians, waves 0 to 3
  // then 4 to 7: waterPhasesAt(), made on the CPU in double precision).
  vec4 water;
  vec4 waterColour;
  vec4 waterBed;
  vec4 waterPhases;
  vec4 waterPhasesHigh;
};
SHADER_STATIC_ASSERT(sizeof(SceneFrame) == 64 + 22 * 16);

// Sky radiance along a view direction: a zenith-to-horizon blend, ground below, a sun disc and
// its glow. Shared so the terrain's fog fades to exactly the sky behind it.
SHADER_INLINE vec3 skyRadiance(vec3 direction, vec3 sun, vec3 zenith, vec3 horizon, vec3 ground,
                               vec3 sunColour, float discScale) {
  const float up = direction.y;
  vec3 colour = up >= 0.0f ? mix(horizon, zenith, sqrt(clamp(up, 0.0f, 1.0f)))
                           : mix(horizon, ground, clamp(-up * 8.0f, 0.0f, 1.0f));
  const float sunCos = dot(direction, sun);
  // max(sunCos, 0)^48 by squaring (x^3, then four squarings): pow() is a log and an exp per
  // pixel on a CPU device.
  const float c = max(sunCos, 0.0f);
  float glow = c * c * c;
  glow *= glow;
  glow *= glow;
  glow *= glow;
  glow *= glow;
  glow *= 0.15f;
  const float disc = smoothstep(0.99985f, 0.99995f, sunCos) * discScale;
  return colour + sunColour * (glow + disc);
}

SHADER_NAMESPACE_END

#endif
