#version 460
// Terrain shading in a scene with an atmosphere: the surface lit, seen through the aerial
// perspective its vertices read (terrain_hazed.vert).
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
#include "terrain_lighting.glsl"
layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inColor;
layout(location = 2) in vec4 inHaze;
layout(location = 0) out vec4 outColor;

void main() {
  outColor = vec4(terrainLit(inColor, inNormal) * inHaze.a + inHaze.rgb, 1.0f);
}
