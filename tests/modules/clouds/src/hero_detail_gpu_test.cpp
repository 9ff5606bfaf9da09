// Hero clouds' detail (Settings::heroDetail, Nubis³'s up-rez; cloud_hero.h, cloud_noise.h): the
// detail noise the GPU makes tiles on every axis and channel and its chain is the box mean of
// each level below; each term of the density sampler does what it is there for; up close the
// detail shows as half-metre structure, far away the noise's levels keep it from aliasing; and
// a context that never asks for detail never makes the noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cloud_gpu_fixture.h"
#include "cloud_hero.h"
#include "cloud_noise.h"
#include "clouds/nvdf.h"
#include "clouds/procedural_textures.h"
#include "hero_cloud_scenes.h"
#include "seam_statistics.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::Assets;
using test::heroOnly;
using test::meanOpacity;

using HeroNoise = test::SharedHarnessTest<32, 18>;
using HeroDetail = test::SharedHarnessTest<160, 90>;

constexpr int kN = clouds::shader::kHeroNoiseSize;

// Channel `channel` of texel `t` of `level` of the read-back chain, in [0, 1].
double chainTexel(const std::vector<std::uint8_t>& chain, int level, glm::ivec3 t, int channel) {
  const glm::ivec3 p = clouds::shader::heroNoiseTexelAddress(level, t);
  return chain[4 * ((std::size_t(p.z) * kN + std::size_t(p.y)) * kN + std::size_t(p.x)) +
               std::size_t(channel)] /
         255.0;
}

// The chain a context with up-rezzed hero clouds makes on its first frame.
std::vector<std::uint8_t> generatedNoise(clouds::tools::CloudHarness& harness) {
  const Assets assets(harness.context());
  CloudView view;
  view.heroClouds = {test::aheadOfTheCamera()};
  harness.render(view, clouds::tools::singleFrame(heroOnly()), {32, 18});
  return harness.readHeroNoise();
}

TEST_F(HeroNoise, TilesOnEveryAxisAndChannel) {
  const std::vector<std::uint8_t> chain = generatedNoise(harness());
  ASSERT_EQ(chain.size(), std::size_t(4) * kN * kN * clouds::shader::kHeroNoiseDepth);
  for (int channel = 0; channel < 4; ++channel) {
    double sum = 0.0;
    double squares = 0.0;
    for (int z = 0; z < kN; ++z) {
      for (int y = 0; y < kN; ++y) {
        for (int x = 0; x < kN; ++x) {
          const double v = chainTexel(chain, 0, {x, y, z}, channel);
          sum += v;
          squares += v * v;
        }
      }
    }
    const double mean = sum / (double(kN) * kN * kN);
    const double deviation = std::sqrt(squares / (double(kN) * kN * kN) - mean * mean);
    std::printf("channel %d: mean %.3f, standard deviation %.3f\n", channel, mean, deviation);
    EXPECT_GT(deviation, 0.08) << "channel " << channel << " is nearly flat";
    for (int axis = 0; axis < 3; ++axis) {
      test::expectTiles(
          test::seamStatistics(kN, kN, axis,
                               [&](int x, int y, int z) {
                                 return chainTexel(chain, 0, {x, y, z}, channel);
                               }),
          "hero noise channel " + std::to_string(channel) + " axis " + std::to_string(axis));
    }
  }
}

TEST_F(HeroNoise, EachLevelIsTheBoxMeanOfTheLevelBelow) {
  const std::vector<std::uint8_t> chain = generatedNoise(harness());
  double worst = 0.0;
  for (int level = 1; level < clouds::shader::kHeroNoiseLevels; ++level) {
    const int size = kN >> level;
    for (int z = 0; z < size; ++z) {
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          for (int c = 0; c < 4; ++c) {
            double sum = 0.0;
            for (int k = 0; k < 8; ++k) {
              const glm::ivec3 q(2 * x + (k & 1), 2 * y + ((k >> 1) & 1), 2 * z + (k >> 2));
              sum += chainTexel(chain, level - 1, q, c);
            }
            worst = std::max(worst, std::abs(chainTexel(chain, level, {x, y, z}, c) - sum / 8.0));
          }
        }
      }
    }
  }
  EXPECT_LE(worst, 0.5 / 255.0 + 1e-9) << "a level is not the mean of the one below";
}

