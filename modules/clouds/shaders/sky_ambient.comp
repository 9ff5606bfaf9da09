#version 460
// Derives the ambient colours from a host sky-radiance image (equirectangular: u = azimuth,
// v = 0 at the zenith): ambientTop = cosine-weighted mean of the upper hemisphere (what lights
// cloud tops), ambientBottom = mean over the band up to 10 degrees above the horizon (what
// reaches cloud bases sideways). One workgroup; results are written into the uniform buffer.
#extension GL_GOOGLE_include_directive : require
#include "cloud_math.h"
#include "cloud_types.h"

layout(local_size_x = kSkyAmbientLanes) in;
layout(binding = kSkyAmbientUniforms, std430) buffer Uniforms { CloudUniforms u; };
layout(binding = kSkyAmbientSky) uniform sampler2D sky;

shared vec4 topSum[kSkyAmbientLanes];
shared vec4 bottomSum[kSkyAmbientLanes];

void main() {
  const uint lane = gl_LocalInvocationID.x;
  vec4 top = vec4(0.0f);
  vec4 bottom = vec4(0.0f);
  // kSkyAmbientLanes x kSkyAmbientSamples (64 x 16): a stratified 32 x 32 grid over azimuth
  // and elevation.
  for (uint k = 0u; k < kSkyAmbientSamples; ++k) {
    const uint index = lane * kSkyAmbientSamples + k;
    const float azimuth = (float(index % 32u) + 0.5f) / 32.0f;
    const float e = (float(index / 32u) + 0.5f) / 32.0f;   // [0, 1) over the hemisphere
    const float elevation = e * 0.5f * kPi;                 // radians above the horizon
    const float weight = sin(elevation) * cos(elevation);    // cos(zenith) dOmega
    const vec3 radiance = textureLod(sky, vec2(azimuth, 0.5f - elevation / kPi), 0.0f).rgb;
    top += vec4(radiance * weight, weight);
    const vec2 band = vec2(azimuth, 0.5f - (e * 10.0f / 180.0f));
    bottom += vec4(textureLod(sky, band, 0.0f).rgb, 1.0f);
  }
  topSum[lane] = top;
  bottomSum[lane] = bottom;
  barrier();
  for (uint stride = kSkyAmbientLanes / 2u; stride > 0u; stride >>= 1u) {
    if (lane < stride) {
      topSum[lane] += topSum[lane + stride];
      bottomSum[lane] += bottomSum[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    u.ambientTop = topSum[0].rgb / max(topSum[0].w, 1e-6f);
    u.ambientBottom = bottomSum[0].rgb / max(bottomSum[0].w, 1e-6f);
  }
}
