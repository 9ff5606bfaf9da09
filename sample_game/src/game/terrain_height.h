#pragma once
// A coarse height field of the terrain for gameplay queries (staying above the ground): the
// highest point of the mesh in each cell of a regular grid over its bounds, sampled
// bilinearly. Built once from the loaded mesh, so it works for any glTF terrain.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/assets/gltf_loader.h"

namespace sample {

class TerrainHeightField {
 public:
  TerrainHeightField() = default;
  TerrainHeightField(const engine::assets::MeshData& mesh, std::uint32_t resolution = 512);

  // Height (m) of the terrain under (x, z); 0 (sea level) outside the mesh.
  double heightAt(double x, double z) const;
  bool empty() const { return heights_.empty(); }

 private:
  double cellHeight(int i, int j) const;

  std::vector<float> heights_;
  std::uint32_t resolution_ = 0;
  glm::dvec2 min_{0.0};
  glm::dvec2 cellSize_{1.0};
};

// The terrain's surface itself at the centres of a resolution x resolution grid over its
// bounds (row j at z = origin.y + (j + 0.5) size.y / resolution): each centre's height is
// interpolated on the triangle above it, and centres no triangle covers get the mesh's lowest
// height. What long shadows are cast from, where the conservative field above would lift
// every slope by up to a cell's rise.
struct SurfaceHeights {
  std::uint32_t resolution = 0;
  glm::dvec2 originMetres{0.0};  // world (x, z) of the grid's corner
  glm::dvec2 sizeMetres{0.0};
  std::vector<float> metres;  // row-major, resolution^2
  float minMetres = 0.0f;
  float maxMetres = 0.0f;
};
SurfaceHeights sampleSurface(const engine::assets::MeshData& mesh, std::uint32_t resolution);

}  // namespace sample
