// The benchmark's Reference looks inside its pixels along a sequence of its own
// (bench_reference.h): even over the pixel, and apart from every Halton (2, 3) point that the
// module's presets sample an output pixel at, so that averaging the Reference cannot share a
// preset's own samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bench_reference.h"
#include "cloud_math.h"

namespace {

constexpr std::uint32_t kFrames = 16;  // the benchmark's Reference frames (bench_run.h)

TEST(BenchReference, OffsetsStayInsideThePixelAndCoverItEvenly) {
  int perQuadrant[2][2] = {};
  glm::vec2 mean(0.0f);
  for (std::uint32_t i = 0; i < kFrames; ++i) {
    const glm::vec2 o = bench::referenceSubpixelOffset(i);
    ASSERT_GE(o.x, -0.5f);
    ASSERT_LT(o.x, 0.5f);
    ASSERT_GE(o.y, -0.5f);
    ASSERT_LT(o.y, 0.5f);
    ++perQuadrant[o.x < 0.0f ? 0 : 1][o.y < 0.0f ? 0 : 1];
    mean += o / float(kFrames);
    // No two frames look at the same point.
    for (std::uint32_t j = 0; j < i; ++j) {
      EXPECT_GT(glm::length(o - bench::referenceSubpixelOffset(j)), 0.2f) << i << " " << j;
    }
  }
  // Each quarter of the pixel holds a quarter of the points, and they do not shift the image.
  for (const auto& row : perQuadrant) {
    for (int count : row) EXPECT_EQ(count, int(kFrames) / 4);
  }
  EXPECT_LT(glm::length(mean), 1e-6f);
  // Every 4 frames in a row spread over the pixel: one in each quarter.
  for (std::uint32_t start = 0; start < kFrames; start += 4) {
    int quarters = 0;
    for (std::uint32_t i = start; i < start + 4; ++i) {
      const glm::vec2 o = bench::referenceSubpixelOffset(i);
      quarters |= 1 << ((o.x < 0.0f ? 0 : 1) + (o.y < 0.0f ? 0 : 2));
    }
    EXPECT_EQ(quarters, 15) << start;
  }
}

TEST(BenchReference, OffsetsAreNotTheModulesHaltonPoints) {
  // The module's points inside an output pixel (uniforms.cpp): Halton (2, 3) indices from 1,
  // offsets from the pixel centre; High holds 2 of them per pixel after 128 frames, 4 after
  // 256. Measured nearest of the first 16: 0.063 pixel.
  float nearest = 1.0f;
  for (std::uint32_t i = 0; i < kFrames; ++i) {
    const glm::vec2 o = bench::referenceSubpixelOffset(i);
    for (std::uint32_t n = 1; n <= 16; ++n) {
      const glm::vec2 h(clouds::shader::halton(n, 2u) - 0.5f, clouds::shader::halton(n, 3u) - 0.5f);
      nearest = std::min(nearest, glm::length(o - h));
    }
  }
  EXPECT_GT(nearest, 0.05f);
}

}  // namespace
