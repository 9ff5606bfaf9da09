// The shared cloud math (shaders/cloud_math.h), compiled as C++: phase normalisation and
// finiteness, planet-scale ray/shell intersection against double precision, jitter patterns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "cloud_march.h"
#include "cloud_math.h"
#include "phase_normaliser.h"

namespace {

using namespace clouds::shader;

// Integral over the sphere of a phase function of cos(theta): 2 pi * int_{-1}^{1} p(mu) dmu,
// by the midpoint rule after substituting mu = +-(1 - x^4) on each half, which crowds samples
// towards mu = +-1 where strong forward or backward peaks are.
double integrateOverSphere(const std::function<double(double)>& phase) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) / n;
    const double mu = 1.0 - x * x * x * x;
    const double dmu = 4.0 * x * x * x / n;
    sum += (phase(mu) + phase(-mu)) * dmu;
  }
  return 2.0 * M_PI * sum;
}

TEST(CloudMath, HenyeyGreensteinIntegratesToOne) {
  for (float g : {-0.99f, -0.5f, 0.0f, 0.3f, 0.8f, 0.95f, 0.99f}) {
    const double total =
        integrateOverSphere([g](double mu) { return henyeyGreenstein(static_cast<float>(mu), g); });
    EXPECT_NEAR(total, 1.0, 2e-3) << "g = " << g;
  }
}

TEST(CloudMath, DualLobeIntegratesToOne) {
  for (float w : {0.0f, 0.3f, 1.0f}) {
    const double total = integrateOverSphere(
        [w](double mu) { return dualLobePhase(static_cast<float>(mu), 0.85f, -0.4f, w); });
    EXPECT_NEAR(total, 1.0, 2e-3) << "blend = " << w;
  }
}

// The silver lining's max() of two phase functions, divided by the integral the CPU computes
// for the uniforms, integrates to 1 (the white furnace's condition) for every octave's
// eccentricity, for sharp and wide silver lobes, weak and strong.
TEST(CloudMath, SilverLiningPhaseIntegratesToOne) {
  for (float intensity : {0.0f, 0.3f, 1.0f, 4.0f}) {
    for (float silverG : {0.99f, 0.89f, 0.5f}) {
      for (float eccentricity : {1.0f, 0.5f, 0.125f}) {
        clouds::detail::PhaseLobes lobes;
        lobes.forwardG = 0.8f * eccentricity;
        lobes.backwardG = -0.3f * eccentricity;
        lobes.backwardWeight = 0.3f;
        lobes.silverG = silverG * eccentricity;
        lobes.silverIntensity = intensity;
        const double normaliser = clouds::detail::silverLiningPhaseIntegral(lobes);
        const double total = integrateOverSphere([&](double mu) {
          return silverLiningPhase(static_cast<float>(mu), lobes.forwardG, lobes.backwardG,
                                   lobes.backwardWeight, lobes.silverG, intensity,
                                   static_cast<float>(1.0 / normaliser));
        });
        EXPECT_NEAR(total, 1.0, 2e-3)
            << "intensity " << intensity << " g " << silverG << " eccentricity " << eccentricity;
        // The max gains energy wherever a sharp silver lobe stands above the mix.
        if (intensity >= 1.0f && eccentricity == 1.0f) {
          EXPECT_GT(normaliser, 1.01);
        }
      }
    }
  }
}

// The octaves' normalisers are kept between calls: changing any phase setting must give that
// setting's normalisers, and going back the first ones again.
TEST(CloudMath, OctaveNormalisersFollowTheSettings) {
  const auto direct = [](const clouds::detail::OctavePhaseSettings& p, int octave) {
    clouds::detail::PhaseLobes lobes = p.lobes;
    const float e = std::pow(p.eccentricityScale, float(octave));
    lobes.forwardG *= e;
    lobes.backwardG *= e;
    lobes.silverG *= e;
    return static_cast<float>(1.0 / clouds::detail::silverLiningPhaseIntegral(lobes));
  };
  clouds::detail::OctavePhaseSettings a;
  a.lobes = {0.8f, -0.3f, 0.3f, 0.94f, 2.0f};
  a.eccentricityScale = 0.5f;
  clouds::detail::OctavePhaseSettings b = a;
  b.lobes.silverIntensity = 1.0f;
  clouds::detail::OctavePhaseSettings c = a;
  c.eccentricityScale = 0.7f;
  for (const auto* p : {&a, &b, &a, &c, &a}) {
    const auto inverses = clouds::detail::octavePhaseNormaliserInverses(*p);
    for (int n = 0; n < 8; ++n) EXPECT_FLOAT_EQ(inverses[std::size_t(n)], direct(*p, n)) << n;
  }
}

