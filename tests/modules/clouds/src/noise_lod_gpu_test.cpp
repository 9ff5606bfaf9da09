// The noise's level of detail (Settings::noiseLevelOfDetail): each level of the mip chains is
// the box mean of the level below, packed for 2-fetch filtering; far clouds, whose noise is finer
// than their pixels, read coarser levels and so flicker less as their rays move by a fraction of a
// pixel, without thinning out; near clouds read level 0 and are the same image as without it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cloud_gpu_fixture.h"
#include "cloud_sampling.h"

namespace {
using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::kExtent;
using NoiseLod = test::CloudGpuTest;

// One channel of texel (x, y, z) of `level` in a read-back n x n x 3n/2 chain, in [0, 255].
int chainTexel(const std::vector<std::uint8_t>& chain, int n, int level, glm::ivec3 t,
               int channel) {
  const glm::ivec3 p = clouds::shader::noiseLevelOrigin(level, n) + t;
  return chain[4 * ((std::size_t(p.z) * std::size_t(n) + std::size_t(p.y)) * std::size_t(n) +
                    std::size_t(p.x)) +
               std::size_t(channel)];
}

// A level's value at texel (x, y, z): the first channel of the packed texel (cloud_sampling.h).
int chainValue(const std::vector<std::uint8_t>& chain, int n, int level, glm::ivec3 t) {
  return chainTexel(chain, n, level, t, 0);
}

// Largest difference (in 1/255) between each value of levels 1.. and the mean of the 8 values
// it covers one level down; between the last level (1 texel) and the mean of level 0; and
// between each texel's other channels and the values they pack (its neighbours at +x, +y and
// +x+y, wrapping round the level).
struct ChainError {
  double boxMean = 0.0;
  double lastLevelFromTheMean = 0.0;
  int packing = 0;
};

ChainError chainError(const std::vector<std::uint8_t>& chain, int n, int levels) {
  ChainError e;
  for (int level = 0; level < levels; ++level) {
    const int size = n >> level;
    for (int z = 0; z < size; ++z) {
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          for (int c = 1; c < 4; ++c) {
            const glm::ivec3 neighbour((x + (c & 1)) % size, (y + (c >> 1)) % size, z);
            e.packing = std::max(e.packing, std::abs(chainTexel(chain, n, level, {x, y, z}, c) -
                                                     chainValue(chain, n, level, neighbour)));
          }
          if (level == 0) continue;
          double sum = 0.0;
          for (int k = 0; k < 8; ++k) {
            const glm::ivec3 q(2 * x + (k & 1), 2 * y + ((k >> 1) & 1), 2 * z + (k >> 2));
            sum += chainValue(chain, n, level - 1, q);
          }
          const double got = chainValue(chain, n, level, {x, y, z});
          e.boxMean = std::max(e.boxMean, std::abs(got - sum / 8.0));
        }
      }
    }
  }
  double sum = 0.0;
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) sum += chainValue(chain, n, 0, {x, y, z});
    }
  }
  const double last = chainValue(chain, n, levels - 1, {0, 0, 0});
  e.lastLevelFromTheMean = std::abs(last - sum / (n * n * n));
  return e;
}

TEST_F(NoiseLod, EachLevelOfTheMipChainsIsTheBoxMeanOfTheLevelBelowPacked) {
  auto r = renderer();
  r->render(test::cumulusView(), clouds::Settings{}, {16, 16});  // generates the noise
  using namespace clouds::shader;
  const ChainError shape = chainError(r->readShapeNoise(), kShapeNoiseSize, kShapeNoiseLevels);
  const ChainError detail = chainError(r->readDetailNoise(), kDetailNoiseSize, kDetailNoiseLevels);
  // Each level is rounded to 8 bits once (half a step); the last level has been rounded once
  // per level on the way down. The packed channels are the neighbours' values exactly.
  EXPECT_LE(shape.boxMean, 0.5 + 1e-9);
  EXPECT_LE(detail.boxMean, 0.5 + 1e-9);
  EXPECT_LE(shape.lastLevelFromTheMean, 0.5 * (kShapeNoiseLevels - 1));
  EXPECT_LE(detail.lastLevelFromTheMean, 0.5 * (kDetailNoiseLevels - 1));
  EXPECT_EQ(shape.packing, 0);
  EXPECT_EQ(detail.packing, 0);
}

// Above the layer, looking out towards the horizon: most clouds are 10 to 60 km away, where a
// pixel of this 160 x 90 view is 150 to 900 m wide: many texels of both noises (39 and 49 m).
CloudView farView() {
  CloudView view;
  view.position = {0.0, 6500.0, 0.0};
  view.pitchDegrees = -8.0;
  view.yawDegrees = 270.0;
  view.timeSeconds = 5.0;
  return view;
}

