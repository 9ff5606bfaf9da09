#pragma once
// The triangle mesh of a heightfield: the arrays a glTF primitive holds.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cover.h"
#include "heightfield.h"

namespace terrain {

/// Vertex arrays (metres, Y up) and a uint32 triangle list wound counter-clockwise seen from
/// above, glTF's front face.
struct TerrainMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  /// Linear RGB of each vertex's cover class.
  std::vector<glm::vec3> colours;
  std::vector<std::uint32_t> indices;
};

/// Normals come from central differences of the grid (one-sided at the border), UVs span 0..1
/// over the map with u along +X and v along +Z, colours from `rules`.
TerrainMesh buildTerrainMesh(const Heightfield& field, const CoverRules& rules);

}  // namespace terrain
