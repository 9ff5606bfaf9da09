// Parameters and settings as a host meets them: out-of-range values are named with the field,
// the presets are valid and cost more as they go up, quality names parse.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "atmosphere/atmosphere.h"

namespace {

TEST(AtmosphereParameters, EarthDefaultsAndPresetsAreValid) {
  EXPECT_EQ(atmosphere::validateParameters(atmosphere::Parameters{}), "");
  for (auto q : {atmosphere::Quality::Low, atmosphere::Quality::Medium, atmosphere::Quality::High,
                 atmosphere::Quality::Reference}) {
    EXPECT_EQ(atmosphere::validateSettings(atmosphere::settingsFor(q)), "")
        << atmosphere::qualityName(q);
  }
  // The planet the clouds module assumes.
  EXPECT_EQ(atmosphere::Parameters{}.bottomRadiusMetres, 6360e3f);
}

TEST(AtmosphereParameters, OutOfRangeValuesAreNamedWithTheirField) {
  atmosphere::Parameters p;
  p.miePhaseG = 1.0f;
  EXPECT_EQ(atmosphere::validateParameters(p).rfind("Parameters.miePhaseG = 1", 0), 0u)
      << atmosphere::validateParameters(p);
  p = {};
  p.rayleighScatteringPerMetre.y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(atmosphere::validateParameters(p).find("rayleighScatteringPerMetre.y"),
            std::string::npos);
  p = {};
  p.topRadiusMetres = p.bottomRadiusMetres;
  EXPECT_NE(atmosphere::validateParameters(p).find("topRadiusMetres"), std::string::npos);
  p = {};
  p.mieExtinctionPerMetre = glm::vec3(1e-6f);  // below the scattering: negative absorption
  EXPECT_NE(atmosphere::validateParameters(p).find("mieExtinctionPerMetre"), std::string::npos);

  atmosphere::Settings s;
  s.aerialPerspectiveSlices = 0;
  EXPECT_EQ(atmosphere::validateSettings(s).rfind("Settings.aerialPerspectiveSlices = 0", 0), 0u);
  s = {};
  s.aerialPerspectiveRangeMetres = std::numeric_limits<float>::infinity();
  EXPECT_NE(atmosphere::validateSettings(s).find("aerialPerspectiveRangeMetres"),
            std::string::npos);
}

TEST(AtmosphereParameters, PresetsCostMoreAsTheyGoUp) {
  // Per-frame work: sky-view texels x samples, plus froxel columns x slices x samples.
  const auto work = [](const atmosphere::Settings& s) {
    return double(s.skyViewWidth) * s.skyViewHeight * s.skyViewSamples +
           double(s.aerialPerspectiveWidth) * s.aerialPerspectiveHeight *
               s.aerialPerspectiveSlices * s.aerialPerspectiveSamplesPerSlice;
  };
  double previous = 0.0;
  for (auto q : {atmosphere::Quality::Low, atmosphere::Quality::Medium, atmosphere::Quality::High,
                 atmosphere::Quality::Reference}) {
    const double w = work(atmosphere::settingsFor(q));
    EXPECT_GT(w, previous) << atmosphere::qualityName(q);
    previous = w;
  }
}

TEST(AtmosphereParameters, QualityNamesParseCaseInsensitively) {
  atmosphere::Quality q = atmosphere::Quality::Low;
  EXPECT_TRUE(atmosphere::parseQuality("high", &q));
  EXPECT_EQ(q, atmosphere::Quality::High);
  EXPECT_TRUE(atmosphere::parseQuality("Reference", &q));
  EXPECT_EQ(q, atmosphere::Quality::Reference);
  EXPECT_FALSE(atmosphere::parseQuality("ultra", &q));
}

TEST(AtmosphereParameters, SunTransmittanceIsFiniteForAnyInput) {
  const atmosphere::Parameters earth;
  for (double altitude : {-100.0, 0.0, 1e5, 1e7, std::numeric_limits<double>::quiet_NaN()}) {
    for (glm::dvec3 sun :
         {glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 0)}) {
      const glm::vec3 t = atmosphere::sunTransmittance(earth, altitude, sun);
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(t[c]) && t[c] >= 0.0f && t[c] <= 1.0f)
            << altitude << " " << sun.y;
      }
    }
  }
}

}  // namespace