// The standalone generator's hero noise (clouds/procedural_textures.h) rounds to the GPU's
// bytes: within one step, off by one in at most one texel in a thousand (float evaluation order).
TEST_F(HeroNoise, IsTheStandaloneGeneratorsNoise) {
  const std::vector<std::uint8_t> chain = generatedNoise(harness());
  int worst = 0;
  std::size_t differing = 0;
  for (int z = 0; z < kN; ++z) {
    const std::vector<glm::vec4> slice =
        clouds::heroNoiseSlice(clouds::tools::HarnessOptions{}.noiseSeed, z);
    for (int y = 0; y < kN; ++y) {
      for (int x = 0; x < kN; ++x) {
        const glm::ivec3 p = clouds::shader::heroNoiseTexelAddress(0, {x, y, z});
        const std::size_t at = (std::size_t(p.z) * kN + std::size_t(p.y)) * kN + std::size_t(p.x);
        for (int c = 0; c < 4; ++c) {
          const int steps =
              std::abs(int(chain[4 * at + std::size_t(c)]) -
                       int(clouds::storedUnorm8(slice[std::size_t(y) * kN + std::size_t(x)][c])));
          worst = std::max(worst, steps);
          differing += steps != 0 ? 1u : 0u;
        }
      }
    }
  }
  std::printf("%zu of %d values differ, by at most %d step(s)\n", differing, 4 * kN * kN * kN,
              worst);
  EXPECT_LE(worst, 1);
  EXPECT_LE(double(differing), 1e-3 * 4.0 * kN * kN * kN);
}

// The seam statistic flags an alligator noise whose lattice does not wrap with the texture.
TEST(HeroNoiseControl, TheStatisticCatchesANonTilingAlligator) {
  using namespace clouds::shader;
  const int size = 64;
  const auto at = [](int period) {
    return [period](int x, int y, int) {
      const vec3 p = (vec3(float(x), float(y), 0.0f) + 0.5f) / float(size) * 4.0f;
      return double(alligatorNoise(p, period, 9u));
    };
  };
  std::string why;
  EXPECT_FALSE(test::tiles(test::seamStatistics(size, 1, 0, at(64)), &why))
      << "control tiles: " << why;
  test::expectTiles(test::seamStatistics(size, 1, 0, at(4)), "matching-period control");
}

// The density sampler's terms, on the CPU.
TEST(HeroDetailSampler, ErodesOnlyWhereTheNoiseRisesAboveTheProfile) {
  using clouds::shader::heroUprezzedDensity;
  const glm::vec4 low(0.1f), high(0.9f);
  // Erosion: the same voxel keeps cloud under low noise and loses it under high noise.
  EXPECT_GT(heroUprezzedDensity(0.5f, 0.0f, 1.0f, low), 0.5f);
  EXPECT_EQ(heroUprezzedDensity(0.5f, 0.0f, 1.0f, high), 0.0f);
  // Clear air stays clear, whatever the noise.
  EXPECT_EQ(heroUprezzedDensity(0.0f, 0.0f, 1.0f, glm::vec4(0.0f)), 0.0f);
}

TEST(HeroDetailSampler, TheDetailTypeChoosesWispsOrBillows) {
  using clouds::shader::heroUprezzedDensity;
  // Wisps read R and G, billows B and A: raising only the wisps' channels erodes a wispy voxel
  // and leaves a billowy one.
  const glm::vec4 calm(0.2f, 0.2f, 0.2f, 0.2f);
  const glm::vec4 wispsHigh(0.9f, 0.9f, 0.2f, 0.2f);
  EXPECT_LT(heroUprezzedDensity(0.6f, 0.0f, 1.0f, wispsHigh),
            0.5f * heroUprezzedDensity(0.6f, 0.0f, 1.0f, calm));
  EXPECT_EQ(heroUprezzedDensity(0.6f, 1.0f, 1.0f, wispsHigh),
            heroUprezzedDensity(0.6f, 1.0f, 1.0f, calm));
  // The billows erode at 0.3 of their strength: full billow noise leaves most of a core.
  EXPECT_GT(heroUprezzedDensity(0.9f, 1.0f, 1.0f, glm::vec4(1.0f)), 0.8f);
}

TEST(HeroDetailSampler, TheProfileMovesTheDetailFromLowToHighFrequency) {
  using clouds::shader::heroUprezzedDensity;
  // At an edge (profile low) the low-frequency channel erodes, in a core the high one.
  const glm::vec4 lowFrequency(0.6f, 0.0f, 0.0f, 0.0f);
  const glm::vec4 highFrequency(0.0f, 0.6f, 0.0f, 0.0f);
  EXPECT_LT(heroUprezzedDensity(0.3f, 0.0f, 1.0f, lowFrequency),
            heroUprezzedDensity(0.3f, 0.0f, 1.0f, highFrequency));
  EXPECT_GT(heroUprezzedDensity(0.95f, 0.0f, 1.0f, lowFrequency),
            heroUprezzedDensity(0.95f, 0.0f, 1.0f, highFrequency));
}

