#version 460
// The aerial-perspective froxels (Hillaire 2020, section 5.4), every frame: for each froxel
// column (a cell of the screen) the march along its view ray through the slices
// (atmosphere_types.h: slice s at range * ((s + 0.5) / slices)^2), storing at each slice the
// radiance the air between the camera and there scatters towards the camera (unit sun
// illuminance; single scattering with its phases, plus the multiple-scattering LUT) and the
// transmittance (mean of the channels). Past the ground or the top of the atmosphere the
// values stay as they were there. With a cloud shadow map (kFlagCloudShadow) the sun's single
// scattering is taken where the map hides the sun (by cloud or terrain): light shafts.
// Inputs: uniforms, transmittance and multiple-scattering LUTs, the cloud shadow map and its
// parameters. Output: the 3D texture (RGBA16F, rgb in-scattering, a transmittance).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
// The model's single scattering asks what shadows the air (defined below).
float cloudSunVisibility(vec3 relative);
#define ATMOSPHERE_SUN_VISIBILITY(relative) cloudSunVisibility(relative)
#include "atmosphere_model.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kBindingMultiScattering) uniform sampler2D multiScatteringLut;
layout(binding = kBindingTarget, rgba16f) uniform writeonly image3D target;

#define CLOUD_SHADOW_MAP_BINDING kBindingCloudShadow
#include "fxcontracts/cloud_shadow_sampled.glsl"
// Indexed like the uniforms (atmosphere_uniforms.glsl), read in place.
layout(binding = kBindingCloudShadowParameters, std140) uniform CloudShadow {
  CloudShadowParameters cloudShadow[1];
};

// The sun the cloud shadow map lets through to a point of the air (1 without a map): the
// clouds' transmittance times the terrain's light.
float cloudSunVisibility(vec3 relative) {
  float visibility = 1.0;
  for (int i = 0; i < ((u.flags & kFlagCloudShadow) != 0u ? 1 : 0); ++i) {
    const uint slot = uniformsIndex;
    vec4 uv01;
    vec4 uv23;
    CLOUD_SHADOW_COORDINATES(cloudShadow[slot], relative, uv01, uv23);
    const vec2 sun = cloudShadowAt(cloudShadow[slot].info, uv01, uv23,
                                   cloudShadow[slot].info.z + relative.y, kCloudShadowBoth);
    visibility = sun.x * sun.y;
  }
  return visibility;
}

vec3 sampleTransmittance(vec2 uv) { return textureLod(transmittanceLut, uv, 0.0).rgb; }
vec3 sampleMultiScattering(vec2 uv) { return textureLod(multiScatteringLut, uv, 0.0).rgb; }

void main() {
  loadUniforms();
  const uvec2 column = gl_GlobalInvocationID.xy;
  const uvec3 froxels = u.aerialPerspectiveSize.xyz;
  if (any(greaterThanEqual(column, froxels.xy))) return;
  const AtmosphereModel a = modelOf(u);
  const vec3 direction = viewDirection(vec2(column) + 0.5, vec2(froxels.xy));
  const vec3 origin = vec3(0.0, u.cameraRadius, 0.0);
  // Where the ray leaves the air (the ground or the top); from above, where it enters.
  const float r = u.cameraRadius;
  const float mu = direction.y;
  float enter = 0.0;
  if (r > a.topRadius) enter = max(raySphere(r, mu, a.topRadius), 0.0);
  const float toGround = rayHitsGround(r, mu, a) ? raySphere(r, mu, a.bottomRadius) : -1.0;
  const float toTop = raySphere(r, mu, a.topRadius);
  const float leave = toGround >= 0.0 ? toGround : max(toTop, 0.0);
  Scattering s = noScattering();
  float marched = 0.0;
  for (uint slice = 0u; slice < froxels.z; ++slice) {
    const float w = (float(slice) + 0.5) / float(froxels.z);
    const float distance = u.aerialPerspectiveRange * w * w;
    const float t0 = clamp(marched, enter, leave);
    const float t1 = clamp(distance, enter, leave);
    scatterAlong(s, origin, direction, u.sunDirection, t0, t1, u.aerialPerspectiveSize.w,
                 kPhaseAtmosphere, 1u, float(u.multiScatteringSize), a);
    marched = distance;
    const float transmittance = dot(s.transmittance, vec3(1.0 / 3.0));
    imageStore(target, ivec3(column, slice), vec4(s.luminance, transmittance));
  }
}
