#include "plot.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "plot_canvas.h"
#include "plot_font.h"

namespace bench {

namespace {

// Colours: near-black ink for text and frame, two greys for the grid so decades stand out from
// the 2 and 5 minor lines.
constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kInk{34, 34, 34};
constexpr Rgb kFrame{70, 70, 70};
constexpr Rgb kMajorGrid{218, 218, 218};
constexpr Rgb kMinorGrid{238, 238, 238};
constexpr Rgb kLegendBorder{170, 170, 170};
constexpr Rgb kNote{120, 120, 120};

// Sizes in pixels.
constexpr int kOuterPaddingPx = 16;
constexpr int kTitleGapPx = 14;  // below the title
constexpr int kMajorTickPx = 6;
constexpr int kMinorTickPx = 3;
constexpr int kTickLabelGapPx = 4;   // between a tick and its label
constexpr int kAxisTitleGapPx = 10;  // between tick labels and the axis title
constexpr int kLegendGapPx = 28;     // between the frame and the legend; room for a tick label
constexpr int kLegendPaddingPx = 8;
constexpr int kLegendRowGapPx = 8;
constexpr int kLegendSwatchPx = 28;    // the line-and-marker sample before each name
constexpr int kMinFrameWidthPx = 120;  // below this the legend is dropped to keep the data
constexpr double kLineWidthPx = 2.0;
constexpr double kMarkerRadiusPx = 4.0;
constexpr double kEmphasisedRadiusPx = 6.5;
constexpr int kPointLabelGapPx = 5;  // between a marker's edge and its label
// Image sizes are clamped to this for layout arithmetic in int; a chart is never this big.
constexpr std::uint32_t kMaxLayoutSizePx = 1u << 20;
constexpr double kMinXLabelSpacingPx = 50.0;  // between tick label anchors: "5000" is 28 px
constexpr double kMinYLabelSpacingPx = 32.0;

// The layout plus what was measured to build it, so rendering does not measure twice.
struct ChartGeometry {
  PlotLayout layout;
  std::vector<AxisTick> xTicks;
  std::vector<AxisTick> yTicks;
  int legendLeftPx = 0;
  int legendTopPx = 0;
  int legendWidthPx = 0;
  int legendEntryHeightPx = 0;
  TextSize titleSize = TextSize::Title;  // Label when the large title would not fit the width
  bool drawable = false;                 // false when the image is too small for a frame
};

bool showable(const PlotLayout& layout, const PlotPoint& point) {
  return layout.xAxis.canShow(point.x) && layout.yAxis.canShow(point.y);
}

// Fits both axes to the points that both axes can show: a point skipped on one axis must not
// stretch the other.
void fitAxes(const PlotDesc& desc, const std::vector<PlotSeries>& series, PlotLayout& layout) {
  const PlotAxis xProbe{1.0, 10.0, desc.logX};
  const PlotAxis yProbe{1.0, 10.0, desc.logY};
  std::vector<double> xs;
  std::vector<double> ys;
  for (const PlotSeries& s : series) {
    for (const PlotPoint& p : s.points) {
      if (!xProbe.canShow(p.x) || !yProbe.canShow(p.y)) continue;
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  }
  layout.xAxis = fitAxis(xs, desc.logX);
  layout.yAxis = fitAxis(ys, desc.logY);
}

int widestLabelPx(const PlotFont& font, const std::vector<AxisTick>& ticks) {
  int widest = 0;
  for (const AxisTick& tick : ticks) {
    widest = std::max(widest, font.textWidthPx(TextSize::Label, tick.label));
  }
  return widest;
}

ChartGeometry computeGeometry(const PlotDesc& desc, const std::vector<PlotSeries>& series,
                              const PlotFont& font) {
  ChartGeometry geometry;
  PlotLayout& layout = geometry.layout;
  fitAxes(desc, series, layout);
  const int widthPx = static_cast<int>(std::min(desc.width, kMaxLayoutSizePx));
  const int heightPx = static_cast<int>(std::min(desc.height, kMaxLayoutSizePx));
  const int labelHeightPx = font.lineHeightPx(TextSize::Label);
  if (font.textWidthPx(TextSize::Title, desc.title) > widthPx - 2 * kOuterPaddingPx) {
    geometry.titleSize = TextSize::Label;
  }

  // Vertical first: the y ticks depend on the frame's height, and their labels set the left
  // margin, which the x ticks then depend on.
  const int titleBandPx =
      desc.title.empty() ? 0 : font.lineHeightPx(geometry.titleSize) + kTitleGapPx;
  const int xTitleBandPx = desc.xLabel.empty() ? 0 : kAxisTitleGapPx + labelHeightPx;
  layout.frameTopPx = kOuterPaddingPx + titleBandPx + labelHeightPx / 2;
  layout.frameBottomPx = heightPx - 1 - kOuterPaddingPx - xTitleBandPx - labelHeightPx -
                         kTickLabelGapPx - kMajorTickPx;
  const int frameHeightPx = layout.frameBottomPx - layout.frameTopPx;
  geometry.yTicks = axisTicks(layout.yAxis, frameHeightPx, kMinYLabelSpacingPx);

  const int yTitleBandPx = desc.yLabel.empty() ? 0 : labelHeightPx + kAxisTitleGapPx;
  layout.frameLeftPx = kOuterPaddingPx + yTitleBandPx + widestLabelPx(font, geometry.yTicks) +
                       kTickLabelGapPx + kMajorTickPx;

  // The legend sits right of the frame, as wide as its longest name; it is dropped when it
  // would squeeze the data area below a useful width.
  int widestNamePx = 0;
  for (const PlotSeries& s : series) {
    widestNamePx = std::max(widestNamePx, font.textWidthPx(TextSize::Label, s.name));
  }
  geometry.legendWidthPx = 3 * kLegendPaddingPx + kLegendSwatchPx + widestNamePx;
  geometry.legendEntryHeightPx = labelHeightPx + kLegendRowGapPx;
  geometry.legendLeftPx = widthPx - kOuterPaddingPx - geometry.legendWidthPx;
  geometry.legendTopPx = layout.frameTopPx;
  const int frameRightWithLegendPx = geometry.legendLeftPx - kLegendGapPx;
  layout.hasLegend =
      !series.empty() && frameRightWithLegendPx - layout.frameLeftPx >= kMinFrameWidthPx;
  layout.frameRightPx =
      layout.hasLegend ? frameRightWithLegendPx : widthPx - 1 - kOuterPaddingPx - kLegendGapPx / 2;

  const int frameWidthPx = layout.frameRightPx - layout.frameLeftPx;
  geometry.drawable = frameWidthPx >= 2 && frameHeightPx >= 2;
  if (geometry.drawable) {
    geometry.xTicks = axisTicks(layout.xAxis, frameWidthPx, kMinXLabelSpacingPx);
  }
  return geometry;
}

// Text with a one-pixel white halo, so labels stay legible where they cross grid or data lines.
void drawHaloText(Canvas& canvas, const PlotFont& font, int leftPx, int topPx,
                  std::string_view text, Rgb colour) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx != 0 || dy != 0) {
        font.draw(canvas, TextSize::Label, leftPx + dx, topPx + dy, text, kWhite);
      }
    }
  }
  font.draw(canvas, TextSize::Label, leftPx, topPx, text, colour);
}