TEST(HeroDetailSampler, TheDensityScaleScalesAndSharpens) {
  using clouds::shader::heroUprezzedDensity;
  const glm::vec4 noise(0.2f);
  const float thin = heroUprezzedDensity(0.6f, 0.5f, 0.25f, noise);
  const float dense = heroUprezzedDensity(0.6f, 0.5f, 1.0f, noise);
  EXPECT_LT(thin, dense);
  // The power: thin cloud is lifted towards 1 more than dense cloud (exponent 0.3 against 0.6),
  // so a quarter of the scale leaves more than a quarter of the density.
  EXPECT_GT(thin, 0.5f * dense);
  EXPECT_LT(dense, 1.0f);
}

// Up close the detail shows: the picture of a cloud 300 m off, up-rezzed, has more than twice the
// pixel-to-pixel structure of its smooth voxels (measured 2.5 times; what both share is the
// march's own sampling noise and the silhouette).
double structure(const CloudFrame& frame) {
  double sum = 0.0;
  int count = 0;
  const int w = static_cast<int>(frame.extent.width);
  const int h = static_cast<int>(frame.extent.height);
  for (int y = 1; y < h - 1; ++y) {
    for (int x = 1; x < w - 1; ++x) {
      const auto t = [&](int dx, int dy) {
        return double(frame.radiance[std::size_t((y + dy) * w + x + dx)].a);
      };
      sum += std::abs(4.0 * t(0, 0) - t(1, 0) - t(-1, 0) - t(0, 1) - t(0, -1));
      ++count;
    }
  }
  return sum / count;
}

CloudView closeUp() {
  CloudView view;
  view.position = {-1200.0, 2100.0, -2500.0};  // about 300 m from the cumulus's side
  view.yawDegrees = -90.0;
  view.pitchDegrees = 0.0;
  view.sunElevationDegrees = 40.0;
  view.heroClouds = {test::aheadOfTheCamera()};
  return view;
}

TEST_F(HeroDetail, UpCloseShowsHalfMetreStructure) {
  const Assets assets(harness().context());
  clouds::Settings detailed = clouds::referenceSettings(heroOnly());
  clouds::Settings smooth = detailed;
  smooth.heroDetail = clouds::HeroDetail::Off;
  const CloudFrame withDetail = harness().renderAveraged(closeUp(), detailed, {160, 90}, 4);
  harness().cut();
  const CloudFrame without = harness().renderAveraged(closeUp(), smooth, {160, 90}, 4);
  const double a = structure(withDetail);
  const double b = structure(without);
  std::printf("structure: %.4f up-rezzed, %.4f smooth; opacity %.3f, %.3f\n", a, b,
              meanOpacity(withDetail), meanOpacity(without));
  EXPECT_GT(meanOpacity(without), 0.3) << "the view shows too little cloud";
  EXPECT_GT(a, 2.0 * b);
}

// Far away the noise's levels keep the detail from aliasing: 2.5 km off, a pixel spans 60 of
// its half-metre texels, and rays moved by a tenth of a pixel between two frames read other
// texels at level 0; at the level the pixel covers they read nearly the same mean.
TEST_F(HeroDetail, FarAwayItsLevelsKeepItFromFlickering) {
  const Assets assets(harness().context());
  CloudView view;
  view.position = {0.0, 2100.0, 0.0};
  view.sunElevationDegrees = 40.0;
  view.heroClouds = {test::aheadOfTheCamera()};
  const auto flicker = [&](bool levels) {
    clouds::Settings s = clouds::tools::singleFrame(clouds::settingsFor(clouds::Quality::High));
    s.coverage = 0.0f;
    s.jitter = clouds::Jitter::None;
    s.noiseLevelOfDetail = levels;
    CloudView moved = view;
    harness().cut();
    const CloudFrame before = harness().render(moved, s, {160, 90});
    moved.position.x += 3.0;
    harness().cut();
    const CloudFrame after = harness().render(moved, s, {160, 90});
    double change = 0.0;
    int pixels = 0;
    for (std::size_t i = 0; i < before.radiance.size(); ++i) {
      if (before.radiance[i].a > 0.98f) continue;
      const glm::vec4 d = glm::abs(after.radiance[i] - before.radiance[i]);
      change += (d.r + d.g + d.b) / 3.0;
      ++pixels;
    }
    EXPECT_GT(pixels, 300) << "the view shows too little cloud";
    return change / std::max(pixels, 1);
  };
  const double without = flicker(false);
  const double with = flicker(true);
  std::printf("mean change of the cloud's pixels: %.4f with the levels, %.4f without\n", with,
              without);
  EXPECT_LT(with, 0.6 * without);
}

