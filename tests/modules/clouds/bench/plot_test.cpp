#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/assets/image_io.h"
#include "plot.h"

namespace {

using bench::AxisTick;
using bench::PlotAxis;
using bench::PlotDesc;
using bench::PlotLayout;
using bench::PlotPoint;
using bench::PlotSeries;
using Rgb = std::array<std::uint8_t, 3>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Rgb pixelAt(const engine::assets::ImageRgba8& image, int x, int y) {
  const std::size_t offset =
      4 * (static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x));
  return {image.pixels[offset], image.pixels[offset + 1], image.pixels[offset + 2]};
}

bool sameColour(Rgb a, Rgb b, int tolerance) {
  for (std::size_t c = 0; c < 3; ++c) {
    if (std::abs(int(a[c]) - int(b[c])) > tolerance) return false;
  }
  return true;
}

// Whether `colour` appears within `radiusPx` pixels (a square) of (xPx, yPx).
bool colourNear(const engine::assets::ImageRgba8& image, double xPx, double yPx, int radiusPx,
                Rgb colour) {
  const int cx = static_cast<int>(std::lround(xPx));
  const int cy = static_cast<int>(std::lround(yPx));
  for (int y = cy - radiusPx; y <= cy + radiusPx; ++y) {
    for (int x = cx - radiusPx; x <= cx + radiusPx; ++x) {
      if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) continue;
      if (sameColour(pixelAt(image, x, y), colour, 6)) return true;
    }
  }
  return false;
}

// Pixels darker than mid-grey in rows [top, bottom) and columns [left, right).
int countDarkPixels(const engine::assets::ImageRgba8& image, int left, int top, int right,
                    int bottom) {
  int count = 0;
  for (int y = std::max(top, 0); y < std::min(bottom, int(image.height)); ++y) {
    for (int x = std::max(left, 0); x < std::min(right, int(image.width)); ++x) {
      const Rgb p = pixelAt(image, x, y);
      if (int(p[0]) + int(p[1]) + int(p[2]) < 3 * 110) ++count;
    }
  }
  return count;
}

PlotDesc smallDesc() {
  PlotDesc desc;
  desc.title = "Accuracy versus cost";
  desc.xLabel = "frame time (ms)";
  desc.yLabel = "PSNR (dB)";
  desc.width = 640;
  desc.height = 420;
  return desc;
}

// ---- axes ---------------------------------------------------------------------------------

TEST(PlotAxis, LogFractionPlacesDecadesEvenly) {
  const PlotAxis axis{0.1, 1000.0, true};
  EXPECT_NEAR(axis.fraction(0.1), 0.0, 1e-12);
  EXPECT_NEAR(axis.fraction(1.0), 0.25, 1e-12);
  EXPECT_NEAR(axis.fraction(100.0), 0.75, 1e-12);
  EXPECT_NEAR(axis.fraction(1000.0), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(axis.fraction(0.0)));
  EXPECT_TRUE(std::isnan(axis.fraction(-3.0)));
  EXPECT_TRUE(std::isnan(axis.fraction(kNaN)));
}

