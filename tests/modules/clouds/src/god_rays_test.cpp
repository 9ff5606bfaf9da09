// The god rays' arithmetic without a GPU (fxcontracts/god_rays.h, god_rays.h): where the sun is on
// screen and how the mask fades as it leaves, the radial blur's averaging, and the Mie share
// that puts the shafts towards the sun.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cloud_harness.h"
#include "fxcontracts/god_rays.h"
#include "god_rays.h"

namespace {

using clouds::detail::godRaySun;

// The occlusion the blur reads in these tests: a function of uv.
float (*gOcclusion)(glm::vec2) = nullptr;

}  // namespace

float fxcontracts::shader::fetchGodRayOcclusion(glm::vec2 uv) {
  return gOcclusion(uv);
}

namespace {

clouds::tools::CloudView towardsTheSun() {
  clouds::tools::CloudView view;
  view.sunElevationDegrees = 20.0;
  view.sunAzimuthDegrees = 200.0;
  view.yawDegrees = 200.0;
  view.pitchDegrees = 20.0;
  return view;
}

clouds::detail::GodRaySun sunFor(const clouds::tools::CloudView& view) {
  const VkExtent2D extent{320, 180};
  return godRaySun(clouds::tools::viewMatrix(view), clouds::tools::projectionMatrix(view, extent),
                   clouds::tools::sunDirection(view));
}

TEST(GodRays, TheSunAheadIsInTheMiddleOfTheScreen) {
  const clouds::detail::GodRaySun sun = sunFor(towardsTheSun());
  EXPECT_NEAR(sun.uv.x, 0.5f, 1e-4f);
  EXPECT_NEAR(sun.uv.y, 0.5f, 1e-4f);
  EXPECT_FLOAT_EQ(sun.fade, 1.0f);
}

TEST(GodRays, TheSunAboveTheMiddleIsHigherOnScreen) {
  clouds::tools::CloudView view = towardsTheSun();
  view.pitchDegrees = 10.0;  // the sun 10 degrees above the view's centre: y is down
  const clouds::detail::GodRaySun sun = sunFor(view);
  EXPECT_LT(sun.uv.y, 0.5f);
  EXPECT_NEAR(sun.uv.x, 0.5f, 1e-4f);
}

TEST(GodRays, TheFadeFallsAsTheSunLeavesTheScreenAndIsZeroBehind) {
  clouds::tools::CloudView view = towardsTheSun();
  float previous = 1.0f;
  bool reachedZero = false;
  for (double yaw = 0.0; yaw <= 180.0; yaw += 5.0) {
    view.yawDegrees = 200.0 + yaw;
    const clouds::detail::GodRaySun sun = sunFor(view);
    ASSERT_TRUE(std::isfinite(sun.fade) && std::isfinite(sun.uv.x) && std::isfinite(sun.uv.y));
    EXPECT_LE(sun.fade, previous + 1e-6f) << "yaw " << yaw;
    EXPECT_GE(sun.uv.x, -4.0f);
    EXPECT_LE(sun.uv.x, 5.0f);
    previous = sun.fade;
    reachedZero = reachedZero || sun.fade == 0.0f;
  }
  EXPECT_TRUE(reachedZero);
  view.yawDegrees = 20.0;  // straight away from the sun
  EXPECT_EQ(sunFor(view).fade, 0.0f);
  view.yawDegrees = 200.0 + 90.0;  // the sun exactly beside the camera: w = 0
  EXPECT_EQ(sunFor(view).fade, 0.0f);
}

TEST(GodRays, ASunBelowTheHorizonFades) {
  clouds::tools::CloudView view = towardsTheSun();
  view.pitchDegrees = 0.0;
  view.sunElevationDegrees = 2.0;
  EXPECT_FLOAT_EQ(sunFor(view).fade, 1.0f);
  view.sunElevationDegrees = 0.0;
  EXPECT_NEAR(sunFor(view).fade, 0.5f, 1e-3f);
  view.sunElevationDegrees = -2.0;
  EXPECT_EQ(sunFor(view).fade, 0.0f);
}

TEST(GodRays, ABadSunDirectionFadesToNothing) {
  const glm::mat4 identity(1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(godRaySun(identity, identity, glm::vec3(0.0f)).fade, 0.0f);
  EXPECT_EQ(godRaySun(identity, identity, glm::vec3(nan, 1.0f, 0.0f)).fade, 0.0f);
}

TEST(GodRays, TheMaskIsTheWeightedMeanOfTheOcclusionOnTheWayToTheSun) {
  fxcontracts::shader::GodRayParameters p{};
  p.sun = glm::vec4(0.9f, 0.5f, 1.0f, 16.0f);
  p.blur = glm::vec4(1.0f, 0.9f, 80.0f, 45.0f);
  gOcclusion = [](glm::vec2) { return 0.3f; };
  EXPECT_NEAR(fxcontracts::shader::godRayMaskAt({0.1f, 0.5f}, p), 0.3f, 1e-6f);
  // Everything left of x = 0.5 is hidden: a texel at 0.1 sees its first samples hidden, the
  // later ones (nearer the sun) clear, weighted towards the first.
  gOcclusion = [](glm::vec2 uv) { return uv.x < 0.5f ? 0.0f : 1.0f; };
  const float m = fxcontracts::shader::godRayMaskAt({0.1f, 0.5f}, p);
  float clear = 0.0f;
  float all = 0.0f;
  float w = 1.0f;
  for (int i = 0; i < 16; ++i) {
    const float x = 0.1f + 0.8f * (float(i) + 0.5f) / 16.0f;
    clear += x < 0.5f ? 0.0f : w;
    all += w;
    w *= 0.9f;
  }
  EXPECT_NEAR(m, clear / all, 1e-6f);
  EXPECT_GT(m, 0.2f);
  EXPECT_LT(m, 0.5f);
  EXPECT_FLOAT_EQ(fxcontracts::shader::godRayMaskAt({0.7f, 0.5f}, p), 1.0f) << "a clear way";
  p.sun.w = 0.0f;
  EXPECT_FLOAT_EQ(fxcontracts::shader::godRayMaskAt({0.1f, 0.5f}, p), 1.0f)
      << "no samples: no mask";
}

TEST(GodRays, TheMieShareIsLargeTowardsTheSunAndSmallAcross) {
  const glm::vec3 rayleigh(5.802e-6f, 13.558e-6f, 33.1e-6f);
  const glm::vec3 mie(3.996e-6f);
  const glm::vec3 towards = fxcontracts::shader::godRayMieShare(rayleigh, mie, 0.8f, 1.0f);
  const glm::vec3 across = fxcontracts::shader::godRayMieShare(rayleigh, mie, 0.8f, 0.0f);
  // Earth's air: Mie outshines Rayleigh towards the sun (less so in blue, where Rayleigh is
  // strongest), and Rayleigh wins across.
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(towards[c], 0.75f);
    EXPECT_LT(across[c], 0.2f);
    EXPECT_GT(across[c], 0.0f);
  }
  EXPECT_GT(towards.r, towards.b);
  EXPECT_EQ(fxcontracts::shader::godRayMieShare(glm::vec3(0.0f), glm::vec3(0.0f), 0.8f, 1.0f),
            glm::vec3(0.0f));
}

}  // namespace
