#include "plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace bench {

namespace {

// Coverage of a pixel whose centre lies `signedDistancePx` from the edge of a shape (inside when
// negative): a one-pixel ramp centred on the edge, which is what a box filter gives for a
// straight edge and is close enough for curves of a few pixels' radius.
float edgeCoverage(double signedDistancePx) {
  return static_cast<float>(std::clamp(0.5 - signedDistancePx, 0.0, 1.0));
}

}  // namespace

Canvas::Canvas(std::uint32_t widthPx, std::uint32_t heightPx, Rgb background)
    : width_(widthPx), height_(heightPx) {
  const std::size_t pixelCount = std::size_t{widthPx} * heightPx;
  rgb_.resize(3 * pixelCount);
  for (std::size_t i = 0; i < pixelCount; ++i) {
    for (std::size_t c = 0; c < 3; ++c) rgb_[3 * i + c] = background[c];
  }
}

void Canvas::blend(int x, int y, Rgb colour, float coverage) {
  if (x < 0 || y < 0 || x >= width() || y >= height() || !(coverage > 0.0f)) return;
  const float weight = std::min(coverage, 1.0f);
  std::uint8_t* dst =
      &rgb_[3 * (static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x))];
  for (std::size_t c = 0; c < 3; ++c) {
    // Mixing sRGB-encoded values directly: slightly thin-looking edges, but the chart is
    // compared by eye, not measured, and this keeps the canvas trivial.
    const float mixed = static_cast<float>(dst[c]) +
                        (static_cast<float>(colour[c]) - static_cast<float>(dst[c])) * weight;
    dst[c] = static_cast<std::uint8_t>(std::lround(std::clamp(mixed, 0.0f, 255.0f)));
  }
}

void Canvas::fillRect(int left, int top, int right, int bottom, Rgb colour) {
  left = std::max(left, 0);
  top = std::max(top, 0);
  right = std::min(right, width() - 1);
  bottom = std::min(bottom, height() - 1);
  for (int y = top; y <= bottom; ++y) {
    for (int x = left; x <= right; ++x) blend(x, y, colour, 1.0f);
  }
}

void Canvas::strokeRect(int left, int top, int right, int bottom, Rgb colour) {
  fillRect(left, top, right, top, colour);
  fillRect(left, bottom, right, bottom, colour);
  fillRect(left, top, left, bottom, colour);
  fillRect(right, top, right, bottom, colour);
}

template <typename CoverageFn>
void Canvas::fillByCoverage(double left, double top, double right, double bottom, Rgb colour,
                            CoverageFn coverageAt) {
  // Non-finite bounds (a NaN that slipped through) draw nothing rather than loop forever.
  if (!std::isfinite(left) || !std::isfinite(top) || !std::isfinite(right) ||
      !std::isfinite(bottom)) {
    return;
  }
  const int x0 = std::max(static_cast<int>(std::floor(std::max(left, -1.0))), 0);
  const int y0 = std::max(static_cast<int>(std::floor(std::max(top, -1.0))), 0);
  const int x1 =
      std::min(static_cast<int>(std::ceil(std::min(right, double(width())))), width() - 1);
  const int y1 =
      std::min(static_cast<int>(std::ceil(std::min(bottom, double(height())))), height() - 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) blend(x, y, colour, coverageAt(double(x), double(y)));
  }
}

void Canvas::drawLine(double x0, double y0, double x1, double y1, double widthPx, Rgb colour) {
  const double halfWidth = 0.5 * widthPx;
  const double dx = x1 - x0;
  const double dy = y1 - y0;
  const double lengthSquared = dx * dx + dy * dy;
  const double reach = halfWidth + 1.0;
  fillByCoverage(std::min(x0, x1) - reach, std::min(y0, y1) - reach, std::max(x0, x1) + reach,
                 std::max(y0, y1) + reach, colour, [&](double px, double py) {
                   // Distance from the pixel centre to the closest point of the segment.
                   double t = 0.0;
                   if (lengthSquared > 0.0) {
                     t = std::clamp(((px - x0) * dx + (py - y0) * dy) / lengthSquared, 0.0, 1.0);
                   }
                   const double distance = std::hypot(px - (x0 + t * dx), py - (y0 + t * dy));
                   return edgeCoverage(distance - halfWidth);
                 });
}

void Canvas::fillCircle(double centreX, double centreY, double radiusPx, Rgb colour) {
  const double reach = radiusPx + 1.0;
  fillByCoverage(centreX - reach, centreY - reach, centreX + reach, centreY + reach, colour,
                 [&](double px, double py) {
                   return edgeCoverage(std::hypot(px - centreX, py - centreY) - radiusPx);
                 });
}

Rgb Canvas::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width() || y >= height()) return {0, 0, 0};
  const std::size_t offset =
      3 * (static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x));
  return {rgb_[offset], rgb_[offset + 1], rgb_[offset + 2]};
}

engine::assets::ImageRgba8 Canvas::release() {
  engine::assets::ImageRgba8 image;
  image.width = width_;
  image.height = height_;
  const std::size_t pixelCount = std::size_t{width_} * height_;
  image.pixels.resize(4 * pixelCount);
  for (std::size_t i = 0; i < pixelCount; ++i) {
    image.pixels[4 * i + 0] = rgb_[3 * i + 0];
    image.pixels[4 * i + 1] = rgb_[3 * i + 1];
    image.pixels[4 * i + 2] = rgb_[3 * i + 2];
    image.pixels[4 * i + 3] = 255;
  }
  *this = Canvas(0, 0, {});
  return image;
}

}  // namespace bench