TEST(CloudMath, PhaseStaysFiniteAtTheExtremes) {
  for (float g : {-1.0f, -0.99999f, 0.99999f, 1.0f, 2.0f, -2.0f}) {
    for (float c : {-1.0f, -0.5f, 0.0f, 0.999f, 1.0f, 1.5f}) {
      const float p = henyeyGreenstein(c, g);
      EXPECT_TRUE(std::isfinite(p) && p >= 0.0f) << "g " << g << " cos " << c << " -> " << p;
      const float d = dualLobePhase(c, g, -g, 0.5f);
      EXPECT_TRUE(std::isfinite(d) && d >= 0.0f);
    }
  }
}

TEST(CloudMath, RemapHandlesDegenerateRanges) {
  EXPECT_FLOAT_EQ(remap(0.5f, 0.0f, 1.0f, 10.0f, 20.0f), 15.0f);
  EXPECT_FLOAT_EQ(remap(0.5f, 1.0f, 1.0f, 0.0f, 1.0f), 0.0f);  // coverage 0 erodes everything
  EXPECT_FLOAT_EQ(remapClamped(2.0f, 0.0f, 1.0f, 0.0f, 4.0f), 4.0f);
}

TEST(CloudMath, StepWeightHasTheRightLimits) {
  EXPECT_FLOAT_EQ(stepScatteringWeight(0.0f, 10.0f), 10.0f);
  EXPECT_NEAR(stepScatteringWeight(1e-8f, 10.0f), 10.0f, 1e-5f);
  EXPECT_NEAR(stepScatteringWeight(1e6f, 10.0f), 1e-6f, 1e-9f);
  EXPECT_NEAR(stepScatteringWeight(0.1f, 10.0f), (1.0 - std::exp(-1.0)) / 0.1, 1e-4);
}

// Distance to a sphere at altitude `a` from altitude `h`, in double precision.
std::pair<double, double> exactRoots(double h, double mu, double a, double radius) {
  const double r0 = radius + h;
  const double b = r0 * mu;
  const double c = r0 * r0 - (radius + a) * (radius + a);
  const double d = b * b - c;
  if (d < 0) return {-1, -1};
  return {-b - std::sqrt(d), -b + std::sqrt(d)};
}

TEST(CloudMath, RaySphereIsPreciseAtPlanetScale) {
  const double radius = 6360000.0;
  for (double h : {0.0, 300.0, 1499.0, 2500.0, 4200.0, 12000.0}) {
    for (double mu : {-0.9, -0.2, -0.01, 0.0, 0.001, 0.02, 0.3, 1.0}) {
      for (double a : {1500.0, 4000.0}) {
        const auto exact = exactRoots(h, mu, a, radius);
        const vec2 r = raySphere(float(h), float(mu), float(a), float(radius));
        if (exact.second < 0) {
          EXPECT_LT(r.y, 0.0f);
          continue;
        }
        // Tolerance: float rounding of the inputs themselves (mu in particular) moves the
        // exact answer; allow 1 mm plus a relative 2e-6.
        for (const auto& [got, want] :
             {std::pair{double(r.x), exact.first}, std::pair{double(r.y), exact.second}}) {
          EXPECT_NEAR(got, want, 1e-3 + 2e-6 * std::abs(want))
              << "h " << h << " mu " << mu << " a " << a;
        }
      }
    }
  }
}

TEST(CloudMath, AltitudeAlongRayMatchesDoublePrecision) {
  const double radius = 6360000.0;
  for (double h : {0.0, 2000.0, 8000.0}) {
    for (double mu : {-0.5, 0.0, 0.05, 0.7}) {
      for (double t : {0.0, 10.0, 5000.0, 60000.0}) {
        const double r0 = radius + h;
        const double exact = std::sqrt(r0 * r0 + 2 * t * r0 * mu + t * t) - radius;
        EXPECT_NEAR(altitudeAlongRay(float(t), float(mu), float(h), float(radius)), exact,
                    0.02 + 1e-6 * std::abs(exact));
      }
    }
  }
}

