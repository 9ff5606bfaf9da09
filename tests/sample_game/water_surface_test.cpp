// The water's surface model (sample_game/shaders/water_surface.h), evaluated on the CPU from the
// very header its shader includes: Fresnel's reflectance, the ripples' filtering into roughness,
// the glint's energy, the bed's share and the phases' precision over long runs and far away.
#include <gtest/gtest.h>

#include <cmath>

#include "water_surface.h"

namespace {

using namespace engine::shaders;

constexpr double kPi = 3.14159265358979323846;

TEST(WaterSurface, FresnelReflectsATwentiethHeadOnAndAllAtGrazing) {
  EXPECT_NEAR(waterFresnel(1.0f), 0.02f, 1e-6f);  // ((1.33 - 1) / (1.33 + 1))^2
  EXPECT_NEAR(waterFresnel(0.0f), 1.0f, 1e-6f);
  float previous = waterFresnel(1.0f);
  for (float c = 0.95f; c >= 0.0f; c -= 0.05f) {
    const float f = waterFresnel(c);
    EXPECT_GE(f, previous) << "the reflectance grows towards grazing, cosine " << c;
    previous = f;
  }
}

// Over a whole period of every wave, the slope the pixel resolves plus the variance it does not
// is the ripples' whole slope variance, at every footprint: filtering moves it from the normal
// into the roughness, and loses none of it.
TEST(WaterSurface, RipplesAPixelDoesNotResolveBecomeRoughness) {
  const auto slopeVariance = [](float footprint) {
    double meanSquare = 0.0, unresolved = 0.0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
      // Points along a line that crosses each wave's crests at incommensurate rates.
      const glm::vec2 xz(0.731f * float(i) * 0.37f, 0.913f * float(i) * 0.41f);
      const glm::vec3 r = waterRipples(xz, glm::vec4(0.0f), glm::vec4(0.0f), footprint);
      meanSquare += double(r.x) * r.x + double(r.y) * r.y;
      unresolved += r.z;
    }
    return std::pair{meanSquare / n, unresolved / n};
  };
  const auto [near, nearRoughness] = slopeVariance(0.01f);  // a centimetre: every wave resolved
  const auto [far, farRoughness] = slopeVariance(50.0f);    // 50 m: none
  EXPECT_EQ(nearRoughness, 0.0);
  EXPECT_EQ(far, 0.0) << "no ripple the pixel cannot resolve is left in its normal";
  // Eight waves of greatest slope 0.05: each adds 0.05^2 / 2 to the variance.
  EXPECT_NEAR(farRoughness, 8 * 0.5 * 0.05 * 0.05, 1e-7);
  EXPECT_NEAR(near, farRoughness, 0.15 * farRoughness)
      << "the resolved ripples' slope variance is what the far water's roughness stands for";
  // In between, the two shares still add up.
  const auto [mid, midRoughness] = slopeVariance(0.6f);
  EXPECT_GT(mid, 0.0);
  EXPECT_GT(midRoughness, 0.0);
  EXPECT_NEAR(mid + midRoughness, farRoughness, 0.15 * farRoughness);
}

// The glint is a microfacet lobe: integrated over the sun's directions (it holds the cosine at the
// surface already: radiance per unit of the illuminance across the sun's beam) it gives the
// share of light from all around that the surface reflects towards the viewer: Fresnel's (a few
// percent), however rough the water.
TEST(WaterSurface, TheGlintReflectsFresnelsShareOfTheSun) {
  const glm::vec3 normal(0.0f, 1.0f, 0.0f);
  for (const float viewCosine : {0.9f, 0.5f}) {
    const glm::vec3 toViewer(std::sqrt(1.0f - viewCosine * viewCosine), viewCosine, 0.0f);
    for (const float roughness2 : {0.0f, 0.01f, 0.05f}) {
      double reflected = 0.0;
      const int thetaSteps = 1200, phiSteps = 480;
      for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) / thetaSteps * 0.5 * kPi;
        for (int j = 0; j < phiSteps; ++j) {
          const double phi = (j + 0.5) / phiSteps * 2.0 * kPi;
          const glm::vec3 toSun(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                float(std::sin(theta) * std::sin(phi)));
          const double solidAngle =
              std::sin(theta) * (0.5 * kPi / thetaSteps) * (2.0 * kPi / phiSteps);
          reflected += double(waterGlint(normal, toViewer, toSun, roughness2)) * solidAngle;
        }
      }
      // The mirror direction's Fresnel, up to a tenth more as the lobe widens towards facets
      // seen more obliquely (a double-precision integral over the half vectors gives 1.00 to
      // 1.10 times it for these cases).
      const double fresnel = waterFresnel(viewCosine);
      EXPECT_GT(reflected, 0.97 * fresnel)
          << "view cosine " << viewCosine << ", m^2 " << roughness2;
      EXPECT_LT(reflected, 1.13 * fresnel)
          << "view cosine " << viewCosine << ", m^2 " << roughness2;
    }
  }
  // No light from behind the surface, none towards a viewer below it.
  EXPECT_EQ(waterGlint(normal, glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), 0.01f), 0.0f);
  EXPECT_EQ(waterGlint(normal, glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), 0.01f), 0.0f);
}

