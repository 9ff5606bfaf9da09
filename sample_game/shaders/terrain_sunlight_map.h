// The terrain's sunlight map, shared by its compute shader and the C++ that places it: per
// texel of the terrain's heightfield (same grid, same texel centres), the share of the sun that
// reaches the surface there past the clouds and past the terrain itself, both read from the
// clouds' shadow map (fxcontracts/cloud_shadow.h). The terrain then lights each fragment with one
// filtered read of it instead of the shadow map's cascade selection per fragment and per vertex.
#ifndef SAMPLE_SHADERS_TERRAIN_SUNLIGHT_MAP_H
#define SAMPLE_SHADERS_TERRAIN_SUNLIGHT_MAP_H

#include "interop.h"

SHADER_NAMESPACE_BEGIN

const uint kTerrainSunlightGroupSize = 8;

// Push constants of one refresh: rows [firstRow, firstRow + rowCount) of the map.
struct TerrainSunlightConstants {
  vec2 cornerRelative;  // the heightfield's (x, z) corner relative to this frame's camera (m)
  vec2 texelMetres;     // a texel's size along x and z (m)
  uint resolution;      // texels per side (the heightfield's)
  uint firstRow;
  uint rowCount;
  uint pad;
};
SHADER_STATIC_ASSERT(sizeof(TerrainSunlightConstants) == 32);

// Where a world position's (x, z) falls in the map, [0, 1] per axis, from the camera's place
// in it (`cameraUv`) and the map's reciprocal size (1/m): what SceneFrame::sunlightMap holds.
SHADER_INLINE vec2 terrainSunlightUv(vec2 relativeXz, vec4 sunlightMap) {
  return vec2(sunlightMap.x, sunlightMap.y) + relativeXz * vec2(sunlightMap.z, sunlightMap.w);
}

SHADER_NAMESPACE_END

#endif
