#version 460
// The terrain's sunlight map (compute; terrain_sunlight.h): one invocation per texel of the
// rows this frame refreshes. Each texel is the terrain's surface at the heightfield texel's
// centre; it reads the clouds' transmittance and the terrain's own shadow there from the cloud
// shadow map, as any receiver does (fxcontracts/cloud_shadow.h), and stores their product.
// Inputs (bindings.h): the heightfield (R32F or R16F altitudes, m), the cloud shadow map, its
// parameters (this frame's camera); push constants TerrainSunlightConstants. Output: the map.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "terrain_sunlight_map.h"

layout(local_size_x = kTerrainSunlightGroupSize, local_size_y = kTerrainSunlightGroupSize) in;

layout(binding = kSunlightHeightfieldBinding) uniform sampler2D heightfield;
#define CLOUD_SHADOW_MAP_BINDING kSunlightCloudShadowBinding
#include "fxcontracts/cloud_shadow_sampled.glsl"
layout(binding = kSunlightShadowParametersBinding, std140) uniform CloudShadow {
  CloudShadowParameters cloudShadow;
};
layout(binding = kSunlightMapBinding, r16f) uniform writeonly image2D sunlight;
layout(push_constant) uniform Constants { TerrainSunlightConstants c; };

void main() {
  const uvec2 texel = uvec2(gl_GlobalInvocationID.x, c.firstRow + gl_GlobalInvocationID.y);
  if (texel.x >= c.resolution || gl_GlobalInvocationID.y >= c.rowCount) return;
  const float altitude = texelFetch(heightfield, ivec2(texel), 0).r;
  const vec2 flatOffset = c.cornerRelative + (vec2(texel) + 0.5f) * c.texelMetres;
  const vec3 relative = vec3(flatOffset.x, altitude - cloudShadow.info.z, flatOffset.y);
  vec4 uv01;
  vec4 uv23;
  CLOUD_SHADOW_COORDINATES(cloudShadow, relative, uv01, uv23);
  const vec2 sun = cloudShadowAt(cloudShadow.info, uv01, uv23, altitude, kCloudShadowBoth);
  imageStore(sunlight, ivec2(texel), vec4(sun.x * sun.y));
}