void drawMarker(Canvas& canvas, double xPx, double yPx, Rgb colour, bool emphasised) {
  if (emphasised) {
    // A dark rim separates the presets from the sweeps they sit among.
    canvas.fillCircle(xPx, yPx, kEmphasisedRadiusPx + 1.5, kInk);
    canvas.fillCircle(xPx, yPx, kEmphasisedRadiusPx, colour);
  } else {
    // A white ring lifts the marker off its own connecting line.
    canvas.fillCircle(xPx, yPx, kMarkerRadiusPx + 1.0, kWhite);
    canvas.fillCircle(xPx, yPx, kMarkerRadiusPx, colour);
  }
}

void drawGridAndTicks(Canvas& canvas, const PlotFont& font, const ChartGeometry& geometry) {
  const PlotLayout& layout = geometry.layout;
  const int labelHeightPx = font.lineHeightPx(TextSize::Label);
  // All grid lines first, so no minor line is drawn over a major one.
  for (const bool major : {false, true}) {
    for (const AxisTick& tick : geometry.xTicks) {
      if (tick.major != major) continue;
      const int xPx = static_cast<int>(std::lround(layout.pixelX(tick.value)));
      canvas.fillRect(xPx, layout.frameTopPx, xPx, layout.frameBottomPx,
                      major ? kMajorGrid : kMinorGrid);
    }
    for (const AxisTick& tick : geometry.yTicks) {
      if (tick.major != major) continue;
      const int yPx = static_cast<int>(std::lround(layout.pixelY(tick.value)));
      canvas.fillRect(layout.frameLeftPx, yPx, layout.frameRightPx, yPx,
                      major ? kMajorGrid : kMinorGrid);
    }
  }
  canvas.strokeRect(layout.frameLeftPx, layout.frameTopPx, layout.frameRightPx,
                    layout.frameBottomPx, kFrame);

  for (const AxisTick& tick : geometry.xTicks) {
    const int xPx = static_cast<int>(std::lround(layout.pixelX(tick.value)));
    const int lengthPx = tick.major ? kMajorTickPx : kMinorTickPx;
    canvas.fillRect(xPx, layout.frameBottomPx + 1, xPx, layout.frameBottomPx + lengthPx, kFrame);
    if (tick.label.empty()) continue;
    const int labelWidthPx = font.textWidthPx(TextSize::Label, tick.label);
    font.draw(canvas, TextSize::Label, xPx - labelWidthPx / 2,
              layout.frameBottomPx + kMajorTickPx + kTickLabelGapPx, tick.label, kInk);
  }
  for (const AxisTick& tick : geometry.yTicks) {
    const int yPx = static_cast<int>(std::lround(layout.pixelY(tick.value)));
    const int lengthPx = tick.major ? kMajorTickPx : kMinorTickPx;
    canvas.fillRect(layout.frameLeftPx - lengthPx, yPx, layout.frameLeftPx - 1, yPx, kFrame);
    if (tick.label.empty()) continue;
    const int labelWidthPx = font.textWidthPx(TextSize::Label, tick.label);
    font.draw(canvas, TextSize::Label,
              layout.frameLeftPx - kMajorTickPx - kTickLabelGapPx - labelWidthPx,
              yPx - labelHeightPx / 2, tick.label, kInk);
  }
}

