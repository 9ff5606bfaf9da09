#include "noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/mat2x2.hpp>

namespace terrain {
namespace {

// Chris Wellons' "lowbias32" integer hash: cheap, with good avalanche.
std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

std::uint32_t hashLattice(std::uint32_t seed, std::int64_t ix, std::int64_t iy) {
  // Wrapping the lattice coordinates to 32 bits is intended: it only repeats after 2^32 cells.
  return hash32(static_cast<std::uint32_t>(ix) ^ hash32(static_cast<std::uint32_t>(iy) ^ seed));
}

// 256 unit gradients evenly spread around the circle. Only eight (axes and diagonals) would
// line up the zero crossings of neighbouring cells along lattice lines, and ridged noise turns
// those into long straight crests. Built once from sin/cos; the table, not the call, is what
// every sample uses.
glm::dvec2 latticeGradient(std::uint32_t hash) {
  static const std::array<glm::dvec2, 256> kDirections = [] {
    std::array<glm::dvec2, 256> directions{};
    for (std::size_t i = 0; i < directions.size(); ++i) {
      const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / 256.0;
      directions[i] = {std::cos(angle), std::sin(angle)};
    }
    return directions;
  }();
  return kDirections[hash & 255U];
}

// Rotating each octave's domain (a 3-4-5 rotation, exact in binary) hides the lattice axes that
// would otherwise line up across octaves as a visible grid.
glm::dvec2 rotateOctave(glm::dvec2 p) {
  return {0.8 * p.x - 0.6 * p.y, 0.6 * p.x + 0.8 * p.y};
}
// The transpose of that rotation: it carries a gradient taken in a rotated domain back to p's.
// GLM takes columns, so this reads as rows (0.8, 0.6) and (-0.6, 0.8).
const glm::dmat2 kRotateGradientBack(0.8, -0.6, 0.6, 0.8);

// 2D gradient noise with unit gradients peaks near +-sqrt(0.5); this brings it to about +-1.
constexpr double kNoiseScale = 1.4142135623730951;

// Squared half-width of the rounded crest of a ridged octave, in noise units.
constexpr double kCrestRounding = 0.0025;

}  // namespace

NoiseLayer makeNoiseLayer(std::uint32_t seed, std::uint32_t layerId) {
  NoiseLayer layer;
  layer.seed = hash32(seed ^ hash32(layerId + 0x9e3779b9U));
  const std::uint32_t hx = hash32(layer.seed + 1U);
  const std::uint32_t hy = hash32(layer.seed + 2U);
  // Offsets up to 1000 cells, with fractional parts, move the origin into the middle of a cell.
  layer.offset = {static_cast<double>(hx % 1000000U) * 1.0e-3 + 0.37,
                  static_cast<double>(hy % 1000000U) * 1.0e-3 + 0.61};
  return layer;
}

NoiseSample gradientNoise(const NoiseLayer& layer, std::uint32_t octave, glm::dvec2 p) {
  const std::uint32_t seed = hash32(layer.seed + octave * 0x632be5abU);
  const glm::dvec2 cell = glm::floor(p);
  const glm::dvec2 f = p - cell;
  const auto ix = static_cast<std::int64_t>(cell.x);
  const auto iy = static_cast<std::int64_t>(cell.y);

  const glm::dvec2 ga = latticeGradient(hashLattice(seed, ix, iy));
  const glm::dvec2 gb = latticeGradient(hashLattice(seed, ix + 1, iy));
  const glm::dvec2 gc = latticeGradient(hashLattice(seed, ix, iy + 1));
  const glm::dvec2 gd = latticeGradient(hashLattice(seed, ix + 1, iy + 1));
  const double va = glm::dot(ga, f);
  const double vb = glm::dot(gb, f - glm::dvec2(1.0, 0.0));
  const double vc = glm::dot(gc, f - glm::dvec2(0.0, 1.0));
  const double vd = glm::dot(gd, f - glm::dvec2(1.0, 1.0));

  // Quintic fade: its zero first and second derivatives at the cell edges keep normals smooth.
  const glm::dvec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  const glm::dvec2 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  const double k = va - vb - vc + vd;

  NoiseSample s;
  s.value = va + u.x * (vb - va) + u.y * (vc - va) + u.x * u.y * k;
  s.gradient = ga + u.x * (gb - ga) + u.y * (gc - ga) + u.x * u.y * (ga - gb - gc + gd) +
               du * (glm::dvec2(u.y, u.x) * k + glm::dvec2(vb - va, vc - va));
  s.value *= kNoiseScale;
  s.gradient *= kNoiseScale;
  return s;
}

double fbm(const NoiseLayer& layer, glm::dvec2 p, int octaves, double lacunarity, double gain) {
  glm::dvec2 q = p + layer.offset;
  double sum = 0.0;
  double amplitude = 1.0;
  double norm = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * gradientNoise(layer, static_cast<std::uint32_t>(o), q).value;
    norm += amplitude;
    amplitude *= gain;
    q = rotateOctave(q) * lacunarity;
  }
  return sum / norm;
}

double erodedRidged(const NoiseLayer& layer, glm::dvec2 p, const RidgedSettings& settings) {
  glm::dvec2 q = p + layer.offset;
  double sum = 0.0;
  double norm = 0.0;
  double amplitude = 1.0;
  double weight = 1.0;
  double frequency = 1.0;
  glm::dvec2 slope(0.0);    // gradient of the octaves so far, in units of the first octave
  glm::dmat2 toWorld(1.0);  // maps a gradient in this octave's rotated domain back to p's
  for (int o = 0; o < settings.octaves; ++o) {
    const NoiseSample n = gradientNoise(layer, static_cast<std::uint32_t>(o), q);
    // Ridge: 1 at the zero crossing, raised to `sharpness` to narrow the crest. A smooth |n|
    // rounds the crest slightly; with a true |n| the gradient flips sign across every crest,
    // the damping below jumps with it, and later octaves leave cliffs along the crest lines.
    const double smoothAbs = std::sqrt(n.value * n.value + kCrestRounding);
    const double ridge = std::max(1.0 - smoothAbs, 0.0);
    const double shaped = std::pow(ridge, settings.sharpness);
    const double value = shaped * weight;
    // Damping uses the slope of the octaves before this one only: damping the first octave by
    // its own slope would flatten the massifs themselves, not just the detail on their flanks.
    sum += amplitude * value / (1.0 + settings.erosion * glm::dot(slope, slope));
    norm += amplitude;

    const glm::dvec2 dRidge = -(n.value / smoothAbs) * n.gradient;
    const glm::dvec2 dValue =
        ridge > 0.0 ? settings.sharpness * (shaped / ridge) * weight * dRidge : glm::dvec2(0.0);
    slope += amplitude * frequency * (toWorld * dValue);

    // Musgrave's weighting: the next octave's detail follows this octave's ridges.
    weight = std::clamp(value * 1.5, 0.0, 1.0);
    amplitude *= settings.gain;
    frequency *= settings.lacunarity;
    q = rotateOctave(q) * settings.lacunarity;
    toWorld = toWorld * kRotateGradientBack;
  }
  return sum / norm;
}

}  // namespace terrain
