#pragma once
// Reads back a terrain glTF written by gltf_writer, validating its structure on the way.
#include <filesystem>
#include <optional>

#include <glm/vec3.hpp>

#include "terrain_mesh.h"

namespace terrain {

/// The three cover colours recorded in the mesh's extras.
struct CoverPalette {
  glm::vec3 grass{0.0f};
  glm::vec3 rock{0.0f};
  glm::vec3 snow{0.0f};
};

struct LoadedTerrain {
  TerrainMesh mesh;
  /// POSITION accessor's declared bounds, to compare with the data.
  glm::vec3 declaredMin{0.0f};
  glm::vec3 declaredMax{0.0f};
  std::optional<CoverPalette> palette;
};

/// Loads the one-primitive float-attribute layout this tool writes. Throws engine::Error naming
/// the file and the JSON path for anything else: a missing attribute, a wrong component type or
/// element type, a view or accessor that runs past its buffer, a buffer of the wrong size.
LoadedTerrain readTerrainGltf(const std::filesystem::path& gltfPath);

}  // namespace terrain