TEST(PlotAxis, LogFitRoundsOutToHalfDecades) {
  // 1 and 100 ms, padded and rounded out to half decades: 10^-0.5 .. 10^2.5, so the two points
  // sit a sixth in from either end.
  const std::vector<double> oneToHundred{1.0, 100.0};
  const PlotAxis axis = bench::fitAxis(oneToHundred, true);
  EXPECT_TRUE(axis.log);
  EXPECT_NEAR(std::log10(axis.min), -0.5, 1e-12);
  EXPECT_NEAR(std::log10(axis.max), 2.5, 1e-12);
  EXPECT_NEAR(axis.fraction(1.0), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(axis.fraction(100.0), 5.0 / 6.0, 1e-12);

  const std::vector<double> benchmarkRange{2.0, 3000.0};
  const PlotAxis wide = bench::fitAxis(benchmarkRange, true);
  EXPECT_LT(wide.min, 2.0);
  EXPECT_GT(wide.max, 3000.0);
  for (const double limit : {wide.min, wide.max}) {
    const double halfDecades = 2.0 * std::log10(limit);
    EXPECT_NEAR(halfDecades, std::round(halfDecades), 1e-9) << limit;
  }
}

TEST(PlotAxis, LinearFitPadsTheDataSpan) {
  const std::vector<double> psnr{20.0, 60.0, 35.0};
  const PlotAxis axis = bench::fitAxis(psnr, false);
  EXPECT_FALSE(axis.log);
  EXPECT_NEAR(axis.min, 18.0, 1e-12);
  EXPECT_NEAR(axis.max, 62.0, 1e-12);

  const std::vector<double> single{40.0};
  const PlotAxis around = bench::fitAxis(single, false);
  EXPECT_LT(around.min, 40.0);
  EXPECT_GT(around.max, 40.0);
}

TEST(PlotAxis, FitSkipsValuesTheAxisCannotShow) {
  const std::vector<double> mixed{kNaN, -5.0, 0.0, kInf, -kInf, 10.0, 100.0};
  const std::vector<double> clean{10.0, 100.0};
  const PlotAxis logMixed = bench::fitAxis(mixed, true);
  const PlotAxis logClean = bench::fitAxis(clean, true);
  EXPECT_DOUBLE_EQ(logMixed.min, logClean.min);
  EXPECT_DOUBLE_EQ(logMixed.max, logClean.max);

  const PlotAxis linearMixed = bench::fitAxis(mixed, false);
  EXPECT_DOUBLE_EQ(linearMixed.min, -5.0 - 0.05 * 105.0);
  EXPECT_DOUBLE_EQ(linearMixed.max, 100.0 + 0.05 * 105.0);

  const std::vector<double> nothing{kNaN, -1.0};
  const PlotAxis fallback = bench::fitAxis(nothing, true);
  EXPECT_GT(fallback.min, 0.0);
  EXPECT_GT(fallback.max, fallback.min);
}

TEST(PlotAxis, LinearTicksStepByOneTwoOrFiveTimesAPowerOfTen) {
  const PlotAxis axis{18.0, 62.0, false};
  const std::vector<AxisTick> ticks = bench::axisTicks(axis, 600.0, 32.0);
  ASSERT_EQ(ticks.size(), 9u);  // 20, 25, ..., 60
  EXPECT_EQ(ticks.front().label, "20");
  EXPECT_EQ(ticks.back().label, "60");
  for (const AxisTick& tick : ticks) {
    EXPECT_NEAR(std::fmod(tick.value, 5.0), 0.0, 1e-9) << tick.value;
  }
  // Less room: coarser steps, still 1/2/5 x 10^n, and still inside the range.
  for (const double lengthPx : {100.0, 200.0, 1000.0}) {
    const std::vector<AxisTick> coarse = bench::axisTicks(axis, lengthPx, 32.0);
    ASSERT_GE(coarse.size(), 2u) << lengthPx;
    const double step = coarse[1].value - coarse[0].value;
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                std::abs(mantissa - 5.0) < 1e-9)
        << "step " << step << " at " << lengthPx << " px";
    EXPECT_LE(double(coarse.size() - 1), lengthPx / 32.0);
    EXPECT_GE(coarse.front().value, axis.min);
    EXPECT_LE(coarse.back().value, axis.max);
  }
  const std::vector<AxisTick> fractional = bench::axisTicks(PlotAxis{0.0, 1.0, false}, 600, 60);
  ASSERT_FALSE(fractional.empty());
  EXPECT_EQ(fractional.front().label, "0");
  EXPECT_EQ(fractional[1].label, "0.1");
}

TEST(PlotAxis, LogTicksMarkDecadesAndLabelMinorTicksWhenThereIsRoom) {
  const PlotAxis axis{0.1, 1000.0, true};
  const std::vector<AxisTick> roomy = bench::axisTicks(axis, 800.0, 40.0);
  std::vector<std::string> majorLabels;
  std::vector<std::string> minorLabels;
  for (const AxisTick& tick : roomy) (tick.major ? majorLabels : minorLabels).push_back(tick.label);
  EXPECT_EQ(majorLabels, (std::vector<std::string>{"0.1", "1", "10", "100", "1000"}));
  EXPECT_EQ(minorLabels,
            (std::vector<std::string>{"0.2", "0.5", "2", "5", "20", "50", "200", "500"}));

  // 25 px per decade: minor ticks lose their labels and only every other decade keeps one.
  const std::vector<AxisTick> cramped = bench::axisTicks(axis, 100.0, 40.0);
  int labelled = 0;
  for (const AxisTick& tick : cramped) {
    if (!tick.major) {
      EXPECT_TRUE(tick.label.empty()) << tick.value;
    }
    if (!tick.label.empty()) ++labelled;
  }
  EXPECT_EQ(labelled, 2);  // 1 and 100
}

