#pragma once
// A coarse height field of the terrain for gameplay queries (staying above the ground): the
// highest point of the mesh in each cell of a regular grid over its bounds, sampled
// bilinearly. Built once from the loaded mesh, so it works for any glTF terrain.
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

}  // namespace sample
