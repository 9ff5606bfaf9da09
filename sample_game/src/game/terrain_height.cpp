#include "game/terrain_height.h"

#include <algorithm>
#include <cmath>

namespace sample {

TerrainHeightField::TerrainHeightField(const engine::assets::MeshData& mesh,
                                       std::uint32_t resolution)
    : heights_(std::size_t{resolution} * resolution, 0.0f), resolution_(resolution) {
  min_ = glm::dvec2(mesh.boundsMin.x, mesh.boundsMin.z);
  const glm::dvec2 size =
      glm::max(glm::dvec2(mesh.boundsMax.x, mesh.boundsMax.z) - min_, glm::dvec2(1e-3));
  cellSize_ = size / double(resolution);
  // Conservative: every cell a triangle's bounding box touches gets at least its highest vertex
  // height, so the aircraft never clips a peak between samples.
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3& a = mesh.positions[mesh.indices[t]];
    const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
    const double top = std::max({a.y, b.y, c.y});
    const auto cell = [&](double v, double lo, double step) {
      return std::clamp(static_cast<int>((v - lo) / step), 0, static_cast<int>(resolution) - 1);
    };
    const int i0 = cell(std::min({a.x, b.x, c.x}), min_.x, cellSize_.x);
    const int i1 = cell(std::max({a.x, b.x, c.x}), min_.x, cellSize_.x);
    const int j0 = cell(std::min({a.z, b.z, c.z}), min_.y, cellSize_.y);
    const int j1 = cell(std::max({a.z, b.z, c.z}), min_.y, cellSize_.y);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        float& h = heights_[std::size_t(j) * resolution + std::size_t(i)];
        h = std::max(h, static_cast<float>(top));
      }
    }
  }
}

double TerrainHeightField::cellHeight(int i, int j) const {
  const int n = static_cast<int>(resolution_);
  if (i < 0 || j < 0 || i >= n || j >= n) return 0.0;
  return heights_[std::size_t(j) * resolution_ + std::size_t(i)];
}

double TerrainHeightField::heightAt(double x, double z) const {
  if (heights_.empty()) return 0.0;
  // The max of the four surrounding cells: conservative between cell centres.
  const double fx = (x - min_.x) / cellSize_.x - 0.5;
  const double fz = (z - min_.y) / cellSize_.y - 0.5;
  const int i = static_cast<int>(std::floor(fx));
  const int j = static_cast<int>(std::floor(fz));
  return std::max(
      {cellHeight(i, j), cellHeight(i + 1, j), cellHeight(i, j + 1), cellHeight(i + 1, j + 1)});
}

}  // namespace sample
