#version 460
// The sky light (Settings::skyLight): the host's sky with the clouds in it, as an
// equirectangular radiance map laid out as the host's sky image (kSkyLightWidth x
// kSkyLightHeight: u = azimuth, v = 0 at the zenith, 0.5 at the horizon, 1 at the nadir), and
// what the host lights its world with measured from it (SkyLightMeasures). One workgroup.
//  - The upper half: the host's sky seen through the clouds marched towards each texel
//    (cloud_march.comp's sky-light pass, a part of them a frame): sky x transmittance + the
//    clouds' radiance. Without cloud in the sky this frame, the host's sky.
//  - The lower half: the host's; but with the ground's albedo, more than 10 degrees below the
//    horizon the ground as groundRadiance() lights it from this map's upper half and the sun on
//    the share of the ground out of the clouds' shadow: under an overcast the ground is lit by the
//    clouds, not by the clear sky. Nearer the horizon the air in front of the ground is the
//    host's.
//  - For a meter at the camera (SkyLightMeasures::viewpoint): the sun's transmittance through
//    the clouds at the camera and the share of the ground around it in the sun, read from the
//    shadow map, and the altitudes the map holds for.
// Inputs: the frame's uniforms, the host's sky image, the clouds marched, the shadow map and its
// parameters. Outputs: the map (RGBA16F), the measures (a storage buffer the host reads).
#extension GL_GOOGLE_include_directive : require
#include "cloud_lighting.h"
#include "cloud_math.h"
#include "cloud_types.h"

layout(local_size_x = kSkyLightLanes) in;
layout(push_constant) uniform Constants { SkyLightConstants constants; };
#define CLOUDS_FRAME_UNIFORMS_INDEX constants.frameUniformsIndex
#include "frame_uniforms.glsl"
layout(binding = kSkyLightHostSky) uniform sampler2D hostSky;
layout(binding = kSkyLightClouds, rgba16f) uniform readonly image2D marchedClouds;
layout(binding = kSkyLightMap, rgba16f) uniform writeonly image2D skyMap;
layout(binding = kSkyLightMeasures, std430) buffer Measures { SkyLightMeasures measures; };
#define CLOUD_SHADOW_MAP_BINDING kSkyLightShadowMap
#include "fxcontracts/cloud_shadow_sampled.glsl"
#include "cloud_ground_sunlit.glsl"
// Indexed like frame_uniforms.glsl's block, for the same reason.
layout(binding = kSkyLightShadowParameters, std140) uniform ShadowMap {
  MarchShadowMap shadowMap[1];
};

// Per lane, then reduced: radiance x weight (rgb) and the weight (a), per region; the ground's
// sunlit share (sum, count).
shared vec4 upperSum[kSkyLightLanes];
shared vec4 clearSum[kSkyLightLanes];
shared vec4 zenithSum[kSkyLightLanes];
shared vec4 horizonSum[kSkyLightLanes];
shared vec4 lowerSum[kSkyLightLanes];
shared vec2 sunlitSum[kSkyLightLanes];

// Samples of the shadow map's finest cascade per lane (a 32 x 32 grid over it in all).
const uint kSunlitSamples = 1024u / kSkyLightLanes;
// The horizon band's height, and the depression below which the lower half is the ground.
const float kTenDegreesRadians = kPi / 18.0f;

// The direction (world, unit) and elevation (radians) of the map's texel.
vec3 texelDirection(uvec2 texel, out float elevation) {
  const vec2 uv = (vec2(texel) + 0.5f) / vec2(kSkyLightWidth, kSkyLightHeight);
  const float azimuth = 2.0f * kPi * uv.x;
  elevation = kPi * (0.5f - uv.y);
  return vec3(cos(azimuth) * cos(elevation), sin(elevation), sin(azimuth) * cos(elevation));
}

vec3 hostSkyAt(uvec2 texel) {
  return textureLod(hostSky, (vec2(texel) + 0.5f) / vec2(kSkyLightWidth, kSkyLightHeight), 0.0f)
      .rgb;
}

void reduce(uint lane) {
  barrier();
  for (uint stride = kSkyLightLanes / 2u; stride > 0u; stride >>= 1u) {
    if (lane < stride) {
      upperSum[lane] += upperSum[lane + stride];
      clearSum[lane] += clearSum[lane + stride];
      zenithSum[lane] += zenithSum[lane + stride];
      horizonSum[lane] += horizonSum[lane + stride];
      lowerSum[lane] += lowerSum[lane + stride];
      sunlitSum[lane] += sunlitSum[lane + stride];
    }
    barrier();
  }
}

vec3 meanOf(vec4 sum) { return sum.rgb / max(sum.a, 1e-6f); }

