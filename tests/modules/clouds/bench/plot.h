#pragma once
// A small CPU chart renderer for the accuracy-versus-cost benchmark: scatter series with
// optional connecting lines, log or linear axes, a legend and labelled points, rendered into an
// RGBA8 image that engine::assets::writePng can save. Deterministic, no GPU, no ImGui context.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/assets/image_io.h"
#include "plot_axis.h"

namespace bench {

struct PlotPoint {
  double x = 0.0;
  double y = 0.0;
  std::string label;  // drawn next to the point when non-empty
};

struct PlotSeries {
  std::string name;                   // shown in the legend
  std::array<std::uint8_t, 3> rgb{};  // marker and line colour, sRGB
  std::vector<PlotPoint> points;
  bool connect = false;     // draw segments between consecutive points (a sweep of one knob)
  bool emphasised = false;  // larger, outlined markers (the quality presets)
};

struct PlotDesc {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = true;  // x in milliseconds on a log10 axis
  bool logY = false;
  std::uint32_t width = 1100;  // image size in pixels
  std::uint32_t height = 720;
};

// Where the data area sits in the image and how data maps onto it; what renderPlot draws with.
struct PlotLayout {
  PlotAxis xAxis;
  PlotAxis yAxis;
  // The frame of the data area, in pixel coordinates with integral values at pixel centres:
  // x = xAxis.min maps to frameLeftPx, y = yAxis.min to frameBottomPx.
  int frameLeftPx = 0;
  int frameTopPx = 0;
  int frameRightPx = 0;
  int frameBottomPx = 0;
  bool hasLegend = false;  // false when there are no series or no room beside the frame

  double pixelX(double x) const;  // NaN when the x axis cannot show `x`
  double pixelY(double y) const;  // NaN when the y axis cannot show `y`
};

// The layout renderPlot uses for these inputs (axes fitted to every point either axis can show).
PlotLayout layoutPlot(const PlotDesc& desc, const std::vector<PlotSeries>& series);

// Renders the chart: white background, light grid, frame, ticks and tick labels, axis titles,
// title, a legend beside the data area, then lines, markers and point labels. Points with a
// coordinate an axis cannot show (non-finite, or <= 0 on a log axis) are skipped and break a
// connected line; with nothing to show the axes are drawn with a "no data" note. Always returns
// a desc.width x desc.height image (opaque).
engine::assets::ImageRgba8 renderPlot(const PlotDesc& desc, const std::vector<PlotSeries>& series);

// The left edge of a point label `textWidthPx` wide: right of the marker at `anchorPx` with a
// `gapPx` gap, or left of it when that would cross `rightLimitPx`, and never left of
// `leftLimitPx`.
int pointLabelLeftPx(double anchorPx, int gapPx, int textWidthPx, int leftLimitPx,
                     int rightLimitPx);

}  // namespace bench
