#pragma once
// Image error metrics, the one implementation every comparison uses: the golden frames, the
// effects' GPU tests and their accuracy-versus-cost benchmarks. Images are flat float arrays
// of pixels with `stride` values each, of which the first `channels` are compared.
#include <cstddef>
#include <limits>
#include <span>

namespace engine::assets {

struct ImageError {
  double meanSquared = 0.0;  // over every compared value
  double meanAbs = 0.0;
  double maxAbs = 0.0;         // the largest difference of any compared value
  std::size_t pixelsOver = 0;  // pixels whose largest channel difference exceeds the
                               //   threshold given to compareImages()
  std::size_t pixels = 0;
  // Peak signal-to-noise ratio in dB for values whose range is [0, peak]; 200 for identical
  // images (an "infinite" PSNR that still sorts and averages); 0 when nothing was compared
  // (the images' sizes differ).
  double psnr(double peak = 1.0) const;
};

// Compares two images of the same size. Returns a zero-pixel ImageError when their sizes
// differ or are not whole pixels.
ImageError compareImages(std::span<const float> a, std::span<const float> b, std::size_t stride,
                         std::size_t channels,
                         double pixelThreshold = std::numeric_limits<double>::infinity());

// PSNR (dB) of a mean squared error, and back: pooling errors over several images averages
// their mean squared errors, not their PSNRs.
double psnrFromMeanSquared(double meanSquared, double peak = 1.0);
double meanSquaredFromPsnr(double psnr, double peak = 1.0);

}  // namespace engine::assets
