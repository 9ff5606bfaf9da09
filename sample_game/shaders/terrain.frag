#version 460
// Terrain shading, the cheap alternative for scenes without an atmosphere: the surface lit, then
// exponential distance fog towards the gradient sky behind the fragment.
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
#include "terrain_lighting.glsl"
layout(location = 0) in vec3 inRelative;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec4 outColor;

void main() {
  const vec3 lit = terrainLit(inColor, inNormal);
  const float distance = length(inRelative);
  const vec3 view = inRelative / max(distance, 1e-3f);
  const vec3 sky = skyRadiance(view, frame.sunDirection.xyz, frame.skyZenith.rgb,
                               frame.skyHorizon.rgb, frame.skyGround.rgb,
                               frame.sunIlluminance.rgb, 0.0f);
  const float transmittance = exp(-frame.fog.x * distance);
  outColor = vec4(mix(sky, lit, transmittance), 1.0f);
}
