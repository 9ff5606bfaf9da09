#pragma once
// Writes a TerrainMesh as glTF 2.0: a .gltf JSON file and its .bin buffer side by side.
#include <filesystem>

#include "cover.h"
#include "terrain_mesh.h"

namespace terrain {

/// The extras key under which the writer records the cover palette, so that `--check` can tell
/// the share of each cover class without the parameter file.
inline constexpr const char* kCoverPaletteExtras = "cloudscapeCoverPalette";

/// Writes `gltfPath` (which must end in .gltf) and the buffer next to it with the same stem and
/// a .bin extension. One scene, one node, one mesh with one primitive (POSITION, NORMAL,
/// TEXCOORD_0, COLOR_0 as float vectors, uint32 indices) and one white, fully rough material.
/// The output depends only on its inputs, byte for byte. Throws engine::Error on I/O failure.
void writeTerrainGltf(const TerrainMesh& mesh, const CoverRules& rules,
                      const std::filesystem::path& gltfPath);

}  // namespace terrain
