#pragma once
// How any glTF terrain is put into the world: centred on the origin in X/Z, its lowest point at
// sea level, and (small models only) scaled up so the sky matters above it.
#include "engine/assets/gltf_loader.h"

namespace sample {

// Meshes narrower than this are scaled so their wider side spans kSmallTerrainTargetMetres.
inline constexpr double kSmallTerrainMetres = 2000.0;
inline constexpr double kSmallTerrainTargetMetres = 20000.0;

// Transforms the mesh in place and updates its bounds; returns the uniform scale applied.
double placeTerrain(engine::assets::MeshData& mesh);

}  // namespace sample