// Every pixel marched at its centre, at the same place along its ray every frame: what the wind
// changes between two frames is all that changes.
clouds::Settings pointSampled(bool levelOfDetail, float texelsPerPixel = 4.0f) {
  clouds::Settings s = clouds::tools::singleFrame(clouds::settingsFor(clouds::Quality::High));
  s.jitter = clouds::Jitter::None;
  s.noiseLevelOfDetail = levelOfDetail;
  s.noiseTexelsPerPixel = texelsPerPixel;
  return s;
}

struct FarFlicker {
  double meanChange = 0.0;   // mean |change| of the far cloud pixels' radiance between frames
  double meanOpacity = 0.0;  // their mean opacity
  int pixels = 0;
};

// Two frames from cameras 20 m apart: each pixel's ray moves 20 m sideways through the far
// clouds, a tenth of that pixel's width or less. A far cloud seen through its pixel hardly
// changes; noise sampled finer than the pixel does.
FarFlicker farFlicker(clouds::tools::CloudHarness& r, const clouds::Settings& s) {
  CloudView view = farView();
  const CloudFrame before = r.render(view, s, kExtent);
  view.position.x += 20.0;
  r.cut();
  const CloudFrame after = r.render(view, s, kExtent);
  FarFlicker f;
  double change = 0.0;
  double opacity = 0.0;
  for (std::size_t i = 0; i < before.radiance.size(); ++i) {
    const bool far = before.depth[i].x > 15000.0f && before.radiance[i].a < 0.98f;
    if (!far) continue;
    const glm::vec4 d = glm::abs(after.radiance[i] - before.radiance[i]);
    change += (d.r + d.g + d.b) / 3.0;
    opacity += 1.0 - before.radiance[i].a;
    ++f.pixels;
  }
  f.meanChange = change / std::max(f.pixels, 1);
  f.meanOpacity = opacity / std::max(f.pixels, 1);
  return f;
}

TEST_F(NoiseLod, FarCloudsFlickerLessAsTheirRaysMoveAFractionOfAPixel) {
  const FarFlicker off = farFlicker(*renderer(), pointSampled(false));
  const FarFlicker byDefault = farFlicker(*renderer(), pointSampled(true));
  const FarFlicker fromOneTexel = farFlicker(*renderer(), pointSampled(true, 1.0f));
  std::printf(
      "far clouds (%d pixels): mean change %.4f without the noise's LOD, %.4f with it "
      "from 4 texels a pixel, %.4f from 1; mean opacity %.3f, %.3f, %.3f\n",
      off.pixels, off.meanChange, byDefault.meanChange, fromOneTexel.meanChange, off.meanOpacity,
      byDefault.meanOpacity, fromOneTexel.meanOpacity);
  ASSERT_GT(off.pixels, int(kExtent.width * kExtent.height / 20)) << "the view shows far clouds";
  // Measured 0.86 and 0.50 of the change without it (the rest is the weather map's coverage
  // and the clouds' edges, which move with the rays as they would in a supersampled image).
  EXPECT_LT(byDefault.meanChange, 0.92 * off.meanChange);
  EXPECT_LT(fromOneTexel.meanChange, 0.6 * off.meanChange);
  // Without thinning out: the averaged noise is remapped against the coverage as the finest is.
  EXPECT_NEAR(byDefault.meanOpacity, off.meanOpacity, 0.05 * off.meanOpacity);
  EXPECT_NEAR(fromOneTexel.meanOpacity, off.meanOpacity, 0.05 * off.meanOpacity);
}

TEST_F(NoiseLod, CloudsNearerThanTheirFirstLevelAreTheSameImageWithoutIt) {
  // At 160 x 90 a pixel spans 4 detail texels (39 m), where the default starts coarser levels,
  // at 10 km (the shape noise's, 49 m, at 12.6 km). Marched to 8 km, with light samples up to
  // 1.8 km beyond, no sample reaches them, whatever its dither.
  CloudView view = test::cumulusView();
  view.position.y = 1000.0;  // under the cloud base (1500 m), looking up steeply
  view.pitchDegrees = 40.0;
  clouds::Settings s = pointSampled(true);
  s.coverage = 0.8f;
  s.maxDistanceMetres = 8000.0f;
  auto r = renderer();
  const CloudFrame on = r->render(view, s, kExtent);
  s.noiseLevelOfDetail = false;
  r->cut();
  const CloudFrame off = r->render(view, s, kExtent);
  ASSERT_GT(test::meanOpacity(off), 0.05) << "the view must show clouds";
  EXPECT_EQ(test::maxAbsDifference(on, off), 0.0f);
}

}  // namespace
