// The cloud shadow map bound as a sampled image (a linear, clamped sampler), with the reads
// fxcontracts/cloud_shadow.h asks its includer for. A shader defines CLOUD_SHADOW_MAP_BINDING (its
// descriptor binding) and includes this instead of writing the two reads itself.
#ifndef FX_CLOUD_SHADOW_SAMPLED_GLSL
#define FX_CLOUD_SHADOW_SAMPLED_GLSL

layout(binding = CLOUD_SHADOW_MAP_BINDING) uniform sampler2D cloudShadowMap;
vec4 fetchCloudShadow(vec2 uv) { return textureLod(cloudShadowMap, uv, 0.0); }
vec4 gatherCloudShadowTerrain(vec2 uv) { return textureGather(cloudShadowMap, uv, 3); }
#include "fxcontracts/cloud_shadow.h"

#endif