void drawTitles(Canvas& canvas, const PlotFont& font, const PlotDesc& desc,
                const ChartGeometry& geometry) {
  const PlotLayout& layout = geometry.layout;
  const int labelHeightPx = font.lineHeightPx(TextSize::Label);
  const int frameCentreXPx = (layout.frameLeftPx + layout.frameRightPx) / 2;
  const int frameCentreYPx = (layout.frameTopPx + layout.frameBottomPx) / 2;
  if (!desc.title.empty()) {
    // Centred over the data area, but kept inside the image when it is wider than that.
    const int titleWidthPx = font.textWidthPx(geometry.titleSize, desc.title);
    const int leftPx =
        std::clamp(frameCentreXPx - titleWidthPx / 2, kOuterPaddingPx,
                   std::max(kOuterPaddingPx, canvas.width() - kOuterPaddingPx - titleWidthPx));
    font.draw(canvas, geometry.titleSize, leftPx, kOuterPaddingPx, desc.title, kInk);
  }
  if (!desc.xLabel.empty()) {
    const int widthPx = font.textWidthPx(TextSize::Label, desc.xLabel);
    font.draw(
        canvas, TextSize::Label, frameCentreXPx - widthPx / 2,
        layout.frameBottomPx + kMajorTickPx + kTickLabelGapPx + labelHeightPx + kAxisTitleGapPx,
        desc.xLabel, kInk);
  }
  if (!desc.yLabel.empty()) {
    const int widthPx = font.textWidthPx(TextSize::Label, desc.yLabel);
    font.drawUpward(canvas, TextSize::Label, kOuterPaddingPx, frameCentreYPx + widthPx / 2,
                    desc.yLabel, kInk);
  }
}

void drawSeries(Canvas& canvas, const PlotFont& font, const std::vector<PlotSeries>& series,
                const PlotLayout& layout) {
  // Lines under all markers, markers under all point labels: a label must never be hidden by
  // another series' marker.
  for (const PlotSeries& s : series) {
    if (!s.connect) continue;
    const PlotPoint* previous = nullptr;
    for (const PlotPoint& point : s.points) {
      // A point that cannot be shown breaks the line rather than being bridged over.
      if (!showable(layout, point)) {
        previous = nullptr;
        continue;
      }
      if (previous != nullptr) {
        canvas.drawLine(layout.pixelX(previous->x), layout.pixelY(previous->y),
                        layout.pixelX(point.x), layout.pixelY(point.y), kLineWidthPx, s.rgb);
      }
      previous = &point;
    }
  }
  for (const PlotSeries& s : series) {
    for (const PlotPoint& point : s.points) {
      if (!showable(layout, point)) continue;
      drawMarker(canvas, layout.pixelX(point.x), layout.pixelY(point.y), s.rgb, s.emphasised);
    }
  }
  const int labelHeightPx = font.lineHeightPx(TextSize::Label);
  for (const PlotSeries& s : series) {
    const int gapPx =
        static_cast<int>(std::ceil(s.emphasised ? kEmphasisedRadiusPx : kMarkerRadiusPx)) +
        kPointLabelGapPx;
    for (const PlotPoint& point : s.points) {
      if (point.label.empty() || !showable(layout, point)) continue;
      const int widthPx = font.textWidthPx(TextSize::Label, point.label);
      const int leftPx = pointLabelLeftPx(layout.pixelX(point.x), gapPx, widthPx,
                                          layout.frameLeftPx + 2, layout.frameRightPx - 2);
      const int topPx =
          std::clamp(static_cast<int>(std::lround(layout.pixelY(point.y))) - labelHeightPx / 2,
                     layout.frameTopPx + 2, layout.frameBottomPx - 1 - labelHeightPx);
      drawHaloText(canvas, font, leftPx, topPx, point.label, kInk);
    }
  }
}

