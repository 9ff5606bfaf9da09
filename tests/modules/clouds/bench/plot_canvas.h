#pragma once
// A tiny CPU raster canvas for the benchmark chart: opaque RGB pixels, coverage-based
// anti-aliasing, nothing more. Coordinates are in pixels with integral values at pixel centres,
// so a crisp one-pixel line at column 10 is drawn at x = 10 (not 10.5).
#include <array>
#include <cstdint>
#include <vector>

#include "engine/assets/image_io.h"

namespace bench {

using Rgb = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  // A widthPx x heightPx canvas filled with `background`. Zero sizes give an empty canvas on
  // which every draw call is a no-op.
  Canvas(std::uint32_t widthPx, std::uint32_t heightPx, Rgb background);

  int width() const { return static_cast<int>(width_); }
  int height() const { return static_cast<int>(height_); }

  // Mixes `colour` into one pixel with weight `coverage` in [0, 1]; pixels outside are ignored.
  void blend(int x, int y, Rgb colour, float coverage);
  // Fills the pixels x in [left, right], y in [top, bottom] (inclusive, clipped).
  void fillRect(int left, int top, int right, int bottom, Rgb colour);
  // A one-pixel outline of the same inclusive rectangle.
  void strokeRect(int left, int top, int right, int bottom, Rgb colour);
  // An anti-aliased segment of the given width with round caps; the coverage of each pixel is
  // its distance to the segment, so slopes look the same as axis-aligned lines.
  void drawLine(double x0, double y0, double x1, double y1, double widthPx, Rgb colour);
  // An anti-aliased filled disc.
  void fillCircle(double centreX, double centreY, double radiusPx, Rgb colour);

  Rgb pixel(int x, int y) const;  // (0, 0, 0) outside the canvas

  // Hands the pixels over as RGBA8 (alpha 255); the canvas is empty afterwards.
  engine::assets::ImageRgba8 release();

 private:
  // Calls blend() for every pixel of the clipped box around a shape whose coverage at a pixel
  // centre is `coverageAt(x, y)`.
  template <typename CoverageFn>
  void fillByCoverage(double left, double top, double right, double bottom, Rgb colour,
                      CoverageFn coverageAt);

  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
  std::vector<std::uint8_t> rgb_;  // 3 * width * height, row 0 at the top
};

}  // namespace bench
