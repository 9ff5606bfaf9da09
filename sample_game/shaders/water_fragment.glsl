// The water's fragment stage (water_surface.h): the sky and the clouds reflected by its ripples
// (Fresnel), the sun's glint through the clouds (with WATER_CLOUD_SHADOWS, the terrain's sunlight
// map), the water's body lit by the sun and sky, and the bed drawn before it seen through it,
// then hazed like the terrain: by the aerial perspective per fragment with WATER_HAZED (a scene
// with an atmosphere, whose sky map it reflects: the clouds' sky light when they make one), or
// by the fog towards the gradient sky. It writes depth: the clouds are marched to the water's
// surface, so clouds in front of it composite over it and none beyond it show through.
// In a storm's lightning variant (kLightning) the brightest flash in progress lights it as it
// lights the terrain (fxcontracts/lightning_light.h): the cloud deck its ripples reflect glows
// with the flash's sky light, and its body takes that and the glowing core's direct light.
// Blending: colour + destination x alpha (alpha: the share of the bed that shows).
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"
#include "fxcontracts/lightning_light.h"

layout(binding = kWaterFrameBinding, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) in vec3 inRelative;
layout(location = 0) out vec4 outColor;
// A storm's scene: the brightest flash in progress lights the water (none: no such code).
layout(constant_id = 0) const bool kLightning = false;

#ifdef WATER_HAZED
#include "fxcontracts/aerial_perspective.glsl"
layout(binding = kWaterHazeBinding) uniform sampler3D aerialPerspective;
// The sky around the camera, equirectangular (u the azimuth from +x towards +z, v = 0 at the
// zenith, 0.5 at the horizon): the clouds' sky light, or the atmosphere's clear sky.
layout(binding = kWaterSkyBinding) uniform sampler2D skyMap;
#endif

#ifdef WATER_CLOUD_SHADOWS
layout(binding = kWaterSunlightBinding) uniform sampler2D sunlightMap;  // terrain_sunlight_map.h
#endif

// The share of the sun reaching the water: the clouds' (and the terrain's) shadow as the
// terrain's sunlight map holds it at the ground there, the bed or the shore around the water.
float sunVisibility(vec3 relative) {
#ifdef WATER_CLOUD_SHADOWS
  return textureLod(sunlightMap, terrainSunlightUv(relative.xz, frame.sunlightMap), 0.0f).r;
#else
  return 1.0f;
#endif
}

// The sky's radiance along `direction` (above the horizon).
vec3 skyAlong(vec3 direction) {
#ifdef WATER_HAZED
  const float kPi = 3.14159265f;
  // The sampler repeats (the azimuth wraps); the elevation keeps half a texel inside the upper
  // half, so the filter reads neither the nadir's row across the zenith nor the ground's below
  // the horizon.
  const float halfTexel = 0.5f / float(textureSize(skyMap, 0).y);
  const float u = atan(direction.z, direction.x) / (2.0f * kPi);
  const float v = clamp(acos(clamp(direction.y, -1.0f, 1.0f)) / kPi, halfTexel, 0.5f - halfTexel);
  return textureLod(skyMap, vec2(fract(u), v), 0.0f).rgb;
#else
  return skyRadiance(direction, frame.sunDirection.xyz, frame.skyZenith.rgb, frame.skyHorizon.rgb,
                     frame.skyGround.rgb, frame.sunIlluminance.rgb, 0.0f);
#endif
}

