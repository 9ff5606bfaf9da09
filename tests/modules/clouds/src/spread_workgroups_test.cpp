// The order the clouds' marches take their workgroups in (vkfx/spread_workgroups.h), compiled
// as C++: a bijection, and however a CPU device cuts the dispatch into contiguous runs, one a
// thread, each run holds its fair share of every band of the image (the rows in their plain
// order give the first thread the sky and the last the ground).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "vkfx/spread_workgroups.h"

namespace {

using vkfx::shader::spreadIndex;

TEST(SpreadWorkgroups, EveryWorkgroupIsVisitedOnce) {
  for (std::uint32_t count = 1; count <= 5000; ++count) {
    std::vector<bool> seen(count, false);
    for (std::uint32_t position = 0; position < count; ++position) {
      const std::uint32_t index = spreadIndex(position, count);
      ASSERT_LT(index, count) << "position " << position << " of " << count;
      ASSERT_FALSE(seen[index]) << "index " << index << " twice, of " << count;
      seen[index] = true;
    }
  }
}

// The largest difference, over `threads` contiguous runs of the dispatch's positions (lavapipe's
// split: equal runs, the first ones a workgroup longer for the remainder) and over the image's
// four bands of rows, between a run's share of a band and the band's share of the rows.
double worstBandShare(std::uint32_t columns, std::uint32_t rows, std::uint32_t threads,
                      const std::function<std::uint32_t(std::uint32_t, std::uint32_t)>& order) {
  const std::uint32_t count = columns * rows;
  const auto band = [&](std::uint32_t row) { return std::min(3u, row * 4u / rows); };
  std::array<double, 4> expected{};
  for (std::uint32_t row = 0; row < rows; ++row) expected[band(row)] += 1.0 / rows;
  double worst = 0.0;
  std::uint32_t start = 0;
  for (std::uint32_t t = 0; t < threads; ++t) {
    const std::uint32_t length = count / threads + (t < count % threads ? 1u : 0u);
    std::array<double, 4> share{};
    for (std::uint32_t p = start; p < start + length; ++p) {
      share[band(order(p, count) / columns)] += 1.0 / length;
    }
    for (std::size_t b = 0; b < 4; ++b) worst = std::max(worst, std::abs(share[b] - expected[b]));
    start += length;
  }
  return worst;
}

TEST(SpreadWorkgroups, EachThreadsRunCoversTheWholeImage) {
  struct Grid {
    std::uint32_t columns, rows;
  };
  // Workgroups of 8 x 8: Medium's march tiles at 640x360 (10 x 6) and at 1280x720, a 320x180
  // image, 1920x1080, odd shapes.
  const Grid grids[] = {{10, 6}, {20, 12}, {40, 23}, {240, 135}, {7, 5}, {3, 50}, {13, 11}};
  const auto plain = [](std::uint32_t position, std::uint32_t) { return position; };
  for (const Grid& grid : grids) {
    for (std::uint32_t threads : {2u, 3u, 4u, 8u, 16u}) {
      if (grid.columns * grid.rows / threads < 16) continue;  // too few to share out by band
      EXPECT_LE(worstBandShare(grid.columns, grid.rows, threads, spreadIndex), 0.07)
          << grid.columns << " x " << grid.rows << " workgroups, " << threads << " threads";
      // The plain order, for contrast: a thread's run is a band of rows of its own.
      EXPECT_GE(worstBandShare(grid.columns, grid.rows, threads, plain), 0.25)
          << grid.columns << " x " << grid.rows << " workgroups, " << threads << " threads";
    }
  }
}

}  // namespace
