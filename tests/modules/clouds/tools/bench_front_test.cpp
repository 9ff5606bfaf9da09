// The benchmark's front check (bench_report.h): a preset is beaten by a configuration more
// accurate than it and cheaper by more than the run's timing noise, which is twice the standard
// error of the mean difference between High's two timings over the static views.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench_report.h"

namespace {

using bench::BenchConfig;
using bench::BenchResults;
using bench::Measurement;

const char* const kViews[] = {"overcast", "sunset", "above the layer"};

BenchConfig config(const std::string& name, bool preset, bool timingRepeat = false) {
  BenchConfig c;
  c.name = name;
  c.preset = preset;
  c.timingRepeat = timingRepeat;
  return c;
}

// `config` on every view at `milliseconds[view]` and `psnr` dB.
void measure(BenchResults& results, const std::string& config, const double (&milliseconds)[3],
             double psnr) {
  for (int v = 0; v < 3; ++v) {
    Measurement m;
    m.config = config;
    m.view = kViews[v];
    m.medianMs = milliseconds[v];
    m.psnr = m.minPsnr = psnr;
    results.measurements.push_back(m);
  }
}

// High at 10 ms a view, timed again 0.1 ms above, 0.1 below and level: a standard error of
// 0.1 / sqrt(3) ms, a noise of 2 x 0.0577 / 10 = 1.15%.
BenchResults resultsWithHighTimedTwice() {
  BenchResults results;
  results.views = {kViews[0], kViews[1], kViews[2]};
  results.configs = {config("Low", true), config("Medium", true), config("High", true),
                     config("knob", false), config(bench::kHighTimedAgain, false, true)};
  measure(results, "High", {10.0, 10.0, 10.0}, 40.0);
  measure(results, bench::kHighTimedAgain, {10.1, 9.9, 10.0}, 40.0);
  measure(results, "Medium", {4.0, 4.0, 4.0}, 31.0);
  return results;
}

TEST(BenchFront, TheTimingNoiseIsTwiceTheStandardErrorOfHighsTwoTimings) {
  EXPECT_NEAR(bench::timingNoise(resultsWithHighTimedTwice()), 2.0 * 0.1 / std::sqrt(3.0) / 10.0,
              1e-9);
  BenchResults once = resultsWithHighTimedTwice();
  std::erase_if(once.measurements,
                [](const Measurement& m) { return m.config == bench::kHighTimedAgain; });
  EXPECT_EQ(bench::timingNoise(once), 0.0);
}

TEST(BenchFront, OnlyADifferenceBeyondTheNoiseBeatsAPreset) {
  BenchResults results = resultsWithHighTimedTwice();
  measure(results, "Low", {3.0, 3.0, 3.0}, 31.5);      // 25% cheaper than Medium, more accurate
  measure(results, "knob", {9.95, 9.95, 9.95}, 40.1);  // 0.5% cheaper than High: within
  const bench::Front front = bench::checkFront(results);
  ASSERT_EQ(front.beaten.size(), 1u);
  EXPECT_EQ(front.beaten[0].rfind("Medium by Low", 0), 0u) << front.beaten[0];
  ASSERT_EQ(front.withinNoise.size(), 1u);
  EXPECT_EQ(front.withinNoise[0].rfind("High by knob", 0), 0u) << front.withinNoise[0];

  // 2% cheaper is beyond the 1.15%.
  BenchResults clear = resultsWithHighTimedTwice();
  measure(clear, "Low", {3.0, 3.0, 3.0}, 31.5);
  measure(clear, "knob", {9.8, 9.8, 9.8}, 40.1);
  const bench::Front beyond = bench::checkFront(clear);
  EXPECT_EQ(beyond.beaten.size(), 2u);
  EXPECT_TRUE(beyond.withinNoise.empty());
}

TEST(BenchFront, HighsSecondTimingNeverBeatsAPreset) {
  BenchResults results = resultsWithHighTimedTwice();
  std::erase_if(results.measurements,
                [](const Measurement& m) { return m.config == bench::kHighTimedAgain; });
  measure(results, bench::kHighTimedAgain, {5.0, 5.0, 5.0}, 45.0);
  const bench::Front front = bench::checkFront(results);
  for (const std::string& item : front.beaten) {
    EXPECT_EQ(item.find(bench::kHighTimedAgain), std::string::npos) << item;
  }
}

}  // namespace
