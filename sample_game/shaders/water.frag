#version 460
#extension GL_GOOGLE_include_directive : require
// Water in a scene without an atmosphere: fogged (water_fragment.glsl).
#include "water_fragment.glsl"
