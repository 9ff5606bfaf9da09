#version 460
#extension GL_GOOGLE_include_directive : require
// Water in a scene with an atmosphere, under cloud shadows (water_fragment.glsl).
#define WATER_HAZED
#define WATER_CLOUD_SHADOWS
#include "water_fragment.glsl"
