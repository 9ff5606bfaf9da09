#include "heightfield.h"

#include <algorithm>
#include <cmath>

#include "noise.h"

namespace terrain {
namespace {

// Layer ids: each use of noise draws from its own independent field of the same seed.
constexpr std::uint32_t kPlainsLayer = 1;
constexpr std::uint32_t kMountainLayer = 2;
constexpr std::uint32_t kRangeLayer = 3;
constexpr std::uint32_t kValleyLayer = 4;

// Octaves of the large-scale masks: enough to bend their outlines, few enough to keep them broad.
constexpr int kMaskOctaves = 3;

double smoothstep(double edge0, double edge1, double x) {
  if (edge1 <= edge0) return x < edge0 ? 0.0 : 1.0;
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

TerrainSample sampleTerrain(const TerrainParams& params, double x, double z) {
  const glm::dvec2 pos(x, z);
  const std::uint32_t seed = params.seed;

  // Where the ranges stand: a broad mask, faded out towards the border of the map.
  const RangeParams& ranges = params.ranges;
  const double rangeNoise = 0.5 + 0.5 * fbm(makeNoiseLayer(seed, kRangeLayer),
                                            pos / ranges.wavelengthMetres, kMaskOctaves, 2.0, 0.5);
  double mask = smoothstep(ranges.threshold - ranges.softness, ranges.threshold + ranges.softness,
                           rangeNoise);
  const double half = 0.5 * params.sizeMetres;
  const double toBorder = std::min(half - std::abs(x), half - std::abs(z));
  mask *= smoothstep(0.0, ranges.edgeFalloffMetres, toBorder);

  // Valleys follow the zero set of a noise field: a connected, meandering network that cuts the
  // ranges into massifs and holds a river channel along its floor.
  const ValleyParams& valleys = params.valleys;
  const double valleyDistance = std::abs(fbm(
      makeNoiseLayer(seed, kValleyLayer), pos / valleys.wavelengthMetres, kMaskOctaves, 2.0, 0.5));
  mask *= smoothstep(0.0, valleys.width, valleyDistance);
  const double river =
      valleys.riverDepthMetres * (1.0 - smoothstep(0.0, valleys.riverWidth, valleyDistance));

  const MountainParams& m = params.mountains;
  const RidgedSettings ridged{m.octaves, m.lacunarity, m.gain, m.sharpness, m.erosion};
  const double mountain =
      erodedRidged(makeNoiseLayer(seed, kMountainLayer), pos / m.wavelengthMetres, ridged);

  const PlainsParams& plains = params.plains;
  const double rolling =
      plains.amplitudeMetres * fbm(makeNoiseLayer(seed, kPlainsLayer),
                                   pos / plains.wavelengthMetres, plains.octaves, 2.0, 0.5);

  return {params.baseHeightMetres + rolling - river, mask * mountain};
}

Heightfield synthesizeHeightfield(const TerrainParams& params) {
  Heightfield field;
  field.resolution = params.gridResolution;
  field.sizeMetres = params.sizeMetres;
  const auto n = static_cast<std::size_t>(field.resolution);
  std::vector<TerrainSample> samples;
  samples.reserve(n * n);
  double maxRelief = 0.0;
  for (int z = 0; z < field.resolution; ++z) {
    for (int x = 0; x < field.resolution; ++x) {
      samples.push_back(sampleTerrain(params, field.coordinate(x), field.coordinate(z)));
      maxRelief = std::max(maxRelief, samples.back().relief);
    }
  }
  // A map with no mountains at all (mask zero everywhere) keeps its plains.
  const double scale = maxRelief > 0.0 ? params.mountains.heightMetres / maxRelief : 0.0;
  field.heights.reserve(samples.size());
  for (const TerrainSample& s : samples) {
    field.heights.push_back(static_cast<float>(s.groundMetres + scale * s.relief));
  }
  return field;
}

}  // namespace terrain
