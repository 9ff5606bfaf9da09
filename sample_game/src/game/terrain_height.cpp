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

SurfaceHeights sampleSurface(const engine::assets::MeshData& mesh, std::uint32_t resolution) {
  SurfaceHeights s;
  s.resolution = resolution;
  s.originMetres = glm::dvec2(mesh.boundsMin.x, mesh.boundsMin.z);
  s.sizeMetres =
      glm::max(glm::dvec2(mesh.boundsMax.x, mesh.boundsMax.z) - s.originMetres, glm::dvec2(1e-3));
  s.metres.assign(std::size_t{resolution} * resolution, mesh.boundsMin.y);
  const glm::dvec2 cell = s.sizeMetres / double(resolution);
  const int last = static_cast<int>(resolution) - 1;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
    // Twice the signed area in (x, z): degenerate (vertical) triangles hold no centre.
    const double area = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
    if (std::abs(area) < 1e-12) continue;
    // The centres inside the triangle's box: index i has its centre at (i + 0.5) cells.
    const auto first = [&](double v, double lo, double step) {
      return std::clamp(static_cast<int>(std::ceil((v - lo) / step - 0.5)), 0, last);
    };
    const auto final = [&](double v, double lo, double step) {
      return std::clamp(static_cast<int>(std::floor((v - lo) / step - 0.5)), 0, last);
    };
    const int i0 = first(std::min({a.x, b.x, c.x}), s.originMetres.x, cell.x);
    const int i1 = final(std::max({a.x, b.x, c.x}), s.originMetres.x, cell.x);
    const int j0 = first(std::min({a.z, b.z, c.z}), s.originMetres.y, cell.y);
    const int j1 = final(std::max({a.z, b.z, c.z}), s.originMetres.y, cell.y);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const glm::dvec2 p = s.originMetres + (glm::dvec2(i, j) + 0.5) * cell;
        // Barycentric weights of b and c (a gets the rest); inside with a small tolerance so
        // centres on shared edges are not lost.
        const double wb = ((p.x - a.x) * (c.z - a.z) - (c.x - a.x) * (p.y - a.z)) / area;
        const double wc = ((b.x - a.x) * (p.y - a.z) - (p.x - a.x) * (b.z - a.z)) / area;
        const double wa = 1.0 - wb - wc;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
        s.metres[std::size_t(j) * resolution + std::size_t(i)] =
            static_cast<float>(wa * a.y + wb * b.y + wc * c.y);
      }
    }
  }
  const auto [low, high] = std::minmax_element(s.metres.begin(), s.metres.end());
  s.minMetres = *low;
  s.maxMetres = *high;
  return s;
}

}  // namespace sample
