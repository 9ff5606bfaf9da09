#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain vertices in a scene with fog, without cloud shadows (terrain_vertex.glsl).
#include "terrain_vertex.glsl"
