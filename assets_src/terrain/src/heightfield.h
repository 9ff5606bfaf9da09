#pragma once
// The terrain's height as a function of position, sampled on a square grid.
#include <cstddef>
#include <vector>

#include "terrain_params.h"

namespace terrain {

/// Heights in metres on a `resolution` x `resolution` grid spanning [-size/2, size/2] in X and Z.
/// Row-major with X varying fastest: heights[z * resolution + x].
struct Heightfield {
  int resolution = 0;
  double sizeMetres = 0.0;
  std::vector<float> heights;

  double spacingMetres() const { return sizeMetres / static_cast<double>(resolution - 1); }
  /// World X (or Z) of grid column (or row) `i`.
  double coordinate(int i) const { return -0.5 * sizeMetres + spacingMetres() * i; }
  float at(int x, int z) const {
    return heights[static_cast<std::size_t>(z) * static_cast<std::size_t>(resolution) +
                   static_cast<std::size_t>(x)];
  }
};

/// The terrain at one position, before the mountains are scaled to their height.
struct TerrainSample {
  /// Base height, rolling plains and river channels, in metres.
  double groundMetres = 0.0;
  /// Mountain relief, unscaled: the eroded ridged fractal times the range mask (0 on plains).
  double relief = 0.0;
};

/// An analytic function of position, so the terrain's shape does not depend on the grid.
TerrainSample sampleTerrain(const TerrainParams& params, double x, double z);

/// Samples the grid, then scales the relief so the tallest mountain stands exactly
/// `mountains.heightMetres` above the ground beneath it. Normalising by the sampled maximum makes
/// the peak height a parameter rather than an accident of the seed; it shifts heights by well
/// under 1% between grid resolutions.
Heightfield synthesizeHeightfield(const TerrainParams& params);

}  // namespace terrain
