#version 460
// Tonemap pass: HDR scene radiance (RGBA16F, linear) -> display target (sRGB 8-bit; the
// hardware encodes). Inputs: binding 0 the HDR image (same size as the target), push constants
// TonemapConstants. Reference: Narkowicz 2015, "ACES Filmic Tone Mapping Curve".
#extension GL_GOOGLE_include_directive : require
#include "tonemap_operator.h"

layout(binding = kTonemapHdrBinding) uniform sampler2D hdrImage;
layout(push_constant) uniform Constants { TonemapConstants constants; };

layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  const vec3 hdr = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
  const vec3 color = constants.debugView == 1u ? clamp(hdr, 0.0f, 1.0f)
                                               : tonemap(hdr, constants.exposure);
  outColor = vec4(color, 1.0f);
}
