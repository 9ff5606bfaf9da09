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

TEST(Exposure, AdaptationIsExponentialAndTakesZeroTimeConstantAtOnce) {
  EXPECT_FLOAT_EQ(adaptEv100(10.0f, 15.0f, 0.1, 0.0), 15.0f);
  EXPECT_NEAR(adaptEv100(10.0f, 15.0f, 0.5, 0.5), 15.0f - 5.0f * std::exp(-1.0f), 1e-5f);
  // Two half steps are one whole step.
  const float half = adaptEv100(adaptEv100(10.0f, 15.0f, 0.25, 0.5), 15.0f, 0.25, 0.5);
  EXPECT_NEAR(half, adaptEv100(10.0f, 15.0f, 0.5, 0.5), 1e-5f);
  EXPECT_FLOAT_EQ(adaptEv100(10.0f, 15.0f, -1.0, 0.5), 10.0f) << "time never runs backwards";
}

}  // namespace
