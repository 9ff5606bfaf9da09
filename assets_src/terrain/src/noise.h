#pragma once
// Seeded 2D gradient noise with analytic derivatives, and the fractal sums built on it.
// Integer hashing only (no std::random distributions, whose output varies between standard
// libraries), so a seed gives the same terrain everywhere.
#include <cstdint>

#include <glm/vec2.hpp>

namespace terrain {

/// A noise value and its gradient with respect to the sample position.
struct NoiseSample {
  double value = 0.0;
  glm::dvec2 gradient{0.0};
};

/// One independent noise field: its lattice hash seed and a domain offset that keeps the origin
/// off a lattice point (where gradient noise is always zero).
struct NoiseLayer {
  std::uint32_t seed = 0;
  glm::dvec2 offset{0.0};
};

/// Derives an independent layer from the terrain seed and a per-use layer id.
NoiseLayer makeNoiseLayer(std::uint32_t seed, std::uint32_t layerId);

/// Quintic-interpolated gradient (Perlin) noise, scaled to roughly [-1, 1]; `octave` selects an
/// independent lattice so octaves do not line up.
NoiseSample gradientNoise(const NoiseLayer& layer, std::uint32_t octave, glm::dvec2 p);

/// Fractal sum of `octaves` gradient-noise octaves, normalised to roughly [-1, 1].
double fbm(const NoiseLayer& layer, glm::dvec2 p, int octaves, double lacunarity, double gain);

/// Settings of the ridged, erosion-damped fractal.
struct RidgedSettings {
  int octaves = 8;
  double lacunarity = 2.0;
  double gain = 0.5;
  /// Exponent on each octave's ridge profile: 1 gives broad massifs, 2 knife-edge crests.
  double sharpness = 2.0;
  double erosion = 0.0;
};

/// Ridged multifractal in [0, 1] (sharp crests where the noise crosses zero). Two terms stand in
/// for erosion: each octave is weighted by the previous one's ridge value, so valleys stay
/// smooth as if filled with sediment, and by 1 / (1 + erosion * |gradient so far|^2), so detail
/// fades on steep flanks as if washed off while crests and valley floors keep theirs.
double erodedRidged(const NoiseLayer& layer, glm::dvec2 p, const RidgedSettings& settings);

}  // namespace terrain