// The lighting reads the profile the detail left (so the billows are lit as shapes): along a
// line through the cumulus's edge, at the finest level, the field's profile is the eroded one,
// below its voxels' where they are not core (profile 1 survives any erosion), and the same as
// theirs with the detail off.
TEST_F(HeroNoise, TheLightingReadsTheErodedProfile) {
  const std::vector<std::uint8_t> chain = generatedNoise(harness());
  clouds::tools::CpuTextures textures;
  const clouds::HeroCloud clouds[] = {test::aheadOfTheCamera()};
  textures.heroes = test::cumulusOnTheCpu(
      clouds::detail::heroCloudUniforms(test::cumulusAtlas().assets, clouds, glm::dvec3(0.0)));
  textures.heroes.noise = chain;
  clouds::shader::CloudUniforms u{};
  u.extinctionPerMetre = 0.05f;
  int eroded = 0;
  int cloudy = 0;
  for (const std::uint32_t detail :
       {clouds::shader::kHeroDetailUprezzed, clouds::shader::kHeroDetailOff}) {
    textures.heroes.uniforms.count.w = detail;
    const clouds::tools::CpuHeroScope scope(textures);
    for (float x = -1000.0f; x < 0.0f; x += 0.25f) {
      const glm::vec3 p(x, 2100.0f, -2500.0f);
      clouds::shader::HeroSample s = clouds::shader::heroFieldExcept(p, u, 0u);
      clouds::shader::heroAddDetail(s, 0.0f, 0.0f);
      if (s.sigmaT <= 0.0f) continue;
      if (detail == clouds::shader::kHeroDetailOff) {
        EXPECT_FLOAT_EQ(s.profile, s.reach) << "at x = " << x;
        continue;
      }
      EXPECT_LE(s.profile, s.reach + 1e-6f) << "at x = " << x;  // (p - c) / (1 - c) <= p
      if (s.reach > 0.95f) continue;
      ++cloudy;
      if (s.profile < s.reach - 0.01f) ++eroded;
    }
  }
  std::printf("%d of %d cloudy points outside the core lit by an eroded profile\n", eroded, cloudy);
  EXPECT_GT(cloudy, 100);
  EXPECT_GT(eroded, cloudy * 9 / 10);
}

// Seed 002's memory budget for a cloudscape of hero clouds at Medium, 25.2 MB: the three
// shipped clouds with everything they need on the GPU (atlas, light volume, detail noise and
// the per-frame blocks), as Context::memoryUsage() counts it once the atlas's upload buffer
// has gone (frames in flight after the first).
TEST_F(HeroDetail, TheShippedCloudsFitSeed002sBudget) {
  std::vector<clouds::NvdfVolume> volumes;
  for (const char* name : {"towering_cumulus", "cumulonimbus", "arch"}) {
    clouds::Error error;
    std::optional<clouds::NvdfVolume> v =
        clouds::readNvdf(std::string(CLOUDS_HERO_CLOUD_DIR) + "/" + name + ".nvdf", &error);
    ASSERT_TRUE(v) << error.message;
    volumes.push_back(std::move(*v));
  }
  std::vector<const clouds::NvdfVolume*> list;
  for (const clouds::NvdfVolume& v : volumes) list.push_back(&v);
  clouds::Error error;
  ASSERT_TRUE(harness().context().setHeroCloudAssets(list, &error)) << error.message;
  CloudView view;
  view.heroClouds = {test::aheadOfTheCamera()};
  const clouds::Settings medium = clouds::settingsFor(clouds::Quality::Medium);
  for (int frame = 0; frame < 4; ++frame) harness().render(view, medium, {160, 90});
  const double megabytes = double(harness().memoryUsage().heroCloudBytes) / 1e6;
  std::printf("the shipped hero clouds hold %.1f MB of GPU memory\n", megabytes);
  harness().context().setHeroCloudAssets({}, nullptr);
  EXPECT_LE(megabytes, 25.2);
}

}  // namespace
