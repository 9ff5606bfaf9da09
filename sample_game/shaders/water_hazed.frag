#version 460
#extension GL_GOOGLE_include_directive : require
// Water in a scene with an atmosphere (water_fragment.glsl).
#define WATER_HAZED
#include "water_fragment.glsl"
