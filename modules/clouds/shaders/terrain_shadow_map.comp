#version 460
// The terrain's shadow in the cloud shadow map (compute): after cloud_shadow_map.comp has made
// a cascade, one invocation per texel walks the texel's sun ray over the host's heightfield
// (terrain_shadow_march.h) and writes the altitude below which the terrain hides the sun into
// the texel's alpha (fxcontracts/cloud_shadow.h), keeping the clouds' channels.
// Inputs: binding 0 the heightfield (altitude in metres, sampled linearly, clamped); push
// constants TerrainShadowConstants (the cascade and the heightfield's placement). Output: 1 the
// cascade atlas (read and written in place).
#extension GL_GOOGLE_include_directive : require

#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(binding = kTerrainShadowHeight) uniform sampler2D heightfield;
layout(binding = kTerrainShadowMap, rgba16f) uniform image2D shadowMap;
layout(push_constant) uniform Constants { TerrainShadowConstants t; };

float fetchTerrainHeight(vec2 uv) { return textureLod(heightfield, uv, 0.0f).r; }

#include "terrain_shadow_march.h"

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, uvec2(t.cascade.resolution)))) return;
  const ivec2 atlas = ivec2(t.cascade.cascade * t.cascade.resolution + texel.x, texel.y);
  vec4 value = imageLoad(shadowMap, atlas);
  value.a = terrainShadowTexel(t, texel);
  imageStore(shadowMap, atlas, value);
}