// The steps of a ray from `start` to `end` (m) with a budget of `maxSteps` samples, as the march
// takes them (fine steps throughout): where each starts, and whether it was a near step (one
// outside the budget).
struct Step {
  float start;
  bool near;
};
std::vector<Step> marchSteps(float start, float end, int maxSteps, const CloudUniforms& u) {
  std::vector<Step> steps;
  int budgeted = 0;
  for (float t = start; t < end && budgeted < maxSteps;) {
    const bool near = isNearStep(t, u);
    steps.push_back({t, near});
    t += marchStepLength(t, end, maxSteps - budgeted, 1.0f, u);
    if (!near) ++budgeted;
  }
  steps.push_back({end, false});
  return steps;
}

// Medium's steps (60 m, growing 0.004 m per m; 96 samples) near the camera are short: half
// their distance from it, from 3.75 m, until that reaches 60 m. There the cloud around the
// camera covers much of the screen and its rays sample it at the same places. They are taken
// on top of the budget, so a long ray's far steps stay as they were (the march itself:
// CloudModelCpu.NearTheCameraStepsComeOnTopOfTheBudget).
TEST(CloudMath, NearTheCameraStepsAreShortAndOutsideTheBudget) {
  CloudUniforms u{};
  u.viewStepMetres = 60.0f;
  u.viewStepGrowth = 0.004f;
  const int maxSteps = 96;
  const std::vector<Step> inside = marchSteps(0.0f, 6000.0f, maxSteps, u);
  const auto nearSteps = std::count_if(inside.begin(), inside.end(), [](Step s) { return s.near; });
  EXPECT_GE(nearSteps, 8) << "the first 120 m: 2 samples at Medium's own step";
  EXPECT_LE(nearSteps, kMaxNearSteps);
  EXPECT_FLOAT_EQ(inside[1].start - inside[0].start, 3.75f);
  const auto firstFar = std::find_if(inside.begin(), inside.end(), [](Step s) { return !s.near; });
  EXPECT_NEAR(firstFar->start, 120.0f, 15.0f);
  EXPECT_NEAR(inside[inside.size() - 2].start, 6000.0f, 200.0f) << "the ray reaches its end";
  // The far steps take the whole budget: the first is the budget's stretch from there.
  EXPECT_NEAR((firstFar + 1)->start - firstFar->start,
              std::max(60.0f + 0.004f * firstFar->start, (6000.0f - firstFar->start) / maxSteps),
              1e-2f);
  // From below the layer (the segment starts 1 km away) nothing changes: Medium's step there,
  // or the budget's if longer.
  const std::vector<Step> below = marchSteps(1000.0f, 7000.0f, maxSteps, u);
  EXPECT_FALSE(below[0].near);
  EXPECT_NEAR(below[1].start - below[0].start,
              std::max(60.0f + 0.004f * 1000.0f, 6000.0f / float(maxSteps)), 1e-3f);
}

TEST(CloudMath, BayerIsAPermutationAndHaltonIsInRange) {
  std::set<float> values;
  for (uint y = 0; y < 4; ++y) {
    for (uint x = 0; x < 4; ++x) values.insert(bayer4x4(uvec2(x, y)));
  }
  EXPECT_EQ(values.size(), 16u);
  EXPECT_FLOAT_EQ(*values.begin(), 0.5f / 16.0f);
  EXPECT_FLOAT_EQ(bayer4x4(uvec2(1, 0)), 8.5f / 16.0f);  // the classic matrix's second entry
  for (uint i = 1; i < 64; ++i) {
    const float h = halton(i, 2u);
    EXPECT_GT(h, 0.0f);
    EXPECT_LT(h, 1.0f);
  }
  EXPECT_FLOAT_EQ(halton(1, 2u), 0.5f);
  EXPECT_FLOAT_EQ(halton(3, 2u), 0.75f);
}

// The widest gap between sorted values in [0, 1), the wrap-around included.
float widestGap(std::vector<float> values) {
  std::sort(values.begin(), values.end());
  float gap = values.front() + 1.0f - values.back();
  for (std::size_t i = 1; i < values.size(); ++i) gap = std::max(gap, values[i] - values[i - 1]);
  return gap;
}

