#include "voxel_opacity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace clouds::reference {

namespace {

// 4-point Gauss-Legendre on [-1, 1]: exact for polynomials up to degree 7.
constexpr double kGaussNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                   0.8611363115940526};
constexpr double kGaussWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                     0.3478548451374538};

// Where the ray c0 + t dc (index space) is inside the box [lo, hi]: [enter, exit], empty when
// enter >= exit.
glm::dvec2 boxSpan(glm::dvec3 c0, glm::dvec3 dc, glm::dvec3 lo, glm::dvec3 hi) {
  double enter = 0.0;
  double exit = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (dc[a] == 0.0) {
      if (c0[a] < lo[a] || c0[a] > hi[a]) return glm::dvec2(0.0);
      continue;
    }
    double t0 = (lo[a] - c0[a]) / dc[a];
    double t1 = (hi[a] - c0[a]) / dc[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
  }
  return glm::dvec2(enter, exit);
}

}  // namespace

glm::dvec3 PinholeCamera::rayDirection(unsigned x, unsigned y) const {
  const glm::dvec3 forward = glm::normalize(lookAt - position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double halfWidth = std::tan(fovDegrees * std::numbers::pi / 360.0);
  const double halfHeight = halfWidth * double(size.y) / double(size.x);
  const double sx = (2.0 * (double(x) + 0.5) / double(size.x) - 1.0) * halfWidth;
  const double sy = (1.0 - 2.0 * (double(y) + 0.5) / double(size.y)) * halfHeight;
  return glm::normalize(forward + right * sx + up * sy);
}

double opticalDepth(const NvdfSampler& cloud, glm::dvec3 origin, glm::dvec3 direction,
                    double extinctionPerMetre) {
  const glm::dvec3 c0 = cloud.toIndex(origin);
  const glm::dvec3 dc = direction / double(cloud.volume().voxelMetres);
  // Cells with a cloudy corner lie within one voxel of the outermost centres.
  const glm::dvec2 span = boxSpan(c0, dc, glm::dvec3(-1.0), glm::dvec3(cloud.volume().size));
  if (!(span.x < span.y)) return 0.0;

  // The distances where the ray crosses a lattice plane: between two, one cell's polynomial.
  std::vector<double> breaks{span.x, span.y};
  for (int a = 0; a < 3; ++a) {
    if (dc[a] == 0.0) continue;
    const double from = c0[a] + span.x * dc[a];
    const double to = c0[a] + span.y * dc[a];
    const double lo = std::min(from, to);
    const double hi = std::max(from, to);
    for (double k = std::floor(lo) + 1.0; k < hi; k += 1.0) {
      breaks.push_back((k - c0[a]) / dc[a]);
    }
  }
  std::sort(breaks.begin(), breaks.end());

  double integral = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i];
    const double b = breaks[i + 1];
    if (b <= a) continue;
    const double half = 0.5 * (b - a);
    const double mid = 0.5 * (a + b);
    double sum = 0.0;
    for (int n = 0; n < 4; ++n) {
      sum += kGaussWeights[n] * cloud.density(origin + direction * (mid + half * kGaussNodes[n]));
    }
    integral += sum * half;
  }
  return integral * extinctionPerMetre;
}

std::vector<float> opacityImage(const NvdfSampler& cloud, const PinholeCamera& camera,
                                double extinctionPerMetre) {
  std::vector<float> image(std::size_t(camera.size.x) * camera.size.y);
  for (unsigned y = 0; y < camera.size.y; ++y) {
    for (unsigned x = 0; x < camera.size.x; ++x) {
      const double tau =
          opticalDepth(cloud, camera.position, camera.rayDirection(x, y), extinctionPerMetre);
      image[std::size_t(y) * camera.size.x + x] = float(1.0 - std::exp(-tau));
    }
  }
  return image;
}

}  // namespace clouds::reference
