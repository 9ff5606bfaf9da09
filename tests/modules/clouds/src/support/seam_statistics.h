#pragma once
// Whether a generated noise texture tiles: the difference between texels across each wrap seam
// is statistically like the difference between interior neighbours (noise_tiling_test.cpp,
// hero_detail_gpu_test.cpp; each with a negative control that does not tile).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace test {

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
inline bool tiles(const SeamStatistics& s, std::string* why) {
  const auto [lo, hi] = std::minmax_element(s.lines.begin(), s.lines.end());
  const bool ok = *hi > 0.0 && s.seam >= 0.75 * *lo && s.seam <= 1.25 * *hi;
  if (why != nullptr) {
    *why = "seam " + std::to_string(s.seam) + ", interior lines in [" + std::to_string(*lo) + ", " +
           std::to_string(*hi) + "]";
  }
  return ok;
}

inline void expectTiles(const SeamStatistics& s, const std::string& what) {
  std::string why;
  EXPECT_TRUE(tiles(s, &why)) << what << ": " << why;
}

}  // namespace test
