#include "engine/render/exposure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/render/scene_components.h"

namespace {

using namespace engine::render;

TEST(Exposure, NoonSunlightMetersSunny16) {
  // 100 klx under a meter of C = 250: log2(100000 * 100 / 250) = 15.29.
  EXPECT_NEAR(ev100FromIlluminance(100000.0), 15.29f, 0.01f);
  EXPECT_NEAR(ev100FromIlluminance(200000.0) - ev100FromIlluminance(100000.0), 1.0f, 1e-5f)
      << "twice the light, one stop";
  EXPECT_TRUE(std::isfinite(ev100FromIlluminance(0.0))) << "darkness meters a finite value";
  EXPECT_TRUE(std::isfinite(ev100FromIlluminance(-5.0)));
}

TEST(Exposure, DimLightIsExposedDarkerThanTheMeterSays) {
  EXPECT_EQ(dimLightCompensationEv(15.0f), 0.0f) << "daylight as metered";
  EXPECT_EQ(dimLightCompensationEv(10.0f), 0.0f);
  EXPECT_NEAR(dimLightCompensationEv(5.0f), -1.5f, 1e-6f);
  EXPECT_NEAR(dimLightCompensationEv(0.0f), -3.0f, 1e-6f);
  EXPECT_NEAR(dimLightCompensationEv(-5.0f), -3.0f, 1e-6f) << "no darker than 3 stops";
  EXPECT_LT(dimLightCompensationEv(6.0f), dimLightCompensationEv(7.0f)) << "monotonic";
}

TEST(Exposure, ScaleMapsTheSaturatingRadianceToOne) {
  // At EV100 e, 1.2 * 2^e cd/m^2 (in kcd/m^2 here) reaches the display's white.
  for (float ev : {-2.0f, 0.0f, 9.5f, 15.0f}) {
    const double saturating = 1.2 * std::exp2(double(ev)) / 1000.0;  // kcd/m^2
    EXPECT_NEAR(exposureScale(ev) * saturating, 1.0, 1e-5) << ev;
  }
  EXPECT_NEAR(exposureScale(14.0f) / exposureScale(15.0f), 2.0f, 1e-5f);
}

TEST(Exposure, HorizontalIlluminanceIsTheSunsCosineAndTheSkysMean) {
  SkyLight dark;
  dark.zenith = dark.horizon = dark.ground = glm::vec3(0.0f);
  const glm::vec3 white(100.0f);
  EXPECT_NEAR(horizontalIlluminanceKilolux(white, 1.0, dark), 100.0, 1e-4);
  EXPECT_NEAR(horizontalIlluminanceKilolux(white, 0.5, dark), 50.0, 1e-4) << "Lambert";
  EXPECT_NEAR(horizontalIlluminanceKilolux(white, -0.3, dark), 0.0, 1e-9) << "set sun";

  // A sky mixed from horizon to zenith by sqrt(sin(elevation)): integrate L cos(theta) over the
  // hemisphere numerically and compare (the ground's light is not on a surface facing up).
  SkyLight sky;
  sky.zenith = glm::vec3(2.0f);
  sky.horizon = glm::vec3(6.0f);
  double integral = 0.0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const double mu = (i + 0.5) / steps;  // cos(zenith angle) = sin(elevation)
    const double radiance = 6.0 + (2.0 - 6.0) * std::sqrt(mu);
    integral += radiance * mu * (2.0 * 3.14159265358979 / steps);  // d(omega) = 2 pi d(mu)
  }
  EXPECT_NEAR(horizontalIlluminanceKilolux(glm::vec3(0.0f), 1.0, sky), integral, 1e-3);
}

// Under a cover (CoveredSkyLight): the sun through it at the camera and around it (their mean),
// its measured sky below it, the clear sky above it and a linear blend by altitude inside it.
TEST(Exposure, ACoveredSkyIsMeteredThroughItsCoverAndBlendsIntoTheClearSkyAboveIt) {
  SkyLight clear;
  clear.zenith = clear.horizon = glm::vec3(4.0f);  // pi x 4 = 12.57 klx from the sky
  const glm::vec3 sun(100.0f);
  const double clearKilolux = horizontalIlluminanceKilolux(sun, 1.0, clear);
  ASSERT_NEAR(clearKilolux, 100.0 + 4.0 * 3.14159265358979, 1e-3);
  CoveredSkyLight covered;
  covered.irradianceOverPi = glm::vec3(1.0f);
  covered.sunAtCamera = 0.1f;  // centre-weighted with the land around: a quarter of the sun
  covered.sunAround = 0.4f;
  covered.seenFromMetres = 1000.0;
  covered.clearAboveMetres = 3000.0;
  const double pi = 3.14159265358979;
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, nullptr, 500.0), clearKilolux, 1e-9)
      << "no cover: the clear sky's";
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 500.0), 25.0 + pi, 1e-3)
      << "below the cover: the sun through it and the covered sky's measured irradiance";
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 1000.0), 25.0 + pi, 1e-3);
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 2000.0),
              100.0 * (0.25 + 0.1) / 2.0 + 2.5 * pi, 1e-3)
      << "halfway up the cover: halfway between its sky and the clear sky, and between the sun "
         "centre-weighted and at the camera";
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 5000.0), 10.0 + 4.0 * pi,
              1e-3)
      << "above the cover: the clear sky and the sun as the cover lets it through at the camera";
  covered.sunAtCamera = 1.0f;
  covered.sunAround = 1.0f;
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 5000.0), clearKilolux, 1e-3);
  covered.sunAtCamera = 7.0f;  // out of range: clamped to [0, 1]
  EXPECT_NEAR(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 5000.0), clearKilolux, 1e-3);
  covered.clearAboveMetres = covered.seenFromMetres;  // no thickness: a step, not a division by 0
  EXPECT_TRUE(std::isfinite(horizontalIlluminanceKilolux(sun, 1.0, clear, &covered, 1000.0)));
}

TEST(Exposure, AdaptationIsExponentialAndTakesZeroTimeConstantAtOnce) {
  EXPECT_FLOAT_EQ(adaptEv100(10.0f, 15.0f, 0.1, 0.0), 15.0f);
  EXPECT_NEAR(adaptEv100(10.0f, 15.0f, 0.5, 0.5), 15.0f - 5.0f * std::exp(-1.0f), 1e-5f);
  // Two half steps are one whole step.
  const float half = adaptEv100(adaptEv100(10.0f, 15.0f, 0.25, 0.5), 15.0f, 0.25, 0.5);
  EXPECT_NEAR(half, adaptEv100(10.0f, 15.0f, 0.5, 0.5), 1e-5f);
  EXPECT_FLOAT_EQ(adaptEv100(10.0f, 15.0f, -1.0, 0.5), 10.0f) << "time never runs backwards";
}

}  // namespace
