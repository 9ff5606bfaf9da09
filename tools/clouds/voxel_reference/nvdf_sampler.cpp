#include "nvdf_sampler.h"

#include <cmath>

namespace clouds::reference {

NvdfSampler::NvdfSampler(const NvdfVolume& volume) : volume_(volume) {}

glm::dvec3 NvdfSampler::toIndex(glm::dvec3 positionMetres) const {
  return (positionMetres - glm::dvec3(volume_.originMetres)) / double(volume_.voxelMetres);
}

template <typename Value>
double NvdfSampler::trilinear(glm::dvec3 c, Value value) const {
  const glm::dvec3 base = glm::floor(c);
  const glm::dvec3 f = c - base;
  const glm::ivec3 i0(base);
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
    const double weight =
        (o.x != 0 ? f.x : 1.0 - f.x) * (o.y != 0 ? f.y : 1.0 - f.y) * (o.z != 0 ? f.z : 1.0 - f.z);
    if (weight == 0.0) continue;
    sum += weight * value(i0 + o);
  }
  return sum;
}

double NvdfSampler::field(glm::dvec3 positionMetres, NvdfChannel channel) const {
  const glm::ivec3 size(volume_.size);
  return trilinear(toIndex(positionMetres), [&](glm::ivec3 v) {
    if (glm::any(glm::lessThan(v, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(v, size))) {
      return 0.0;
    }
    return double(volume_.field(glm::uvec3(v), channel));
  });
}

double NvdfSampler::profile(glm::dvec3 positionMetres) const {
  return field(positionMetres, kNvdfProfile);
}

double NvdfSampler::density(glm::dvec3 positionMetres) const {
  const double profile = field(positionMetres, kNvdfProfile);
  if (profile == 0.0) return 0.0;
  return profile * field(positionMetres, kNvdfDensityScale) * double(volume_.densityMultiplier);
}

double NvdfSampler::signedDistanceMetres(glm::dvec3 positionMetres) const {
  const glm::ivec3 last = glm::ivec3(volume_.size) - 1;
  return trilinear(toIndex(positionMetres), [&](glm::ivec3 v) {
    return double(volume_.distanceMetres(glm::uvec3(glm::clamp(v, glm::ivec3(0), last))));
  });
}

}  // namespace clouds::reference
