#pragma once
// Golden-image comparison for the sample's frame-capture tests: a tolerance tree (per-pixel
// channel difference threshold, fraction of failing pixels, PSNR floor) and diff images.
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"

namespace test {

struct GoldenTolerance {
  float pixelThreshold = 10.0f / 255.0f;  // a pixel fails when any channel differs by more
  double maxFailingFraction = 0.01;       // at most 1% of pixels may fail
  double minPsnr = 32.0;                  // dB over the 8-bit image (peak 1)
};

struct GoldenResult {
  bool sizeMatches = false;
  double failingFraction = 1.0;
  double psnr = 0.0;
  float maxDifference = 1.0f;
  bool passed(const GoldenTolerance& t) const {
    return sizeMatches && failingFraction <= t.maxFailingFraction && psnr >= t.minPsnr;
  }
  std::string describe() const;
};

GoldenResult compareImages(const engine::assets::ImageRgba32f& actual,
                           const engine::assets::ImageRgba32f& expected,
                           const GoldenTolerance& tolerance);

// |actual - expected| x 8, so small differences are visible; red where a pixel fails.
engine::assets::ImageRgba8 diffImage(const engine::assets::ImageRgba32f& actual,
                                     const engine::assets::ImageRgba32f& expected,
                                     const GoldenTolerance& tolerance);

}  // namespace test
