#include "render/terrain_materials.h"

#include <cmath>

namespace sample {

engine::shaders::TerrainMaterials terrainMaterialsFor(const engine::assets::MeshData& mesh,
                                                      std::optional<double> snowlineMetres) {
  engine::shaders::TerrainMaterials m;
  m.rock = glm::vec4(0.12f, 0.105f, 0.09f, 1.0f - std::cos(glm::radians(35.0f)));
  const double snowline =
      snowlineMetres.value_or(mesh.boundsMin.y + 0.7 * (mesh.boundsMax.y - mesh.boundsMin.y));
  m.snow = glm::vec4(0.85f, 0.87f, 0.9f, static_cast<float>(snowline));
  return m;
}

glm::vec3 meanTerrainAlbedo(const engine::assets::MeshData& mesh,
                            const engine::shaders::TerrainMaterials& materials) {
  const glm::vec4 calm(0.0f, 0.0f, 0.5f, 0.5f);  // no detail gradient, the waver's middle
  const auto painted = [&](std::uint32_t v) {
    return engine::shaders::terrainAlbedo(glm::vec3(mesh.colors[v]), mesh.normals[v],
                                          mesh.positions[v].y, calm, materials);
  };
  glm::dvec3 sum(0.0);
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t];
    const std::uint32_t b = mesh.indices[t + 1];
    const std::uint32_t c = mesh.indices[t + 2];
    const double triangle = 0.5 * glm::length(glm::cross(mesh.positions[b] - mesh.positions[a],
                                                         mesh.positions[c] - mesh.positions[a]));
    sum += triangle * glm::dvec3(painted(a) + painted(b) + painted(c)) / 3.0;
    area += triangle;
  }
  if (area > 0.0) return glm::vec3(sum / area);
  glm::dvec3 colours(0.0);
  for (const glm::vec4& colour : mesh.colors) colours += glm::dvec3(colour);
  return mesh.colors.empty() ? glm::vec3(0.0f) : glm::vec3(colours / double(mesh.colors.size()));
}

}  // namespace sample
