#include "golden_compare.h"

#include "engine/assets/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace test {

std::string GoldenResult::describe() const {
  std::ostringstream out;
  if (!sizeMatches) return "image sizes differ";
  out << "failing pixels " << failingFraction * 100.0 << "%, PSNR " << psnr
      << " dB, max channel difference " << maxDifference * 255.0f << "/255";
  return out.str();
}

GoldenResult compareImages(const engine::assets::ImageRgba32f& actual,
                           const engine::assets::ImageRgba32f& expected,
                           const GoldenTolerance& tolerance) {
  GoldenResult r;
  r.sizeMatches =
      actual.width == expected.width && actual.height == expected.height && !actual.pixels.empty();
  if (!r.sizeMatches) return r;
  const engine::assets::ImageError e =
      engine::assets::compareImages(actual.pixels, expected.pixels, 4, 3, tolerance.pixelThreshold);
  r.failingFraction = double(e.pixelsOver) / double(e.pixels);
  r.psnr = e.psnr();
  r.maxDifference = static_cast<float>(e.maxAbs);
  return r;
}

engine::assets::ImageRgba8 diffImage(const engine::assets::ImageRgba32f& actual,
                                     const engine::assets::ImageRgba32f& expected,
                                     const GoldenTolerance& tolerance) {
  engine::assets::ImageRgba8 out{actual.width, actual.height, {}};
  out.pixels.resize(std::size_t{4} * actual.width * actual.height, 255);
  if (actual.width != expected.width || actual.height != expected.height) return out;
  for (std::size_t i = 0; i < std::size_t{actual.width} * actual.height; ++i) {
    float worst = 0.0f;
    for (std::size_t c = 0; c < 3; ++c) {
      const float d = std::abs(actual.pixels[4 * i + c] - expected.pixels[4 * i + c]);
      worst = std::max(worst, d);
      out.pixels[4 * i + c] = static_cast<std::uint8_t>(std::min(d * 8.0f, 1.0f) * 255.0f);
    }
    if (worst > tolerance.pixelThreshold) {
      out.pixels[4 * i + 0] = 255;
      out.pixels[4 * i + 1] = 0;
      out.pixels[4 * i + 2] = 0;
    }
    out.pixels[4 * i + 3] = 255;
  }
  return out;
}

}  // namespace test
