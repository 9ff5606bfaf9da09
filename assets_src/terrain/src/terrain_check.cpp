#include "terrain_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "gltf_reader.h"

namespace terrain {
namespace {

constexpr float kUnitTolerance = 1.0e-4f;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[256];
  std::snprintf(text, sizeof(text), pattern, a, b, c);
  return text;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Counts how many elements fail `ok`, and reports the first one.
template <typename T, typename Predicate>
void expectAll(CheckReport& report, const std::vector<T>& items, const char* what, Predicate ok) {
  std::size_t bad = 0;
  std::size_t first = 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (ok(items[i])) continue;
    if (bad++ == 0) first = i;
  }
  if (bad != 0) {
    report.failures.push_back(std::to_string(bad) + " " + what + " (first at vertex " +
                              std::to_string(first) + ")");
  }
}

void checkVertices(const LoadedTerrain& t, CheckReport& report) {
  const TerrainMesh& m = t.mesh;
  if (m.positions.empty()) report.failures.push_back("the mesh has no vertices");
  if (m.normals.size() != m.positions.size() || m.uvs.size() != m.positions.size() ||
      m.colours.size() != m.positions.size()) {
    report.failures.push_back(
        "attribute counts differ: POSITION " + std::to_string(m.positions.size()) + ", NORMAL " +
        std::to_string(m.normals.size()) + ", TEXCOORD_0 " + std::to_string(m.uvs.size()) +
        ", COLOR_0 " + std::to_string(m.colours.size()));
    return;
  }
  expectAll(report, m.positions, "positions are not finite", finite);
  expectAll(report, m.normals, "normals are not unit length or do not point up",
            [](const glm::vec3& n) {
              return finite(n) && std::abs(glm::length(n) - 1.0f) <= kUnitTolerance && n.y > 0.0f;
            });
  expectAll(report, m.uvs, "UVs are outside [0, 1]", [](const glm::vec2& uv) {
    return uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f;
  });
  expectAll(report, m.colours, "colours are outside [0, 1]", [](const glm::vec3& c) {
    return finite(c) && glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
           glm::all(glm::lessThanEqual(c, glm::vec3(1.0f)));
  });
}

void checkBounds(const LoadedTerrain& t, const CheckThresholds& thresholds, CheckReport& report) {
  const std::vector<glm::vec3>& p = t.mesh.positions;
  if (p.empty()) return;
  glm::vec3 lo = p.front();
  glm::vec3 hi = lo;
  double sum = 0.0;
  for (const glm::vec3& v : p) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
    sum += v.y;
  }
  if (lo != t.declaredMin || hi != t.declaredMax) {
    report.failures.push_back("POSITION min/max in the accessor differ from the data");
  }
  // Centred on the origin in X/Z, to within float rounding of the extent.
  const float tolerance = 1.0e-5f * std::max(hi.x - lo.x, hi.z - lo.z);
  if (std::abs(lo.x + hi.x) > tolerance || std::abs(lo.z + hi.z) > tolerance) {
    report.failures.push_back(format("the map is not centred in X/Z: x [%.1f, %.1f]", lo.x, hi.x) +
                              format(", z [%.1f, %.1f]", lo.z, hi.z));
  }
  if (hi.y <= thresholds.minPeakMetres) {
    report.failures.push_back(
        format("highest point %.1f m is not above %.1f m", hi.y, thresholds.minPeakMetres));
  }
  if (lo.y >= thresholds.maxFloorMetres) {
    report.failures.push_back(
        format("lowest point %.1f m is not below %.1f m", lo.y, thresholds.maxFloorMetres));
  }
  report.summary.push_back(format("extent x [%.1f, %.1f] m, ", lo.x, hi.x) +
                           format("z [%.1f, %.1f] m", lo.z, hi.z));
  report.summary.push_back(format("height min %.1f m, max %.1f m, mean %.1f m", lo.y, hi.y,
                                  sum / static_cast<double>(p.size())));
}

