// The image metrics against values worked out by hand: MSE, PSNR, mean and max absolute
// error, the per-pixel threshold count, the channels left out, and the conversions used to
// pool errors.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/assets/image_metrics.h"

namespace {

using engine::assets::compareImages;

TEST(ImageMetrics, KnownDifferences) {
  // Two RGBA pixels; only RGB are compared. Differences: (0.1, 0, 0) and (0, 0.2, 0.4).
  const std::vector<float> a = {0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.2f, 0.4f, 0.0f};
  const std::vector<float> b = {0.4f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  const auto e = compareImages(a, b, 4, 3, 0.3);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_NEAR(e.meanSquared, (0.01 + 0.04 + 0.16) / 6.0, 1e-7);
  EXPECT_NEAR(e.meanAbs, (0.1 + 0.2 + 0.4) / 6.0, 1e-7);
  EXPECT_NEAR(e.maxAbs, 0.4, 1e-7);
  EXPECT_EQ(e.pixelsOver, 1u) << "only the second pixel differs by more than 0.3";
  EXPECT_NEAR(e.psnr(), 10.0 * std::log10(6.0 / 0.21), 1e-5);
  EXPECT_NEAR(e.psnr(2.0), e.psnr() + 20.0 * std::log10(2.0), 1e-9);
  // All four channels: the alpha differences count too.
  EXPECT_NEAR(compareImages(a, b, 4, 4).maxAbs, 1.0, 1e-7);
}

TEST(ImageMetrics, IdenticalAndIncomparableImages) {
  const std::vector<float> a = {0.1f, 0.2f, 0.3f};
  EXPECT_EQ(compareImages(a, a, 3, 3).psnr(), 200.0);
  const std::vector<float> shorter = {0.1f, 0.2f};
  const auto e = compareImages(a, shorter, 3, 3);
  EXPECT_EQ(e.pixels, 0u);
  EXPECT_EQ(e.psnr(), 0.0) << "images that cannot be compared do not agree";
}

TEST(ImageMetrics, PsnrAndMeanSquaredAreInverse) {
  for (double psnr : {10.0, 33.3, 48.0}) {
    EXPECT_NEAR(engine::assets::psnrFromMeanSquared(engine::assets::meanSquaredFromPsnr(psnr)),
                psnr, 1e-9);
  }
  EXPECT_EQ(engine::assets::meanSquaredFromPsnr(200.0), 0.0);
  EXPECT_EQ(engine::assets::psnrFromMeanSquared(0.0), 200.0);
}

}  // namespace
