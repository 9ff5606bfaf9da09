// The terrain's materials on the CPU: the ones its fragment shader paints with, and their
// albedo at large, for light bounced off the ground where no pass sees it texel by texel (the
// atmosphere's ground and the light cloud bases get from below).
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "engine/assets/gltf_loader.h"
#include "terrain_material.h"

namespace sample {

// The rock and snow painted over a mesh's colours (terrain_material.h): rock from 35 degrees of
// slope, snow from `snowlineMetres` (by default 70% of the way up from the mesh's lowest point
// to its highest), in the default terrain's palette.
engine::shaders::TerrainMaterials terrainMaterialsFor(const engine::assets::MeshData& mesh,
                                                      std::optional<double> snowlineMetres);

// The area-weighted mean over the mesh's triangles of what terrainAlbedo() paints at their
// corners (the mesh's colours, rock on its steep slopes, snow high up) with the detail's
// normal and waver left out. A mesh without triangles gives the mean of its colours, or 0.
glm::vec3 meanTerrainAlbedo(const engine::assets::MeshData& mesh,
                            const engine::shaders::TerrainMaterials& materials);

}  // namespace sample
