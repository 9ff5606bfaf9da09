#include "atmosphere_reference.h"

#include <algorithm>
#include <thread>

#include "model_from_parameters.h"

namespace atmosphere::model {
namespace {
// The LUTs the model's prototypes read, per thread (each worker sets them).
thread_local const reference::Lut* tTransmittance = nullptr;
thread_local const reference::Lut* tMultiScattering = nullptr;
}  // namespace

vec3 sampleTransmittance(vec2 uv) {
  return tTransmittance->sample(uv);
}
vec3 sampleMultiScattering(vec2 uv) {
  return tMultiScattering != nullptr ? tMultiScattering->sample(uv) : vec3(0.0);
}

}  // namespace atmosphere::model

namespace atmosphere::reference {
namespace {

using namespace model;

// Fills every texel of `lut` with `texel(x, y)`, on two threads, each with `transmittance`
// and `multiScattering` as the model's textures.
template <typename Texel>
void fill(Lut& lut, const Lut* transmittance, const Lut* multiScattering, Texel texel) {
  lut.texels.resize(std::size_t{lut.width} * lut.height);
  const auto work = [&](std::uint32_t first) {
    tTransmittance = transmittance;
    tMultiScattering = multiScattering;
    for (std::uint32_t y = first; y < lut.height; y += 2) {
      for (std::uint32_t x = 0; x < lut.width; ++x) lut.texels[y * lut.width + x] = texel(x, y);
    }
  };
  std::thread other(work, 1u);
  work(0u);
  other.join();
}

}  // namespace

glm::dvec3 Lut::sample(glm::dvec2 uv) const {
  const glm::dvec2 p = uv * glm::dvec2(width, height) - 0.5;
  const glm::dvec2 f = p - glm::floor(p);
  const auto clampX = [&](double x) {
    return static_cast<std::uint32_t>(std::clamp(x, 0.0, double(width - 1)));
  };
  const auto clampY = [&](double y) {
    return static_cast<std::uint32_t>(std::clamp(y, 0.0, double(height - 1)));
  };
  const double x0 = std::floor(p.x);
  const double y0 = std::floor(p.y);
  const glm::dvec3 a = at(clampX(x0), clampY(y0));
  const glm::dvec3 b = at(clampX(x0 + 1), clampY(y0));
  const glm::dvec3 c = at(clampX(x0), clampY(y0 + 1));
  const glm::dvec3 d = at(clampX(x0 + 1), clampY(y0 + 1));
  return glm::mix(glm::mix(a, b, f.x), glm::mix(c, d, f.x), f.y);
}

Reference::Reference(const Parameters& parameters, const Settings& settings)
    : model_(detail::modelFrom(parameters)), settings_(settings) {
  const AtmosphereModel& a = model_;
  transmittance_.width = settings.transmittanceWidth;
  transmittance_.height = settings.transmittanceHeight;
  fill(transmittance_, nullptr, nullptr, [&](std::uint32_t x, std::uint32_t y) {
    double r = 0.0;
    double mu = 0.0;
    transmittanceParams(
        (glm::dvec2(x, y) + 0.5) / glm::dvec2(transmittance_.width, transmittance_.height), a, r,
        mu);
    return glm::exp(-opticalDepthToTop(r, mu, settings.transmittanceSamples, a));
  });
  const std::uint32_t n = settings.multiScatteringSize;
  multiScattering_.width = n;
  multiScattering_.height = n;
  fill(multiScattering_, &transmittance_, nullptr, [&](std::uint32_t x, std::uint32_t y) {
    return multipleScatteringTexel((glm::dvec2(x, y) + 0.5) / double(n), double(n),
                                   settings.multiScatteringDirections,
                                   settings.multiScatteringSamples, a);
  });
}

Lut Reference::skyView(double altitudeMetres, double sunZenithCos) const {
  const AtmosphereModel& a = model_;
  Lut lut;
  lut.width = settings_.skyViewWidth;
  lut.height = settings_.skyViewHeight;
  // As the GPU's uniforms have them: the camera's radius in float, the dip from it in double.
  const double r = double(float(a.bottomRadius + std::max(altitudeMetres, 1.0)));
  const glm::dvec2 size(lut.width, lut.height);
  const double beta = horizonDip(r, a);
  fill(lut, &transmittance_, &multiScattering_, [&](std::uint32_t x, std::uint32_t y) {
    double viewZenithCos = 0.0;
    double lightViewCos = 0.0;
    skyViewParams((glm::dvec2(x, y) + 0.5) / size, beta, size, viewZenithCos, lightViewCos);
    const Scattering s =
        integrateScattering(glm::dvec3(0.0, r, 0.0), skyViewDirection(viewZenithCos, lightViewCos),
                            sunInSkyViewFrame(sunZenithCos), 1e9, settings_.skyViewSamples,
                            kPhaseAtmosphere, 1u, double(settings_.multiScatteringSize), 1u, a);
    return s.luminance;
  });
  return lut;
}

void Reference::bindToThisThread() const {
  tTransmittance = &transmittance_;
  tMultiScattering = &multiScattering_;
}

Scattering Reference::scattering(double altitudeMetres, glm::dvec3 direction, glm::dvec3 sun,
                                 std::uint32_t samples, double maxDistance, bool ground) const {
  bindToThisThread();
  const double r = model_.bottomRadius + std::max(altitudeMetres, 1.0);
  return integrateScattering(glm::dvec3(0.0, r, 0.0), glm::normalize(direction),
                             glm::normalize(sun), maxDistance, samples, kPhaseAtmosphere, 1u,
                             double(settings_.multiScatteringSize), ground ? 1u : 0u, model_);
}

}  // namespace atmosphere::reference