void main() {
  // The surface where this pixel's ray meets the water's plane, from the ray itself: exact
  // however large the triangles (kWaterReachMetres) whose interpolation gave inRelative.
  const vec2 ndc = gl_FragCoord.xy / vec2(frame.extent.xy) * 2.0f - 1.0f;
  const vec3 ray = normalize(frame.cameraForward.xyz +
                             ndc.x * frame.cameraRight.w * frame.cameraRight.xyz -
                             ndc.y * frame.cameraUp.w * frame.cameraUp.xyz);
  const float height = frame.water.x - frame.cameraPosition.y;
  const vec3 relative = ray.y < 0.0f && height < 0.0f ? ray * (height / ray.y) : inRelative;
  const float distance = length(relative);
  const vec3 toViewer = -relative / max(distance, 1e-3f);

  // The pixel's footprint on the water (m): its longer side, since a ripple's crests run every
  // way and one a pixel cannot resolve along the view would alias into bands across it.
  const float footprint = max(length(dFdx(relative)), length(dFdy(relative)));
  const vec3 ripples =
      waterRipples(relative.xz, frame.waterPhases, frame.waterPhasesHigh, footprint);
  const vec3 normal = waterNormal(ripples.xy);
  const float cosView = max(dot(normal, toViewer), 1e-3f);
  const float fresnel = waterFresnel(cosView);

  // What the ripples reflect: the sky (kept above the horizon: a ripple's reflection that dips
  // below it would see the far water, which reflects the horizon's sky in turn).
  // (Never the zero vector, whose normalisation would be NaN.)
  vec3 reflected = reflect(-toViewer, normal);
  reflected.y = max(reflected.y, 1e-4f);
  reflected = normalize(reflected);
  vec3 sky = skyAlong(reflected);

  const vec3 sun = frame.sunDirection.xyz;
  const vec3 sunlight = frame.sunIlluminance.rgb * sunVisibility(relative);
  const float kInvPi = 0.318309886f;
  const vec3 glint = sunlight * waterGlint(normal, toViewer, sun, ripples.z);
  // The water's body: its albedo lit by the sun and by the sky's light from above.
  vec3 skyAbove = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5f);
  vec3 flashDirect = vec3(0.0f);
  if (kLightning) {
    // The flash's sky light here glows in the reflected sky and in the sky above the body; its
    // core lights the body directly, pi L (core / d)^2 on the level surface (Lambert: albedo /
    // pi of it), as terrain_vertex.glsl gives the ground.
    const float core = flashCoreMetres(frame.flash.w);
    const vec3 toFlash = frame.flash.xyz - relative;
    const float distanceSquared = dot(toFlash, toFlash);
    const float d2 = max(distanceSquared, core * core);
    const vec3 flashSky =
        frame.flashRadiance.rgb * flashSkyLightSquared(distanceSquared, frame.flash.w);
    sky += flashSky;
    skyAbove += flashSky;
    const float cosineOverDistance = max(toFlash.y, 0.0f) * inversesqrt(d2);
    flashDirect = frame.flashRadiance.rgb * (core * core / d2 * cosineOverDistance);
  }
  const vec3 body =
      frame.waterColour.rgb * (sunlight * max(sun.y, 0.0f) * kInvPi + skyAbove + flashDirect);

  // The bed shows through where there is one (the terrain's extent) by the water's clarity,
  // fading out over the last kilometre to its edge, where the sea beyond it is deep.
  const vec2 world = frame.cameraPosition.xz + relative.xz;
  const vec2 inside = min(world - frame.waterBed.xy, frame.waterBed.zw - world);
  const float overBed = smoothstep(0.0f, 1000.0f, min(inside.x, inside.y));
  const float bed = overBed * waterBedShare(frame.water.y, toViewer.y);
  const vec3 surface = fresnel * sky + glint + (1.0f - fresnel) * (1.0f - bed) * body;
  const float transmitted = (1.0f - fresnel) * bed;

#ifdef WATER_HAZED
  const vec2 uv = gl_FragCoord.xy / vec2(frame.extent.xy);
  const vec4 haze = aerialPerspectiveAt(aerialPerspective, uv, distance, frame.fog.y, frame.fog.z);
  const vec3 inScattered = haze.rgb * frame.sunAboveAir.rgb;
  const float airTransmittance = haze.a;
#else
  const vec3 fogSky = skyRadiance(-toViewer, sun, frame.skyZenith.rgb, frame.skyHorizon.rgb,
                                  frame.skyGround.rgb, frame.sunIlluminance.rgb, 0.0f);
  const float airTransmittance = exp(-frame.fog.x * distance);
  const vec3 inScattered = fogSky * (1.0f - airTransmittance);
#endif
  // The bed drawn before the water is already hazed over about the same distance: what shows of
  // it keeps its haze, and the rest of the pixel takes the water's.
  outColor = vec4(surface * airTransmittance + inScattered * (1.0f - transmitted), transmitted);
}