TEST(PlotAxis, FormatsTickValuesCompactly) {
  EXPECT_EQ(bench::formatTickValue(0.5, 1), "0.5");
  EXPECT_EQ(bench::formatTickValue(1000.0, 0), "1000");
  EXPECT_EQ(bench::formatTickValue(-0.00001, 1), "-1e-5");
  EXPECT_EQ(bench::formatTickValue(-0.0004, 2), "0");
  EXPECT_EQ(bench::formatTickValue(2e6, 0), "2e6");
  EXPECT_EQ(bench::formatTickValue(0.0, 3), "0");
}

// ---- layout -------------------------------------------------------------------------------

TEST(PlotLabel, GoesLeftOfTheMarkerNearTheRightEdge) {
  EXPECT_EQ(bench::pointLabelLeftPx(100.0, 8, 50, 0, 1000), 108);
  EXPECT_EQ(bench::pointLabelLeftPx(980.0, 8, 50, 0, 1000), 980 - 8 - 50);
  EXPECT_EQ(bench::pointLabelLeftPx(20.0, 8, 50, 4, 60), 4);  // no room either side: clamp left
}

TEST(PlotLayout, MapsPointsInsideTheFrame) {
  PlotDesc desc = smallDesc();
  const std::vector<PlotSeries> series{
      {"sweep", {0, 114, 178}, {{1.0, 20.0, ""}, {100.0, 60.0, ""}}}};
  const PlotLayout layout = bench::layoutPlot(desc, series);
  EXPECT_TRUE(layout.hasLegend);
  EXPECT_GT(layout.frameLeftPx, 0);
  EXPECT_LT(layout.frameRightPx, int(desc.width) - 1);
  EXPECT_GT(layout.frameTopPx, 0);
  EXPECT_LT(layout.frameBottomPx, int(desc.height) - 1);
  // 1 and 100 ms a sixth in from either side of the log axis; y increases upwards.
  const double frameWidth = layout.frameRightPx - layout.frameLeftPx;
  EXPECT_NEAR(layout.pixelX(1.0), layout.frameLeftPx + frameWidth / 6.0, 1e-9);
  EXPECT_NEAR(layout.pixelX(100.0), layout.frameLeftPx + frameWidth * 5.0 / 6.0, 1e-9);
  EXPECT_GT(layout.pixelY(20.0), layout.pixelY(60.0));
  EXPECT_TRUE(std::isnan(layout.pixelX(-1.0)));
}

// ---- rendering ----------------------------------------------------------------------------

TEST(RenderPlot, ImageHasTheRequestedSizeAndIsOpaque) {
  PlotDesc desc = smallDesc();
  desc.width = 643;
  desc.height = 401;
  const auto image = bench::renderPlot(desc, {{"a", {200, 30, 40}, {{5.0, 30.0, "p"}}}});
  EXPECT_EQ(image.width, 643u);
  EXPECT_EQ(image.height, 401u);
  ASSERT_EQ(image.pixels.size(), std::size_t{4} * 643 * 401);
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) ASSERT_EQ(image.pixels[i], 255) << i;
  EXPECT_EQ(pixelAt(image, 0, 0), (Rgb{255, 255, 255}));
  EXPECT_EQ(pixelAt(image, 642, 400), (Rgb{255, 255, 255}));
}

TEST(RenderPlot, MarkerColourAppearsOnlyWhereItsPointsMap) {
  const PlotDesc desc = smallDesc();
  const Rgb red{200, 30, 40};
  const Rgb blue{30, 60, 200};
  const std::vector<PlotSeries> series{
      {"red", red, {{1.0, 30.0, ""}, {100.0, 50.0, ""}}},
      {"blue", blue, {{10.0, 40.0, ""}}, false, true},
  };
  const auto image = bench::renderPlot(desc, series);
  const PlotLayout layout = bench::layoutPlot(desc, series);
  for (const PlotSeries& s : series) {
    for (const PlotPoint& p : s.points) {
      EXPECT_TRUE(colourNear(image, layout.pixelX(p.x), layout.pixelY(p.y), 1, s.rgb))
          << s.name << " at " << p.x << ", " << p.y;
    }
  }
  EXPECT_FALSE(colourNear(image, layout.pixelX(10.0), layout.pixelY(40.0), 2, red));
  // Inside the frame, every red pixel belongs to a red marker (the legend is outside).
  for (int y = layout.frameTopPx; y <= layout.frameBottomPx; ++y) {
    for (int x = layout.frameLeftPx; x <= layout.frameRightPx; ++x) {
      if (!sameColour(pixelAt(image, x, y), red, 6)) continue;
      bool nearAPoint = false;
      for (const PlotPoint& p : series[0].points) {
        nearAPoint |= std::hypot(x - layout.pixelX(p.x), y - layout.pixelY(p.y)) < 6.0;
      }
      EXPECT_TRUE(nearAPoint) << "stray red pixel at " << x << ", " << y;
    }
  }
}