void main() {
  loadFrameUniforms();
  const uint lane = gl_LocalInvocationID.x;
  const bool marched = (constants.flags & kSkyLightCloudsMarched) != 0u;
  const bool groundShadow = (constants.flags & kSkyLightGroundShadow) != 0u;
  const uint halfTexels = kSkyLightWidth * kSkyLightHeight / 2u;

  // The upper half, and the ground's share in the sun.
  vec4 upper = vec4(0.0f), clear = vec4(0.0f), zenith = vec4(0.0f), horizon = vec4(0.0f);
  for (uint index = lane; index < halfTexels; index += kSkyLightLanes) {
    const uvec2 texel = uvec2(index % kSkyLightWidth, index / kSkyLightWidth);
    float elevation;
    texelDirection(texel, elevation);
    const vec3 sky = hostSkyAt(texel);
    const vec4 cloud = marched ? imageLoad(marchedClouds, ivec2(texel)) : vec4(0, 0, 0, 1);
    const vec3 radiance = sky * cloud.a + cloud.rgb;
    imageStore(skyMap, ivec2(texel), vec4(radiance, 1.0f));
    // An equirectangular texel's solid angle goes with cos(elevation); the irradiance of a
    // surface facing up weights it with sin(elevation) more.
    const float solidAngle = cos(elevation);
    const float cosine = solidAngle * sin(elevation);
    upper += vec4(radiance, 1.0f) * cosine;
    clear += vec4(sky, 1.0f) * cosine;
    if (elevation >= kPi / 3.0f) zenith += vec4(radiance, 1.0f) * solidAngle;
    if (elevation <= kTenDegreesRadians) horizon += vec4(radiance, 1.0f) * solidAngle;
  }
  // With this frame's shadow map: the ground's share in the sun, for the ground texels (with its
  // albedo) and the meter (SkyLightMeasures::viewpoint).
  const bool mapped = (constants.flags & kSkyLightSunAtCamera) != 0u;
  vec2 sunlit = vec2(0.0f);
  if (mapped) {
    for (uint k = 0u; k < kSunlitSamples; ++k) {
      const uint index = lane * kSunlitSamples + k;
      const vec2 cell = (vec2(float(index % 32u), float(index / 32u)) + 0.5f) / 32.0f;
      sunlit += vec2(groundSunlit(constants.shadowCascades, constants.shadowTexels, cell), 1.0f);
    }
  }
  upperSum[lane] = upper;
  clearSum[lane] = clear;
  zenithSum[lane] = zenith;
  horizonSum[lane] = horizon;
  lowerSum[lane] = vec4(0.0f);
  sunlitSum[lane] = sunlit;
  reduce(lane);
  const vec3 skyOverPi = meanOf(upperSum[0]);  // a horizontal surface's irradiance / pi
  const float sunlitShare = mapped ? sunlitSum[0].x / max(sunlitSum[0].y, 1.0f) : 1.0f;
  const vec3 ground = groundRadiance(skyOverPi, constants.groundAlbedo, u.sunIlluminance,
                                     u.sunDirection.y, groundShadow ? sunlitShare : 1.0f);
  const bool groundLit = (constants.flags & kSkyLightGround) != 0u;
  barrier();  // every lane has read the sums before they are reused

  // The lower half.
  vec4 lower = vec4(0.0f);
  for (uint index = halfTexels + lane; index < 2u * halfTexels; index += kSkyLightLanes) {
    const uvec2 texel = uvec2(index % kSkyLightWidth, index / kSkyLightWidth);
    float elevation;
    texelDirection(texel, elevation);
    const vec3 radiance =
        groundLit && elevation < -kTenDegreesRadians ? ground : hostSkyAt(texel);
    imageStore(skyMap, ivec2(texel), vec4(radiance, 1.0f));
    lower += vec4(radiance, 1.0f) * cos(elevation);
  }
  lowerSum[lane] = lower;
  barrier();
  for (uint stride = kSkyLightLanes / 2u; stride > 0u; stride >>= 1u) {
    if (lane < stride) lowerSum[lane] += lowerSum[lane + stride];
    barrier();
  }
  if (lane != 0u) return;
  // The clouds between the camera and the sun (not the terrain: the meter reads what the sky's
  // cover lets through).
  float sunAtCamera = 1.0f;
  if (mapped) {
    vec4 uv01;
    vec4 uv23;
    CLOUD_SHADOW_COORDINATES(shadowMap[0].map, vec3(0.0f), uv01, uv23);
    sunAtCamera = cloudShadowAt(shadowMap[0].map.info, uv01, uv23, u.cameraAltitudeMetres,
                                kCloudShadowClouds)
                      .x;
  }
  measures.viewpoint = vec4(sunAtCamera, skyLightAltitude(u), u.layerTopMetres, sunlitShare);
  const float luminance = dot(skyOverPi, vec3(0.2126f, 0.7152f, 0.0722f));
  measures.upperIrradianceOverPi = vec4(skyOverPi, luminance);
  measures.zenith = vec4(meanOf(zenithSum[0]), 0.0f);
  measures.horizon = vec4(meanOf(horizonSum[0]), 0.0f);
  measures.lower = vec4(meanOf(lowerSum[0]), 0.0f);
  measures.clearIrradianceOverPi = vec4(meanOf(clearSum[0]), 0.0f);
}
