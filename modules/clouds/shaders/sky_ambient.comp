#version 460
// The ambient colours of the frame, written into the uniform buffer. One workgroup.
//  - From a host sky-radiance image (equirectangular: u = azimuth, v = 0 at the zenith), when
//    there is one: ambientTop = cosine-weighted mean of the upper hemisphere (what lights cloud
//    tops), ambientBottom = mean over the band up to 10 degrees above the horizon (the horizon's
//    radiance). Without one, the host's ambientTop and ambientBottom stand.
//  - With the ground's albedo, cloud bases see the ground below them (groundLitBaseRadiance()):
//    lit by the sun where the clouds do not shade it, a share read as the mean sun
//    transmittance of the shadow map's finest cascade (the ground around the camera), and by
//    the sky.
#extension GL_GOOGLE_include_directive : require
#include "cloud_lighting.h"
#include "cloud_math.h"
#include "cloud_types.h"

layout(local_size_x = kSkyAmbientLanes) in;
layout(binding = kSkyAmbientUniforms, std430) buffer Uniforms { CloudUniforms u; };
layout(binding = kSkyAmbientSky) uniform sampler2D sky;
#define CLOUD_SHADOW_MAP_BINDING kSkyAmbientShadowMap
#include "fxcontracts/cloud_shadow_sampled.glsl"
#include "cloud_ground_sunlit.glsl"
layout(push_constant) uniform Constants { AmbientConstants constants; };
layout(binding = kSkyAmbientLastSkyLight, std430) readonly buffer LastSkyLight {
  SkyLightMeasures lastSkyLight;
};

// Reduced over the lanes: the sky's upper hemisphere (rgb, weight), its horizon band (rgb,
// count) and the ground's sunlit share (sum in x, count in y).
shared vec4 topSum[kSkyAmbientLanes];
shared vec4 bottomSum[kSkyAmbientLanes];
shared vec2 sunlitSum[kSkyAmbientLanes];

void main() {
  const uint lane = gl_LocalInvocationID.x;
  const bool fromSky = (constants.flags & kAmbientFromSkyImage) != 0u;
  const bool fromShadow = (constants.flags & kAmbientGroundShadow) != 0u;
  // The last frame's sky light gives the horizon band: the host's is not sampled.
  const bool fromSkyLight = (constants.flags & kAmbientFromSkyLight) != 0u;
  const bool horizonFromSky = fromSky && !fromSkyLight;
  vec4 top = vec4(0.0f);
  vec4 bottom = vec4(0.0f);
  vec2 sunlit = vec2(0.0f);
  // kSkyAmbientLanes x kSkyAmbientSamples (64 x 16): a stratified 32 x 32 grid over azimuth
  // and elevation, and over the shadow map's finest cascade.
  // The horizon band reads no lower than the upper half's last row of texels: the linear filter
  // would blend the ground's first row into the band's lowest samples.
  const float lowestSkyV = 0.5f - 0.5f / float(textureSize(sky, 0).y);
  for (uint k = 0u; k < kSkyAmbientSamples; ++k) {
    const uint index = lane * kSkyAmbientSamples + k;
    const vec2 cell = (vec2(float(index % 32u), float(index / 32u)) + 0.5f) / 32.0f;
    if (fromSky) {
      const float elevation = cell.y * 0.5f * kPi;           // radians above the horizon
      const float weight = sin(elevation) * cos(elevation);  // cos(zenith) dOmega
      const vec3 radiance = textureLod(sky, vec2(cell.x, 0.5f - elevation / kPi), 0.0f).rgb;
      top += vec4(radiance * weight, weight);
    }
    if (horizonFromSky) {
      const vec2 band = vec2(cell.x, min(0.5f - (cell.y * 10.0f / 180.0f), lowestSkyV));
      bottom += vec4(textureLod(sky, band, 0.0f).rgb, 1.0f);
    }
    if (fromShadow) {
      sunlit += vec2(groundSunlit(constants.shadowCascades, constants.shadowTexels, cell), 1.0f);
    }
  }
  topSum[lane] = top;
  bottomSum[lane] = bottom;
  sunlitSum[lane] = sunlit;
  barrier();
  for (uint stride = kSkyAmbientLanes / 2u; stride > 0u; stride >>= 1u) {
    if (lane < stride) {
      topSum[lane] += topSum[lane + stride];
      bottomSum[lane] += bottomSum[lane + stride];
      sunlitSum[lane] += sunlitSum[lane + stride];
    }
    barrier();
  }
  if (lane != 0u) return;
  if (fromSky) u.ambientTop = topSum[0].rgb / max(topSum[0].w, 1e-6f);
  if (horizonFromSky) u.ambientBottom = bottomSum[0].rgb / max(bottomSum[0].w, 1e-6f);
  // What lights the ground under the clouds, and the horizon band above it.
  vec3 groundSky = u.ambientTop;
  if (fromSkyLight) {
    groundSky = lastSkyLight.upperIrradianceOverPi.rgb;
    u.ambientBottom = lastSkyLight.horizon.rgb;
  }
  if ((constants.flags & kAmbientGroundLight) != 0u) {
    // Without the shadow map the ground is taken as all sunlit.
    const float sunlitShare = fromShadow ? sunlitSum[0].x / max(sunlitSum[0].y, 1.0f) : 1.0f;
    u.ambientBottom = groundLitBaseRadiance(u.ambientBottom, groundSky, constants.groundAlbedo,
                                            u.sunIlluminance, u.sunDirection.y, sunlitShare);
  }
}
