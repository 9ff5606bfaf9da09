#include "phase_normaliser.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "cloud_math.h"

namespace clouds::detail {
namespace {

double clampG(float g) {
  return std::clamp(static_cast<double>(g), -double(shader::kMaxPhaseG),
                    double(shader::kMaxPhaseG));
}

double henyeyGreenstein(double mu, double g) {
  const double d = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * M_PI * d * std::sqrt(d));
}

// 2 pi x the integral of HG(mu, g) over mu in [a, b], in closed form (the derivative of
// (1 + g^2 - 2 g mu)^(-1/2) is g (1 + g^2 - 2 g mu)^(-3/2)); g -> 0 is the isotropic 1/2 per unit.
double henyeyGreensteinIntegral(double a, double b, double g) {
  if (std::abs(g) < 1e-6) return 0.5 * (b - a);
  const auto inverseRoot = [g](double mu) { return 1.0 / std::sqrt(1.0 + g * g - 2.0 * g * mu); };
  return (1.0 - g * g) / (2.0 * g) * (inverseRoot(b) - inverseRoot(a));
}

}  // namespace

double silverLiningPhaseIntegral(const PhaseLobes& lobes) {
  const double forward = clampG(lobes.forwardG);
  const double backward = clampG(lobes.backwardG);
  const double blend = std::clamp(static_cast<double>(lobes.backwardWeight), 0.0, 1.0);
  const double silver = clampG(lobes.silverG);
  const double intensity = std::max(static_cast<double>(lobes.silverIntensity), 0.0);
  const auto mixed = [&](double mu) {
    return (1.0 - blend) * henyeyGreenstein(mu, forward) + blend * henyeyGreenstein(mu, backward);
  };
  const auto silverLobe = [&](double mu) { return intensity * henyeyGreenstein(mu, silver); };
  const auto mixedIntegral = [&](double a, double b) {
    return (1.0 - blend) * henyeyGreensteinIntegral(a, b, forward) +
           blend * henyeyGreensteinIntegral(a, b, backward);
  };
  if (intensity == 0.0) return mixedIntegral(-1.0, 1.0);
  const auto silverAbove = [&](double mu) { return silverLobe(mu) > mixed(mu); };

  // Where the max changes sides: sign changes of (silver - mix) on a grid that crowds towards
  // mu = +-1 (mu = +-(1 - x^4)), where sharp lobes peak, each refined by bisection.
  constexpr int kCells = 4096;
  std::vector<double> grid;
  grid.reserve(2 * kCells + 1);
  for (int i = kCells; i > 0; --i) grid.push_back(-1.0 + std::pow(double(i) / kCells, 4.0));
  for (int i = 0; i <= kCells; ++i)
    grid.push_back(1.0 - std::pow(double(kCells - i) / kCells, 4.0));
  grid.front() = -1.0;
  std::vector<double> breaks{-1.0};
  for (std::size_t i = 1; i < grid.size(); ++i) {
    double lo = grid[i - 1];
    double hi = grid[i];
    if (silverAbove(lo) == silverAbove(hi)) continue;
    const bool loAbove = silverAbove(lo);
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (silverAbove(mid) == loAbove ? lo : hi) = mid;
    }
    breaks.push_back(0.5 * (lo + hi));
  }
  breaks.push_back(1.0);

  double total = 0.0;
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    const double a = breaks[i - 1];
    const double b = breaks[i];
    if (b <= a) continue;
    total += silverAbove(0.5 * (a + b)) ? intensity * henyeyGreensteinIntegral(a, b, silver)
                                        : mixedIntegral(a, b);
  }
  return total;
}

std::array<float, 8> octavePhaseNormaliserInverses(const OctavePhaseSettings& settings) {
  const auto same = [](const OctavePhaseSettings& a, const OctavePhaseSettings& b) {
    return a.lobes.forwardG == b.lobes.forwardG && a.lobes.backwardG == b.lobes.backwardG &&
           a.lobes.backwardWeight == b.lobes.backwardWeight && a.lobes.silverG == b.lobes.silverG &&
           a.lobes.silverIntensity == b.lobes.silverIntensity &&
           a.eccentricityScale == b.eccentricityScale;
  };
  thread_local std::optional<std::pair<OctavePhaseSettings, std::array<float, 8>>> last;
  if (last && same(last->first, settings)) return last->second;
  std::array<float, 8> inverses{};
  float eccentricity = 1.0f;
  for (float& inverse : inverses) {
    PhaseLobes lobes = settings.lobes;
    lobes.forwardG *= eccentricity;
    lobes.backwardG *= eccentricity;
    lobes.silverG *= eccentricity;
    inverse = static_cast<float>(1.0 / silverLiningPhaseIntegral(lobes));
    eccentricity *= settings.eccentricityScale;
  }
  last.emplace(settings, inverses);
  return inverses;
}

}  // namespace clouds::detail
