#include "terrain_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace terrain {
namespace {

// Height difference across a grid point along one axis, from the neighbours that exist.
// Returns dh/d(metres).
double slopeAlong(const Heightfield& field, int x, int z, int dx, int dz) {
  const int last = field.resolution - 1;
  const int x0 = std::max(x - dx, 0);
  const int z0 = std::max(z - dz, 0);
  const int x1 = std::min(x + dx, last);
  const int z1 = std::min(z + dz, last);
  const int steps = (x1 - x0) + (z1 - z0);
  return (static_cast<double>(field.at(x1, z1)) - static_cast<double>(field.at(x0, z0))) /
         (steps * field.spacingMetres());
}

}  // namespace

TerrainMesh buildTerrainMesh(const Heightfield& field, const CoverRules& rules) {
  TerrainMesh mesh;
  const int n = field.resolution;
  const auto count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  mesh.positions.reserve(count);
  mesh.normals.reserve(count);
  mesh.uvs.reserve(count);
  mesh.colours.reserve(count);
  const double uvStep = 1.0 / static_cast<double>(n - 1);

  for (int z = 0; z < n; ++z) {
    for (int x = 0; x < n; ++x) {
      const float h = field.at(x, z);
      mesh.positions.emplace_back(static_cast<float>(field.coordinate(x)), h,
                                  static_cast<float>(field.coordinate(z)));
      // The surface y = h(x, z) has the (unnormalised) normal (-dh/dx, 1, -dh/dz).
      const glm::dvec3 normal = glm::normalize(
          glm::dvec3(-slopeAlong(field, x, z, 1, 0), 1.0, -slopeAlong(field, x, z, 0, 1)));
      mesh.normals.emplace_back(normal);
      mesh.uvs.emplace_back(static_cast<float>(x * uvStep), static_cast<float>(z * uvStep));
      const double slopeDegrees =
          std::acos(std::clamp(normal.y, -1.0, 1.0)) * (180.0 / std::numbers::pi);
      mesh.colours.push_back(coverColour(rules, classifyCover(rules, h, slopeDegrees)));
    }
  }

  // Two triangles per cell. With X right and Z towards the viewer, (x0z0, x0z1, x1z0) turns
  // counter-clockwise seen from +Y, so the top face is the front face.
  const auto cells = static_cast<std::size_t>(n - 1);
  mesh.indices.reserve(cells * cells * 6);
  const auto stride = static_cast<std::uint32_t>(n);
  for (std::uint32_t z = 0; z + 1 < stride; ++z) {
    for (std::uint32_t x = 0; x + 1 < stride; ++x) {
      const std::uint32_t i00 = z * stride + x;
      const std::uint32_t i10 = i00 + 1;
      const std::uint32_t i01 = i00 + stride;
      const std::uint32_t i11 = i01 + 1;
      mesh.indices.insert(mesh.indices.end(), {i00, i01, i10, i10, i01, i11});
    }
  }
  return mesh;
}

}  // namespace terrain
