#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain in a scene with an atmosphere, without cloud shadows (terrain_fragment.glsl).
#define TERRAIN_HAZED
#include "terrain_fragment.glsl"