// The rays' start offsets average out wherever a reconstruction looks: over a pixel's own
// refreshes, over the pixels of a tile, and inside the layer over the samples of one frame.
TEST(CloudMath, RayJitterIsStratifiedOverRefreshesTilesAndFrames) {
  const uint mode = 1u;  // Bayer + Halton
  for (const uint k : {1u, 2u, 4u}) {
    for (const bool spread : {false, true}) {
      // A pixel refreshed every k * k frames: 16 refreshes spread over [0, 1).
      std::vector<float> refreshes;
      for (uint round = 0; round < 16; ++round) {
        refreshes.push_back(
            rayJitter(uvec2(5u, 2u), refreshStartOffset(round, 1u), k, spread, mode));
      }
      EXPECT_LE(widestGap(refreshes), 1.5f / 16.0f) << "tile " << k;
    }
  }
  // The 16 pixels of a 4 x 4 tile, marched in turn over one round of 16 frames (and, at the
  // Reference's tile of 1, the pixels of a frame).
  for (const uint k : {1u, 4u}) {
    std::vector<float> tile;
    for (uint i = 0; i < 16; ++i)
      tile.push_back(
          rayJitter(uvec2(8u + i % 4u, 4u + i / 4u), refreshStartOffset(0u, 1u), k, false, mode));
    EXPECT_LE(widestGap(tile), 1.5f / 16.0f) << "tile " << k;
  }
  // Inside the layer a frame without history marches one pixel in 2 x 2: its rays spread over
  // [0, 1) (no gap over 3/8 among 2 x 2 tiles; 3/4 without the spread), repeating every second
  // tile along each axis (what reconstruct.comp's tent averages exactly). Elsewhere they start
  // together.
  std::vector<float> inside;
  std::vector<float> outside;
  for (uint y = 0; y < 2; ++y) {
    for (uint x = 0; x < 2; ++x) {
      inside.push_back(
          rayJitter(uvec2(x, y) * 2u + 1u, refreshStartOffset(1u, 1u), 2u, true, mode));
      outside.push_back(
          rayJitter(uvec2(x, y) * 4u + 1u, refreshStartOffset(0u, 1u), 4u, false, mode));
    }
  }
  EXPECT_LE(widestGap(inside), 0.375f);
  EXPECT_EQ(rayJitter(uvec2(5u, 3u) * 2u, 0.25f, 2u, true, mode),
            rayJitter(uvec2(7u, 1u) * 2u, 0.25f, 2u, true, mode));
  EXPECT_EQ(*std::min_element(outside.begin(), outside.end()),
            *std::max_element(outside.begin(), outside.end()));
  EXPECT_EQ(rayJitter(uvec2(3u, 1u), 0.3f, 4u, false, 0u), 0.5f) << "no jitter: the step's middle";
}

// With temporal upsampling each output pixel keeps the mean of its own samples, which a trace
// pixel's refreshes visit in turn: the rays' start offsets spread over [0, 1) along each output
// pixel's own visits, and over each round of visits to all of them.
TEST(CloudMath, RayStartOffsetsAreStratifiedOverEachOutputPixelsOwnSamples) {
  for (const uint streams : {1u, 4u, 16u}) {
    for (uint stream = 0; stream < streams; ++stream) {
      std::vector<float> own;
      for (uint visit = 0; visit < 4; ++visit) {
        own.push_back(refreshStartOffset(visit * streams + stream, streams));
      }
      EXPECT_LE(widestGap(own), 0.25f + 1e-6f) << streams << " streams, stream " << stream;
    }
    for (uint visit = 0; visit < 4; ++visit) {
      std::vector<float> round;
      for (uint stream = 0; stream < streams; ++stream) {
        round.push_back(refreshStartOffset(visit * streams + stream, streams));
      }
      EXPECT_LE(widestGap(round), 1.0f / float(streams) + 1e-6f) << streams << " streams";
    }
  }
  // One sequence over the rounds, as before: an output pixel's four own samples started within
  // a quarter of a step.
  std::vector<float> oneSequence;
  for (uint visit = 0; visit < 4; ++visit) {
    oneSequence.push_back(refreshStartOffset(visit * 4u, 1u));
  }
  EXPECT_GT(widestGap(oneSequence), 0.5f);
}

