#pragma once
// `terrain_gen --check`: verifies a written terrain glTF and summarises it.
#include <filesystem>
#include <string>
#include <vector>

namespace terrain {

/// What the terrain must reach for the sky to matter: peaks into the cloud layer, lowlands well
/// below it.
struct CheckThresholds {
  double minPeakMetres = 1500.0;
  double maxFloorMetres = 400.0;
};

struct CheckReport {
  /// One line per failed check; empty when everything passed.
  std::vector<std::string> failures;
  /// Human-readable summary: counts, extents, heights, cover shares.
  std::vector<std::string> summary;
};

/// Re-reads the glTF and its buffer and checks: matching attribute counts, finite values,
/// POSITION bounds equal to the data, a map centred on the origin in X/Z, unit normals that
/// point up, UVs and colours in [0, 1], indices in range, no degenerate or downward-facing
/// triangles, every edge shared by at most two triangles in opposite directions (a consistently
/// wound manifold sheet), every vertex used, and the height thresholds. Throws engine::Error
/// when the file cannot be read as a terrain glTF at all.
CheckReport checkTerrainGltf(const std::filesystem::path& gltfPath,
                             const CheckThresholds& thresholds);

}  // namespace terrain
