// The module's generated noise textures tile: the difference between texels across each wrap
// seam is statistically like the difference between interior neighbours. A negative control
// shows the statistic does flag a texture that does not tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cloud_harness.h"
#include "cloud_noise.h"
#include "gpu_test.h"

namespace {

struct SeamStatistics {
  std::vector<double> lines;  // mean |t(i+1) - t(i)| across each interior line i -> i+1
  double seam = 0.0;          // the same across the wrap, n-1 -> 0
};

// `texel(x, y, z)` returns one channel in [0, 1]; the statistic runs along `axis`.
template <typename Texel>
SeamStatistics seamStatistics(int size, int depth, int axis, Texel texel) {
  const int extent[3] = {size, size, depth};
  const int n = extent[axis];
  std::vector<double> sums(static_cast<std::size_t>(n), 0.0);
  long perLine = 0;
  for (int z = 0; z < depth; ++z) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        int q[3] = {x, y, z};
        const int along = q[axis];
        q[axis] = (q[axis] + 1) % n;
        sums[static_cast<std::size_t>(along)] += std::abs(texel(q[0], q[1], q[2]) - texel(x, y, z));
        if (along == 0) ++perLine;
      }
    }
  }
  SeamStatistics s;
  for (int i = 0; i < n; ++i) {
    const double mean = sums[static_cast<std::size_t>(i)] / double(perLine);
    if (i == n - 1) {
      s.seam = mean;
    } else {
      s.lines.push_back(mean);
    }
  }
  return s;
}

// A seam "tiles" when crossing it changes texels like crossing an interior line does: its mean
// difference lies within the spread of the interior lines' (which vary with the lattice phase
// of the noise), give or take 25%. A texture that does not tile jumps by about its own standard
// deviation across the seam, many times an interior difference.
bool tiles(const SeamStatistics& s, std::string* why) {
  const auto [lo, hi] = std::minmax_element(s.lines.begin(), s.lines.end());
  const bool ok = *hi > 0.0 && s.seam >= 0.75 * *lo && s.seam <= 1.25 * *hi;
  if (why != nullptr) {
    *why = "seam " + std::to_string(s.seam) + ", interior lines in [" + std::to_string(*lo) + ", " +
           std::to_string(*hi) + "]";
  }
  return ok;
}

void expectTiles(const SeamStatistics& s, const std::string& what) {
  std::string why;
  EXPECT_TRUE(tiles(s, &why)) << what << ": " << why;
}

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