// The light cloud bases get from below (groundLitBaseRadiance()): the ground's radiance over
// the lower hemisphere's steeper 1 - sin(10 deg) (by solid angle), the horizon's beside it.
TEST(CloudMath, BasesSeeTheGroundLitBySunAndSkyAndTheHorizonBeside) {
  const vec3 horizon(9.0f);
  const vec3 black(0.0f);
  EXPECT_NEAR(kGroundShareOfLowerHemisphere, 1.0 - std::sin(10.0 * M_PI / 180.0), 1e-6);
  // A white ground under a uniform sky of radiance L (irradiance pi L) and no sun sends back L.
  const vec3 underSky = groundLitBaseRadiance(horizon, vec3(2.0f), vec3(1.0f), black, 1.0f, 1.0f);
  EXPECT_NEAR(underSky.x, 9.0 + (2.0 - 9.0) * kGroundShareOfLowerHemisphere, 1e-5);
  // The sun overhead on a ground of albedo a: a E / pi, dimmed by the share in the clouds' shade.
  const vec3 sunlit = groundLitBaseRadiance(black, black, vec3(0.25f), vec3(100.0f), 1.0f, 1.0f);
  EXPECT_NEAR(sunlit.y, 0.25 * 100.0 / M_PI * kGroundShareOfLowerHemisphere, 1e-4);
  const vec3 shaded = groundLitBaseRadiance(black, black, vec3(0.25f), vec3(100.0f), 1.0f, 0.4f);
  EXPECT_NEAR(shaded.y, 0.4 * sunlit.y, 1e-4);
  // The sun on the ground goes as the sine of its elevation, and none from below the horizon.
  const vec3 low = groundLitBaseRadiance(black, black, vec3(0.25f), vec3(100.0f), 0.5f, 1.0f);
  EXPECT_NEAR(low.z, 0.5 * sunlit.z, 1e-4);
  const vec3 night = groundLitBaseRadiance(horizon, black, vec3(0.25f), vec3(100.0f), -0.3f, 1.0f);
  EXPECT_NEAR(night.x, 9.0 * (1.0 - kGroundShareOfLowerHemisphere), 1e-5);
  // A black ground leaves the horizon's share only.
  const vec3 blackGround =
      groundLitBaseRadiance(horizon, vec3(2.0f), black, vec3(100.0f), 1.0f, 1.0f);
  EXPECT_NEAR(blackGround.x, 9.0 * (1.0 - kGroundShareOfLowerHemisphere), 1e-5);
}

}  // namespace

namespace {

TEST(CloudMath, TheNoiseMipLevelsLieSideBySideInTheirImage) {
  for (const int n : {kShapeNoiseSize, kDetailNoiseSize}) {
    const int levels = n == kShapeNoiseSize ? kShapeNoiseLevels : kDetailNoiseLevels;
    ASSERT_EQ(n >> (levels - 1), 1) << "the chain ends at one texel, the mean";
    EXPECT_EQ(noiseLevelOrigin(0, n), ivec3(0));
    int nextX = 0;  // levels 1.. follow each other along x on the slices above level 0
    for (int level = 1; level < levels; ++level) {
      const ivec3 o = noiseLevelOrigin(level, n);
      const int size = n >> level;
      EXPECT_EQ(o, ivec3(nextX, 0, n)) << "n " << n << " level " << level;
      EXPECT_LE(o.x + size, n);
      EXPECT_LE(o.z + size, n + n / 2) << "inside the n x n x 3n/2 image";
      nextX = o.x + size;
    }
  }
}

TEST(CloudMath, TheNoiseLevelIsLog2OfTheFootprintInTexelsRoundedByTheDither) {
  const float texel = 40.0f;
  EXPECT_EQ(noiseLevel(0.0f, texel, 0.99f, 6), 0) << "no footprint: the finest level";
  EXPECT_EQ(noiseLevel(39.0f, texel, 0.99f, 6), 0) << "below a texel: the finest level";
  EXPECT_EQ(noiseLevel(80.0f, texel, 0.0f, 6), 1);
  EXPECT_EQ(noiseLevel(80.0f, texel, 0.99f, 6), 1) << "exactly level 1";
  EXPECT_EQ(noiseLevel(1e9f, texel, 0.5f, 6), 5) << "clamped to the last level";
  // Between levels 1 and 2 (log2 = 1.5), the dither picks the lower one half the time.
  int lower = 0;
  for (int i = 0; i < 100; ++i)
    lower += noiseLevel(113.137f, texel, (float(i) + 0.5f) / 100.0f, 6) == 1;
  EXPECT_EQ(lower, 50);
}

}  // namespace
