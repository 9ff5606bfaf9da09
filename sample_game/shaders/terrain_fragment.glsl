// The terrain's fragment stage: the surface made finer than the mesh (terrain_material.h:
// detail normals, rock and snow by slope and altitude, finer still close up; a user mesh's base
// colour texture when it has one), lit by the sun (with
// TERRAIN_CLOUD_SHADOWS through the clouds and past the terrain itself, as the terrain's
// sunlight map holds it) and the sky, then hazed by the aerial perspective its vertices read
// (TERRAIN_HAZED: a scene with an atmosphere) or, the cheap alternative, fogged towards the
// gradient sky behind the fragment.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"

layout(binding = kTerrainFrameBinding, std140) uniform Frame { SceneFrame frame; };
#include "terrain_lighting.glsl"
layout(location = 0) in vec3 inRelative;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 4) in vec4 inFlashLight;  // terrain_vertex.glsl
layout(location = 5) in vec2 inUv;
layout(location = 0) out vec4 outColor;
// A storm's scene: the brightest flash in progress lights the ground (none: no such code).
layout(constant_id = 0) const bool kLightning = false;
// A user's mesh with a base colour texture: it colours the ground (none: a one-texel stand-in is
// bound and never read).
layout(constant_id = 1) const bool kTextured = false;
// The close-up detail (TerrainDescription::closeDetail; off: compiled out, the ground as a pixel
// covering 15 m of it sees it).
layout(constant_id = 2) const bool kCloseDetail = true;
layout(binding = kTerrainBaseColourBinding) uniform sampler2D baseColour;

#ifdef TERRAIN_HAZED
layout(location = 3) in vec4 inHaze;
#endif

#ifdef TERRAIN_CLOUD_SHADOWS
layout(binding = kTerrainSunlightBinding) uniform sampler2D sunlightMap;  // terrain_sunlight_map.h
#endif

// The share of the sun the fragment sees: what the clouds let through, and none where the
// terrain itself hides the sun, both from the terrain's sunlight map (made from the clouds'
// shadow map each frame).
float sunVisibility() {
#ifdef TERRAIN_CLOUD_SHADOWS
  return textureLod(sunlightMap, terrainSunlightUv(inRelative.xz, frame.sunlightMap), 0.0f).r;
#else
  return 1.0;
#endif
}

void main() {
  // The surface finer than the mesh: its detail (world metres), normal and materials, and close
  // up finer still, as far as the pixel's footprint on the ground (m) resolves. Ground seen at a
  // grazing angle is foreshortened along one side of the pixel: the footprint is the shorter side,
  // up to half the longer (an octave then has at least two pixels a wavelength along it, as a
  // 2x anisotropic texture filter would keep), so the ground ahead is not smeared.
  const vec3 world = frame.cameraPosition.xyz + inRelative;
  const vec4 detail = terrainDetail(vec2(world.x, world.z));
  vec3 normal = terrainDetailNormal(inNormal, detail);
  const vec2 materials = terrainMaterialWeights(normal, world.y, detail, frame.terrain);
  const float across = length(dFdx(inRelative));
  const float down = length(dFdy(inRelative));
  const float footprint = max(min(across, down), 0.5f * max(across, down));
  const vec4 close =
      kCloseDetail ? terrainCloseDetail(world, normal, materials, footprint) : vec4(0.0f);
  if (close.xyz != vec3(0.0f)) normal = normalize(normal + close.xyz);
  // A textured mesh keeps its artist's colours (glTF: the vertex colour times the texture); the
  // generated terrain is painted rock and snow by slope and altitude. Both get the fine detail.
  const vec3 paint = kTextured ? inColor * texture(baseColour, inUv).rgb
                               : terrainPaint(inColor, materials, frame.terrain);
  // (Without the close-up detail: the tint a pixel covering 15 m or more has, 1.)
  const vec3 tint =
      kCloseDetail ? terrainDetailTint(detail, close.w, materials, footprint) : vec3(1.0f);
  const vec3 albedo = paint * tint;
  vec3 lit = terrainLit(albedo, normal, sunVisibility());
  if (kLightning) {
    // The brightest lightning flash in progress (its falloff per vertex: terrain_vertex.glsl):
    // its direct light as the surface faces it, and its sky light from the sky above, whichever
    // way the surface faces the flash ((1 + n.y) / 2 of the sky).
    const float direct = max(dot(normal, inFlashLight.xyz), 0.0f);
    const float sky = inFlashLight.w * (0.5f + 0.5f * normal.y);
    lit += albedo * frame.flashRadiance.rgb * (direct + sky);
  }
#ifdef TERRAIN_HAZED
  outColor = vec4(lit * inHaze.a + inHaze.rgb, 1.0f);
#else
  const float distance = length(inRelative);
  const vec3 view = inRelative / max(distance, 1e-3f);
  const vec3 sky =
      skyRadiance(view, frame.sunDirection.xyz, frame.skyZenith.rgb, frame.skyHorizon.rgb,
                  frame.skyGround.rgb, frame.sunIlluminance.rgb, 0.0f);
  const float transmittance = exp(-frame.fog.x * distance);
  outColor = vec4(mix(sky, lit, transmittance), 1.0f);
#endif
}
