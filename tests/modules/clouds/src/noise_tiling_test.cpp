// The module's generated noise textures tile: the difference between texels across each wrap
// seam is statistically like the difference between interior neighbours. A negative control
// shows the statistic does flag a texture that does not tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cloud_harness.h"
#include "cloud_noise.h"
#include "gpu_test.h"
#include "seam_statistics.h"

namespace {

using test::expectTiles;
using test::seamStatistics;
using test::tiles;

class NoiseTiling : public test::GpuTest {};

TEST_F(NoiseTiling, ShapeDetailAndCurlTexturesTileOnEveryAxisAndChannel) {
  clouds::tools::CloudHarness harness(device(), {16, 16});
  harness.render(clouds::tools::CloudView{}, clouds::Settings{},
                 {16, 16});  // generates the textures
  const auto shape = harness.readShapeNoise();
  const auto detail = harness.readDetailNoise();
  const auto curl = harness.readCurlNoise();
  for (int channel = 0; channel < 4; ++channel) {
    for (int axis = 0; axis < 3; ++axis) {
      const std::string where =
          " channel " + std::to_string(channel) + " axis " + std::to_string(axis);
      expectTiles(
          seamStatistics(
              128, 128, axis,
              [&](int x, int y, int z) {
                return shape[4 * ((std::size_t(z) * 128 + std::size_t(y)) * 128 + std::size_t(x)) +
                             std::size_t(channel)] /
                       255.0;
              }),
          "shape noise" + where);
      if (channel < 3) {
        expectTiles(
            seamStatistics(
                32, 32, axis,
                [&](int x, int y, int z) {
                  return detail[4 * ((std::size_t(z) * 32 + std::size_t(y)) * 32 + std::size_t(x)) +
                                std::size_t(channel)] /
                         255.0;
                }),
            "detail noise" + where);
      }
      if (channel < 2 && axis < 2) {
        expectTiles(
            seamStatistics(
                128, 1, axis,
                [&](int x, int y, int) {
                  return curl[4 * (std::size_t(y) * 128 + std::size_t(x)) + std::size_t(channel)] /
                         255.0;
                }),
            "curl noise" + where);
      }
    }
  }
}

TEST(NoiseTilingControl, TheStatisticCatchesANonTilingTexture) {
  // Perlin noise whose lattice period (64 cells) is far longer than the 4 cells the texture
  // spans: the right edge continues into new cells instead of wrapping to the left edge.
  using namespace clouds::shader;
  const int size = 64;
  const auto nonTiling = [](int x, int y, int) {
    const vec3 p = (vec3(float(x), float(y), 0.0f) + 0.5f) / float(size) * 4.0f;
    return double(perlinNoise(p, 64, 7u));
  };
  std::string why;
  EXPECT_FALSE(tiles(seamStatistics(size, 1, 0, nonTiling), &why)) << "control tiles: " << why;
  // The same noise with the matching period passes.
  const auto tiling = [](int x, int y, int) {
    const vec3 p = (vec3(float(x), float(y), 0.0f) + 0.5f) / float(size) * 4.0f;
    return double(perlinNoise(p, 4, 7u));
  };
  expectTiles(seamStatistics(size, 1, 0, tiling), "matching-period control");
}

}  // namespace
