#pragma once
// Parameters of the procedural terrain, as read from a *.terrain.json file (schema: ../README.md).
#include <cstdint>
#include <filesystem>

#include "cover.h"

namespace terrain {

/// Low rolling relief everywhere: the lowlands between the ranges.
struct PlainsParams {
  double amplitudeMetres = 0.0;
  double wavelengthMetres = 1.0;
  int octaves = 1;
};

/// Ridged, erosion-damped fractal that the range mask scales into mountains.
struct MountainParams {
  /// Relief of the tallest mountain above the ground beneath it (the relief is normalised).
  double heightMetres = 0.0;
  double wavelengthMetres = 1.0;
  int octaves = 1;
  double lacunarity = 2.0;
  double gain = 0.5;
  /// Exponent on the ridge profile: 1 gives broad massifs, 2 knife-edge crests.
  double sharpness = 1.0;
  /// Strength of the derivative damping: detail fades where the accumulated slope is steep.
  double erosion = 0.0;
};

/// Large-scale mask that decides where mountain ranges stand and where plains lie.
struct RangeParams {
  double wavelengthMetres = 1.0;
  /// Mask noise level (0..1) at which the mountains reach half height.
  double threshold = 0.5;
  /// Half-width of the transition around `threshold`, in the same 0..1 units.
  double softness = 0.1;
  /// Distance from the border over which mountains fade out, so the mesh edge is not a cliff.
  double edgeFalloffMetres = 0.0;
};

/// Meandering valleys that cut through the ranges, with a shallow river channel along their floor.
struct ValleyParams {
  double wavelengthMetres = 1.0;
  /// Valley half-width in valley-noise units (0 disables the valleys).
  double width = 0.0;
  /// River channel half-width in the same units.
  double riverWidth = 0.0;
  double riverDepthMetres = 0.0;
};

struct TerrainParams {
  double sizeMetres = 0.0;
  /// Vertices per side of the square grid.
  int gridResolution = 0;
  std::uint32_t seed = 0;
  double baseHeightMetres = 0.0;
  PlainsParams plains;
  MountainParams mountains;
  RangeParams ranges;
  ValleyParams valleys;
  CoverRules cover;
};

/// Reads and validates a parameter file. Throws engine::Error naming the file, the field and the
/// reason for a missing, mistyped, out-of-range or unknown key.
TerrainParams loadTerrainParams(const std::filesystem::path& path);

}  // namespace terrain
