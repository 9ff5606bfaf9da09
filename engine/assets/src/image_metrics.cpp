#include "engine/assets/image_metrics.h"

#include <algorithm>
#include <cmath>

namespace engine::assets {

namespace {
constexpr double kIdenticalPsnr = 200.0;
}

double psnrFromMeanSquared(double meanSquared, double peak) {
  return meanSquared <= 0.0 ? kIdenticalPsnr : 10.0 * std::log10(peak * peak / meanSquared);
}

double meanSquaredFromPsnr(double psnr, double peak) {
  return psnr >= kIdenticalPsnr ? 0.0 : peak * peak * std::pow(10.0, -psnr / 10.0);
}

double ImageError::psnr(double peak) const {
  return pixels == 0 ? 0.0 : psnrFromMeanSquared(meanSquared, peak);
}

ImageError compareImages(std::span<const float> a, std::span<const float> b, std::size_t stride,
                         std::size_t channels, double pixelThreshold) {
  ImageError error;
  if (a.size() != b.size() || stride == 0 || channels == 0 || channels > stride ||
      a.size() % stride != 0) {
    return error;
  }
  double squares = 0.0;
  double sum = 0.0;
  error.pixels = a.size() / stride;
  for (std::size_t p = 0; p < error.pixels; ++p) {
    double worst = 0.0;
    for (std::size_t c = 0; c < channels; ++c) {
      const double d = std::abs(double(a[p * stride + c]) - double(b[p * stride + c]));
      squares += d * d;
      sum += d;
      worst = std::max(worst, d);
    }
    error.maxAbs = std::max(error.maxAbs, worst);
    error.pixelsOver += worst > pixelThreshold ? 1 : 0;
  }
  const double count = double(error.pixels * channels);
  if (count > 0.0) {
    error.meanSquared = squares / count;
    error.meanAbs = sum / count;
  }
  return error;
}

}  // namespace engine::assets
