#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain vertices in a scene with fog, under cloud shadows (terrain_vertex.glsl).
#define TERRAIN_CLOUD_SHADOWS
#include "terrain_vertex.glsl"
