// The descriptor bindings of the sample's own passes: one definition for their shaders and for
// the C++ that lays out and writes their sets (as the clouds module's cloud_types.h does).
#ifndef SAMPLE_SHADERS_BINDINGS_H
#define SAMPLE_SHADERS_BINDINGS_H

#include "interop.h"

SHADER_NAMESPACE_BEGIN

// The terrain (terrain_vertex.glsl, terrain_fragment.glsl; TerrainRenderer, the scene pass).
const uint kTerrainFrameBinding = 0;       // SceneFrame (scene_constants.h)
const uint kTerrainHazeBinding = 1;        // the aerial perspective (3D), hazed variants only
const uint kTerrainSunlightBinding = 2;    // the terrain's sunlight map, shadowed variants only
const uint kTerrainBaseColourBinding = 3;  // the mesh's base colour texture, or a stand-in

// The water (water.vert, water_fragment.glsl; WaterRenderer, the scene pass).
const uint kWaterFrameBinding = 0;     // SceneFrame
const uint kWaterHazeBinding = 1;      // the aerial perspective (3D), hazed variants only
const uint kWaterSunlightBinding = 2;  // the terrain's sunlight map, shadowed variants only
const uint kWaterSkyBinding = 3;       // the sky it reflects (equirectangular), hazed variants only

// The terrain's sunlight map (terrain_sunlight.comp; TerrainSunlight).
const uint kSunlightHeightfieldBinding = 0;       // the terrain's heightfield
const uint kSunlightCloudShadowBinding = 1;       // the clouds' shadow map
const uint kSunlightShadowParametersBinding = 2;  // its CloudShadowParameters
const uint kSunlightMapBinding = 3;               // the map it writes

// The gradient sky (sky.comp; SkyPass).
const uint kSkyFrameBinding = 0;  // SceneFrame
const uint kSkyColorBinding = 1;  // the scene's HDR colour it writes

// The HUD (hud.frag; Hud).
const uint kHudFontBinding = 0;  // the font atlas

SHADER_NAMESPACE_END

#endif