TEST(WaterSurface, TheBedFadesAsTheViewGrazes) {
  EXPECT_FLOAT_EQ(waterBedShare(0.35f, 1.0f), 0.35f);
  EXPECT_FLOAT_EQ(waterBedShare(0.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(waterBedShare(1.0f, 0.1f), 1.0f);
  EXPECT_NEAR(waterBedShare(0.35f, 0.5f), 0.35f * 0.35f, 1e-6f);  // twice the path
  EXPECT_LT(waterBedShare(0.35f, 0.0f), 1e-9f);
}

// The bed's reach: there the water lets through 1/255 of the bed's light, nearer more, farther
// less; so the water beyond it may hide the bed (drawn before the terrain) with an error under
// one 8-bit step of the bed's light.
TEST(WaterSurface, BeyondTheBedsReachLessThanAStepOfItShows) {
  for (const float clarity : {0.1f, 0.35f, 0.8f}) {
    for (const float height : {2.0f, 85.0f, 3000.0f}) {
      const float reach = waterBedReachMetres(clarity, height);
      const auto shareAt = [&](float horizontal) {
        return waterBedShare(clarity,
                             height / std::sqrt(height * height + horizontal * horizontal));
      };
      EXPECT_NEAR(shareAt(reach), 1.0f / 255.0f, 1e-5f) << clarity << ", " << height << " m";
      EXPECT_GT(shareAt(0.9f * reach), 1.0f / 255.0f);
      EXPECT_LT(shareAt(1.1f * reach), 1.0f / 255.0f);
    }
  }
  EXPECT_EQ(waterBedReachMetres(0.0f, 100.0f), 0.0f) << "murky water shows no bed";
  EXPECT_EQ(waterBedReachMetres(1.0f, 100.0f), kWaterReachMetres) << "clear water all of it";
  EXPECT_EQ(waterBedReachMetres(0.35f, -5.0f), kWaterReachMetres) << "seen from below";
  EXPECT_EQ(waterBedReachMetres(0.99f, 5000.0f), kWaterReachMetres) << "clamped to the water";
}

// The waves run on smoothly after any uptime and anywhere: one frame (1/60 s) later each wave's
// phase has moved by its angular frequency times the step, at the origin at start-up as well as
// 10,000 km away after eleven days; and a step along the ground moves the phase by k dx.
TEST(WaterSurface, PhasesStayExactAfterLongRunsFarFromTheOrigin) {
  const double step = 1.0 / 60.0;
  for (const glm::dvec2 place : {glm::dvec2(0.0), glm::dvec2(1e7, -1e7)}) {
    for (const double seconds : {0.0, 1e6}) {
      const WaterPhases now = waterPhasesAt(place, seconds);
      const WaterPhases next = waterPhasesAt(place, seconds + step);
      for (int i = 0; i < kWaterWaves; ++i) {
        EXPECT_GE(now[i], 0.0f);
        EXPECT_LT(now[i], float(2.0 * kPi));
        double moved = double(now[i]) - double(next[i]);
        moved -= 2.0 * kPi * std::floor(moved / (2.0 * kPi) + 0.5);
        EXPECT_NEAR(moved, double(waterAngularFrequency(i)) * step, 1e-5)
            << "wave " << i << " at " << place.x << " m after " << seconds << " s";
      }
      // The same point of the water, reached from two camera places, has the same ripples.
      const glm::dvec2 moved = place + glm::dvec2(37.25, -12.5);
      const WaterPhases there = waterPhasesAt(moved, seconds);
      const glm::vec3 a = waterRipples(glm::vec2(37.25f, -12.5f), now.first, now.second, 0.01f);
      const glm::vec3 b = waterRipples(glm::vec2(0.0f), there.first, there.second, 0.01f);
      EXPECT_NEAR(a.x, b.x, 2e-5f);
      EXPECT_NEAR(a.y, b.y, 2e-5f);
    }
  }
}

}  // namespace
