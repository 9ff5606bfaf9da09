#version 460
// HUD text: the font atlas's coverage times the vertex colour, alpha-blended over the display.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"

layout(binding = kHudFontBinding) uniform sampler2D fontAtlas;
layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() { outColor = inColor * texture(fontAtlas, inUv); }
