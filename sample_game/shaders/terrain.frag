#version 460
#extension GL_GOOGLE_include_directive : require
// Terrain in a scene with fog, without cloud shadows (terrain_fragment.glsl).
#include "terrain_fragment.glsl"