void checkTriangles(const TerrainMesh& m, CheckReport& report) {
  const std::vector<std::uint32_t>& idx = m.indices;
  if (idx.empty() || idx.size() % 3 != 0) {
    report.failures.push_back("index count " + std::to_string(idx.size()) +
                              " is not a positive multiple of 3");
    return;
  }
  const std::size_t vertexCount = m.positions.size();
  if (std::any_of(idx.begin(), idx.end(), [&](std::uint32_t i) { return i >= vertexCount; })) {
    report.failures.push_back("indices out of range (vertex count " + std::to_string(vertexCount) +
                              ")");
    return;
  }

  // Directed edges: a consistently wound manifold uses each at most once, and an interior edge
  // appears once in each direction. Boundary edges have no twin.
  std::unordered_map<std::uint64_t, std::uint32_t> directed;
  directed.reserve(idx.size());
  std::vector<bool> used(vertexCount, false);
  std::size_t degenerate = 0;
  std::size_t facingDown = 0;
  for (std::size_t t = 0; t < idx.size(); t += 3) {
    const std::uint32_t v[3] = {idx[t], idx[t + 1], idx[t + 2]};
    const glm::vec3 n =
        glm::cross(m.positions[v[1]] - m.positions[v[0]], m.positions[v[2]] - m.positions[v[0]]);
    if (glm::length(n) <= 0.0f) {
      ++degenerate;
    } else if (n.y <= 0.0f) {
      ++facingDown;
    }
    for (int e = 0; e < 3; ++e) {
      used[v[e]] = true;
      const std::uint64_t key = (std::uint64_t{v[e]} << 32) | v[(e + 1) % 3];
      ++directed[key];
    }
  }
  std::size_t repeated = 0;
  std::size_t boundary = 0;
  for (const auto& [key, count] : directed) {
    if (count > 1) ++repeated;
    const std::uint64_t twin = (key << 32) | (key >> 32);
    if (directed.find(twin) == directed.end()) ++boundary;
  }
  const auto unused = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  if (degenerate != 0)
    report.failures.push_back(std::to_string(degenerate) + " degenerate triangles");
  if (facingDown != 0) {
    report.failures.push_back(
        std::to_string(facingDown) +
        " triangles face down (front faces must be counter-clockwise from above)");
  }
  if (repeated != 0) {
    report.failures.push_back(std::to_string(repeated) +
                              " directed edges used twice (non-manifold or inconsistent winding)");
  }
  if (unused != 0)
    report.failures.push_back(std::to_string(unused) + " vertices used by no triangle");
  report.summary.push_back("vertices " + std::to_string(vertexCount) + ", triangles " +
                           std::to_string(idx.size() / 3) + ", boundary edges " +
                           std::to_string(boundary));
}

void summariseCover(const LoadedTerrain& t, CheckReport& report) {
  if (!t.palette) {
    report.summary.push_back("cover: no palette in the mesh extras");
    return;
  }
  const glm::vec3 palette[3] = {t.palette->grass, t.palette->rock, t.palette->snow};
  std::size_t counts[3] = {0, 0, 0};
  for (const glm::vec3& c : t.mesh.colours) {
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < 3; ++k) {
      if (glm::distance(c, palette[k]) < glm::distance(c, palette[nearest])) nearest = k;
    }
    ++counts[nearest];
  }
  const double total = static_cast<double>(std::max<std::size_t>(t.mesh.colours.size(), 1));
  report.summary.push_back(format("cover: grass %.1f%%, rock %.1f%%, snow %.1f%%",
                                  100.0 * static_cast<double>(counts[0]) / total,
                                  100.0 * static_cast<double>(counts[1]) / total,
                                  100.0 * static_cast<double>(counts[2]) / total));
}

}  // namespace

CheckReport checkTerrainGltf(const std::filesystem::path& gltfPath,
                             const CheckThresholds& thresholds) {
  const LoadedTerrain terrain = readTerrainGltf(gltfPath);
  CheckReport report;
  checkVertices(terrain, report);
  checkTriangles(terrain.mesh, report);
  checkBounds(terrain, thresholds, report);
  summariseCover(terrain, report);
  return report;
}

}  // namespace terrain