TEST(RenderPlot, ConnectedSeriesDrawsItsLineBetweenPoints) {
  const PlotDesc desc = smallDesc();
  const Rgb green{0, 158, 115};
  const std::vector<PlotSeries> series{
      {"sweep", green, {{2.0, 25.0, ""}, {200.0, 55.0, ""}}, true}};
  const auto image = bench::renderPlot(desc, series);
  const PlotLayout layout = bench::layoutPlot(desc, series);
  const double midX = 0.5 * (layout.pixelX(2.0) + layout.pixelX(200.0));
  const double midY = 0.5 * (layout.pixelY(25.0) + layout.pixelY(55.0));
  EXPECT_TRUE(colourNear(image, midX, midY, 1, green));

  PlotDesc unconnectedDesc = desc;
  std::vector<PlotSeries> unconnected = series;
  unconnected[0].connect = false;
  const auto bare = bench::renderPlot(unconnectedDesc, unconnected);
  EXPECT_FALSE(colourNear(bare, midX, midY, 1, green));
}

TEST(RenderPlot, EmptyInputDrawsAxesAndANote) {
  const PlotDesc desc = smallDesc();
  const auto image = bench::renderPlot(desc, {});
  ASSERT_EQ(image.width, desc.width);
  ASSERT_EQ(image.height, desc.height);
  const PlotLayout layout = bench::layoutPlot(desc, {});
  EXPECT_FALSE(layout.hasLegend);
  const int midY = (layout.frameTopPx + layout.frameBottomPx) / 2;
  const int midX = (layout.frameLeftPx + layout.frameRightPx) / 2;
  EXPECT_LT(int(pixelAt(image, layout.frameLeftPx, midY)[0]), 128);  // the frame
  // "no data" in grey at the centre of the frame.
  int notePixels = 0;
  for (int y = midY - 10; y <= midY + 10; ++y) {
    for (int x = midX - 40; x <= midX + 40; ++x) {
      if (sameColour(pixelAt(image, x, y), {120, 120, 120}, 40)) ++notePixels;
    }
  }
  EXPECT_GT(notePixels, 20);
}

TEST(RenderPlot, NonFiniteAndNonPositiveValuesAreSkipped) {
  const PlotDesc desc = smallDesc();
  const Rgb orange{230, 159, 0};
  const std::vector<PlotSeries> series{
      {"mixed",
       orange,
       {{kNaN, 1.0, "nan"},
        {kInf, 2.0, ""},
        {-1.0, 3.0, ""},
        {0.0, 4.0, ""},
        {10.0, kNaN, ""},
        {10.0, 20.0, "ok"},
        {100.0, 30.0, ""}},
       true},
      {"only nan", {0, 0, 0}, {{kNaN, kNaN, "x"}}},
  };
  const PlotLayout layout = bench::layoutPlot(desc, series);
  EXPECT_GT(layout.xAxis.min, 1.0);  // the fit used 10 and 100 only
  EXPECT_LT(layout.yAxis.min, 20.0);
  EXPECT_GT(layout.yAxis.max, 30.0);
  const auto image = bench::renderPlot(desc, series);
  EXPECT_TRUE(colourNear(image, layout.pixelX(10.0), layout.pixelY(20.0), 1, orange));
  EXPECT_TRUE(colourNear(image, layout.pixelX(100.0), layout.pixelY(30.0), 1, orange));

  const auto allNaN = bench::renderPlot(desc, {series[1]});
  EXPECT_EQ(allNaN.pixels.size(), std::size_t{4} * desc.width * desc.height);
}

TEST(RenderPlot, TitleDrawsDarkPixelsAboveTheFrame) {
  PlotDesc titled = smallDesc();
  PlotDesc untitled = titled;
  untitled.title.clear();
  const std::vector<PlotSeries> series{{"a", {0, 114, 178}, {{3.0, 30.0, ""}}}};
  const PlotLayout titledLayout = bench::layoutPlot(titled, series);
  const PlotLayout untitledLayout = bench::layoutPlot(untitled, series);
  EXPECT_GT(titledLayout.frameTopPx, untitledLayout.frameTopPx + 20);
  // Rows above the highest tick label (which may reach half a line above the frame).
  const int titledBandBottom = titledLayout.frameTopPx - 8;
  const int untitledBandBottom = untitledLayout.frameTopPx - 8;
  EXPECT_GT(
      countDarkPixels(bench::renderPlot(titled, series), 0, 0, int(titled.width), titledBandBottom),
      150);
  EXPECT_EQ(countDarkPixels(bench::renderPlot(untitled, series), 0, 0, int(untitled.width),
                            untitledBandBottom),
            0);
}

