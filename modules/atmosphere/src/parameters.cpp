// Parameters and settings: validation, the quality presets, and the sun's transmittance on the
// CPU (the model header compiled in double precision).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "atmosphere/atmosphere.h"
#include "atmosphere_model.h"
#include "model_from_parameters.h"

namespace atmosphere {
namespace {

struct Checker {
  const char* prefix;
  std::string error;

  template <typename T>
  void range(const char* field, T value, T lo, T hi) {
    if (!error.empty()) return;
    if (!std::isfinite(static_cast<double>(value)) || value < lo || value > hi) {
      std::ostringstream out;
      out << prefix << '.' << field << " = " << value << ": must be in [" << lo << ", " << hi
          << "]";
      error = out.str();
    }
  }
  void range(const char* field, const glm::vec3& value, float lo, float hi) {
    for (int c = 0; c < 3; ++c) {
      const std::string name = std::string(field) + "." + "xyz"[c];
      range(name.c_str(), value[c], lo, hi);
    }
  }
  void require(bool condition, const std::string& message) {
    if (error.empty() && !condition) error = message;
  }
};

}  // namespace

std::string validateParameters(const Parameters& p) {
  Checker c{"Parameters", {}};
  c.range("bottomRadiusMetres", p.bottomRadiusMetres, 1e5f, 1e8f);
  c.range("topRadiusMetres", p.topRadiusMetres, p.bottomRadiusMetres + 1.0f,
          p.bottomRadiusMetres + 1e6f);
  c.range("rayleighScatteringPerMetre", p.rayleighScatteringPerMetre, 0.0f, 1e-3f);
  c.range("rayleighScaleHeightMetres", p.rayleighScaleHeightMetres, 10.0f, 1e6f);
  c.range("mieScatteringPerMetre", p.mieScatteringPerMetre, 0.0f, 1e-3f);
  c.range("mieExtinctionPerMetre", p.mieExtinctionPerMetre, 0.0f, 1e-3f);
  for (int i = 0; i < 3; ++i) {
    c.require(p.mieExtinctionPerMetre[i] >= p.mieScatteringPerMetre[i],
              "Parameters.mieExtinctionPerMetre: must be at least mieScatteringPerMetre "
              "(extinction is scattering plus absorption)");
  }
  c.range("mieScaleHeightMetres", p.mieScaleHeightMetres, 10.0f, 1e6f);
  c.range("miePhaseG", p.miePhaseG, -0.99f, 0.99f);
  c.range("ozoneAbsorptionPerMetre", p.ozoneAbsorptionPerMetre, 0.0f, 1e-3f);
  c.range("ozoneCentreMetres", p.ozoneCentreMetres, 0.0f, 1e6f);
  c.range("ozoneHalfWidthMetres", p.ozoneHalfWidthMetres, 1.0f, 1e6f);
  c.range("groundAlbedo", p.groundAlbedo, 0.0f, 1.0f);
  c.range("sunAngularRadiusRadians", p.sunAngularRadiusRadians, 1e-4f, 0.2f);
  return c.error;
}

std::string validateSettings(const Settings& s) {
  Checker c{"Settings", {}};
  c.range("transmittanceWidth", s.transmittanceWidth, 4u, 4096u);
  c.range("transmittanceHeight", s.transmittanceHeight, 4u, 4096u);
  c.range("transmittanceSamples", s.transmittanceSamples, 1u, 4096u);
  c.range("multiScatteringSize", s.multiScatteringSize, 4u, 1024u);
  c.range("multiScatteringDirections", s.multiScatteringDirections, 1u, 64u);
  c.range("multiScatteringSamples", s.multiScatteringSamples, 1u, 4096u);
  c.range("skyViewWidth", s.skyViewWidth, 4u, 4096u);
  c.range("skyViewHeight", s.skyViewHeight, 4u, 4096u);
  c.range("skyViewSamples", s.skyViewSamples, 1u, 4096u);
  c.range("skyViewAltitudeTolerance", s.skyViewAltitudeTolerance, 0.0f, 0.1f);
  c.range("aerialPerspectiveWidth", s.aerialPerspectiveWidth, 1u, 512u);
  c.range("aerialPerspectiveHeight", s.aerialPerspectiveHeight, 1u, 512u);
  c.range("aerialPerspectiveSlices", s.aerialPerspectiveSlices, 1u, 512u);
  c.range("aerialPerspectiveSamplesPerSlice", s.aerialPerspectiveSamplesPerSlice, 1u, 64u);
  c.range("aerialPerspectiveRangeMetres", s.aerialPerspectiveRangeMetres, 100.0f, 1e7f);
  return c.error;
}

const char* qualityName(Quality quality) {
  switch (quality) {
    case Quality::Low:
      return "Low";
    case Quality::Medium:
      return "Medium";
    case Quality::High:
      return "High";
    case Quality::Reference:
      return "Reference";
  }
  return "?";
}

bool parseQuality(std::string_view name, Quality* quality) {
  for (Quality q : {Quality::Low, Quality::Medium, Quality::High, Quality::Reference}) {
    const std::string_view candidate = qualityName(q);
    if (std::equal(name.begin(), name.end(), candidate.begin(), candidate.end(),
                   [](char a, char b) {
                     return std::tolower(static_cast<unsigned char>(a)) ==
                            std::tolower(static_cast<unsigned char>(b));
                   })) {
      *quality = q;
      return true;
    }
  }
  return false;
}

Settings settingsFor(Quality quality) {
  Settings s;  // High: Hillaire 2020's sizes
  switch (quality) {
    case Quality::Low:
      s.skyViewWidth = 96;
      s.skyViewHeight = 54;
      s.skyViewSamples = 12;
      s.aerialPerspectiveWidth = 16;
      s.aerialPerspectiveHeight = 16;
      s.aerialPerspectiveSlices = 24;
      s.aerialPerspectiveSamplesPerSlice = 1;
      break;
    case Quality::Medium:
      // 96 x 54: 0.1 dB under 128 x 72 for 70% of the sky-view LUT's time (atmosphere_bench).
      s.skyViewWidth = 96;
      s.skyViewHeight = 54;
      s.skyViewSamples = 16;
      s.aerialPerspectiveWidth = 24;
      s.aerialPerspectiveHeight = 24;
      s.aerialPerspectiveSamplesPerSlice = 1;
      break;
    case Quality::High:
      break;
    case Quality::Reference:
      s.transmittanceWidth = 512;
      s.transmittanceHeight = 128;
      s.transmittanceSamples = 400;
      s.multiScatteringSize = 64;
      s.multiScatteringDirections = 16;
      s.multiScatteringSamples = 80;
      s.skyViewWidth = 512;
      s.skyViewHeight = 288;
      s.skyViewSamples = 200;
      s.skyViewAltitudeTolerance = 0.0f;  // converged: rebuilt for every altitude
      s.aerialPerspectiveWidth = 64;
      s.aerialPerspectiveHeight = 64;
      s.aerialPerspectiveSlices = 96;
      s.aerialPerspectiveSamplesPerSlice = 8;
      break;
  }
  return s;
}

glm::vec3 sunTransmittance(const Parameters& parameters, double altitudeMetres,
                           const glm::dvec3& sunDirection, std::uint32_t samples) {
  const model::AtmosphereModel a = detail::modelFrom(parameters);
  const double length = glm::length(sunDirection);
  if (!(length > 0.0) || !std::isfinite(altitudeMetres)) return glm::vec3(0.0f);
  const double r = a.bottomRadius + std::max(altitudeMetres, 0.0);
  const double mu = sunDirection.y / length;
  if (model::rayHitsGround(r, mu, a)) return glm::vec3(0.0f);
  return glm::vec3(glm::exp(-model::opticalDepthToTop(r, mu, std::max(samples, 1u), a)));
}

}  // namespace atmosphere
