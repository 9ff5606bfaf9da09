#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain vertices in a scene with an atmosphere, without cloud shadows (terrain_vertex.glsl).
#define TERRAIN_HAZED
#include "terrain_vertex.glsl"
