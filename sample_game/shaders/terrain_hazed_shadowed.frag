#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain in a scene with an atmosphere, under cloud shadows (terrain_fragment.glsl).
#define TERRAIN_HAZED
#define TERRAIN_CLOUD_SHADOWS
#include "terrain_fragment.glsl"