TEST(RenderPlot, AxisTitlesAndTickLabelsDrawText) {
  PlotDesc desc = smallDesc();
  const std::vector<PlotSeries> series{{"a", {0, 114, 178}, {{3.0, 30.0, ""}, {300.0, 50.0, ""}}}};
  const PlotLayout layout = bench::layoutPlot(desc, series);
  const auto image = bench::renderPlot(desc, series);
  // Below the frame (tick labels and the x title) and left of it (tick labels, y title).
  EXPECT_GT(countDarkPixels(image, layout.frameLeftPx, layout.frameBottomPx + 8,
                            layout.frameRightPx, int(desc.height)),
            100);
  EXPECT_GT(
      countDarkPixels(image, 0, layout.frameTopPx, layout.frameLeftPx - 8, layout.frameBottomPx),
      100);
}

TEST(RenderPlot, TinyAndZeroSizedImagesDoNotCrash) {
  const std::vector<PlotSeries> series{{"a", {0, 114, 178}, {{3.0, 30.0, "label"}}, true, true}};
  for (const auto& [width, height] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {0, 0}, {1, 1}, {0, 300}, {30, 20}, {120, 80}, {4000, 60}}) {
    PlotDesc desc = smallDesc();
    desc.width = width;
    desc.height = height;
    const auto image = bench::renderPlot(desc, series);
    EXPECT_EQ(image.width, width);
    EXPECT_EQ(image.height, height);
    EXPECT_EQ(image.pixels.size(), std::size_t{4} * width * height);
  }
}

// The chart the accuracy-versus-cost benchmark draws: three knob sweeps and five presets. It
// goes through writePng and back, and is left in the test temp folder to look at.
TEST(RenderPlot, BenchmarkChartRoundTripsThroughPng) {
  PlotDesc desc;
  desc.title = "Cloud accuracy versus cost (fake data)";
  desc.xLabel = "GPU time per frame (ms, log scale)";
  desc.yLabel = "PSNR against the reference (dB)";
  const std::vector<PlotSeries> series{
      {"view step (m): 400 .. 25",
       {0, 114, 178},
       {{2.0, 21.0, ""},
        {4.5, 27.5, ""},
        {11.0, 33.0, ""},
        {30.0, 39.0, ""},
        {95.0, 44.5, ""},
        {320.0, 48.0, ""}},
       true},
      {"light steps: 1 .. 32",
       {230, 159, 0},
       {{6.0, 24.0, ""}, {9.0, 31.0, ""}, {16.0, 37.5, ""}, {31.0, 41.0, ""}, {62.0, 42.5, ""}},
       true},
      {"max view steps: 32 .. 1024",
       {0, 158, 115},
       {{3.0, 22.5, ""},
        {7.0, 30.0, ""},
        {20.0, 40.0, ""},
        {70.0, 47.0, ""},
        {260.0, 52.0, ""},
        {900.0, 55.0, ""}},
       true},
      {"quality presets",
       {213, 94, 0},
       {{4.0, 31.0, "Low"},
        {12.0, 38.5, "Medium"},
        {40.0, 45.5, "High"},
        {150.0, 51.0, "Ultra"},
        {3000.0, 60.0, "Reference"}},
       false,
       true},
  };
  const auto image = bench::renderPlot(desc, series);
  const PlotLayout layout = bench::layoutPlot(desc, series);
  for (const PlotSeries& s : series) {
    for (const PlotPoint& p : s.points) {
      EXPECT_TRUE(colourNear(image, layout.pixelX(p.x), layout.pixelY(p.y), 1, s.rgb))
          << s.name << " at " << p.x << " ms";
    }
  }

  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "plot_example.png";
  engine::assets::writePng(path, image);
  const engine::assets::ImageRgba32f readBack = engine::assets::readImage(path);
  ASSERT_EQ(readBack.width, image.width);
  ASSERT_EQ(readBack.height, image.height);
  for (const auto& [x, y] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {0, 0}, {550, 360}, {std::uint32_t(layout.frameLeftPx), 300}}) {
    const Rgb expected = pixelAt(image, int(x), int(y));
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(readBack.at(x, y)[c] * 255.0f, float(expected[c]), 0.5f) << x << ", " << y;
    }
  }
  std::printf("chart written to %s\n", path.c_str());
}

}  // namespace