void drawLegend(Canvas& canvas, const PlotFont& font, const std::vector<PlotSeries>& series,
                const ChartGeometry& geometry) {
  const int entryHeightPx = geometry.legendEntryHeightPx;
  const int leftPx = geometry.legendLeftPx;
  const int topPx = geometry.legendTopPx;
  const int heightPx =
      2 * kLegendPaddingPx + static_cast<int>(series.size()) * entryHeightPx - kLegendRowGapPx;
  canvas.fillRect(leftPx, topPx, leftPx + geometry.legendWidthPx - 1, topPx + heightPx - 1, kWhite);
  canvas.strokeRect(leftPx, topPx, leftPx + geometry.legendWidthPx - 1, topPx + heightPx - 1,
                    kLegendBorder);
  const int labelHeightPx = font.lineHeightPx(TextSize::Label);
  int entryTopPx = topPx + kLegendPaddingPx;
  for (const PlotSeries& s : series) {
    const double swatchLeftPx = leftPx + kLegendPaddingPx;
    const double centreYPx = entryTopPx + 0.5 * (labelHeightPx - 1);
    if (s.connect) {
      canvas.drawLine(swatchLeftPx, centreYPx, swatchLeftPx + kLegendSwatchPx - 1, centreYPx,
                      kLineWidthPx, s.rgb);
    }
    drawMarker(canvas, swatchLeftPx + 0.5 * (kLegendSwatchPx - 1), centreYPx, s.rgb, s.emphasised);
    font.draw(canvas, TextSize::Label, leftPx + 2 * kLegendPaddingPx + kLegendSwatchPx, entryTopPx,
              s.name, kInk);
    entryTopPx += entryHeightPx;
  }
}

void drawNoDataNote(Canvas& canvas, const PlotFont& font, const PlotLayout& layout) {
  const std::string_view note = "no data";
  const int leftPx =
      (layout.frameLeftPx + layout.frameRightPx - font.textWidthPx(TextSize::Label, note)) / 2;
  const int topPx =
      (layout.frameTopPx + layout.frameBottomPx - font.lineHeightPx(TextSize::Label)) / 2;
  font.draw(canvas, TextSize::Label, leftPx, topPx, note, kNote);
}

bool hasShowablePoint(const std::vector<PlotSeries>& series, const PlotLayout& layout) {
  for (const PlotSeries& s : series) {
    for (const PlotPoint& point : s.points) {
      if (showable(layout, point)) return true;
    }
  }
  return false;
}

}  // namespace

double PlotLayout::pixelX(double x) const {
  return frameLeftPx + xAxis.fraction(x) * (frameRightPx - frameLeftPx);
}

double PlotLayout::pixelY(double y) const {
  // Image rows grow downwards, data upwards.
  return frameBottomPx - yAxis.fraction(y) * (frameBottomPx - frameTopPx);
}

PlotLayout layoutPlot(const PlotDesc& desc, const std::vector<PlotSeries>& series) {
  const PlotFont font;
  return computeGeometry(desc, series, font).layout;
}

int pointLabelLeftPx(double anchorPx, int gapPx, int textWidthPx, int leftLimitPx,
                     int rightLimitPx) {
  const int anchor = static_cast<int>(std::lround(anchorPx));
  int leftPx = anchor + gapPx;
  if (leftPx + textWidthPx > rightLimitPx) leftPx = anchor - gapPx - textWidthPx;
  return std::max(leftPx, leftLimitPx);
}

engine::assets::ImageRgba8 renderPlot(const PlotDesc& desc, const std::vector<PlotSeries>& series) {
  Canvas canvas(desc.width, desc.height, kWhite);
  const PlotFont font;
  const ChartGeometry geometry = computeGeometry(desc, series, font);
  if (!geometry.drawable) return canvas.release();

  drawGridAndTicks(canvas, font, geometry);
  drawTitles(canvas, font, desc, geometry);
  if (hasShowablePoint(series, geometry.layout)) {
    drawSeries(canvas, font, series, geometry.layout);
  } else {
    drawNoDataNote(canvas, font, geometry.layout);
  }
  if (geometry.layout.hasLegend) drawLegend(canvas, font, series, geometry);
  return canvas.release();
}

}  // namespace bench
