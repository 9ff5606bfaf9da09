#include "game/terrain_placement.h"

#include <algorithm>

namespace sample {

double placeTerrain(engine::assets::MeshData& mesh) {
  const glm::dvec3 lo(mesh.boundsMin);
  const glm::dvec3 hi(mesh.boundsMax);
  const double width = std::max(hi.x - lo.x, hi.z - lo.z);
  const double scale =
      width > 0.0 && width < kSmallTerrainMetres ? kSmallTerrainTargetMetres / width : 1.0;
  const glm::dvec3 anchor((lo.x + hi.x) * 0.5, lo.y, (lo.z + hi.z) * 0.5);
  for (glm::vec3& p : mesh.positions) p = glm::vec3((glm::dvec3(p) - anchor) * scale);
  mesh.boundsMin = glm::vec3((lo - anchor) * scale);
  mesh.boundsMax = glm::vec3((hi - anchor) * scale);
  return scale;
}

}  // namespace sample
