#version 460
#extension GL_GOOGLE_include_directive : require
// Water fogged, under cloud shadows (water_fragment.glsl).
#define WATER_CLOUD_SHADOWS
#include "water_fragment.glsl"
