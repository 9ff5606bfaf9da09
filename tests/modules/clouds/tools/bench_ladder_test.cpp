// The benchmark's ladder conditions and the governed flight's summary (bench_ladder.h): a rung
// is a real step only when it costs at most 0.6x the next one's time and the next one is at
// least 2 dB more accurate; the flight is read from the sample's frame series, its warm-up
// left out, and a malformed series is refused with the file and line named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bench_ladder.h"
#include "engine/core/error.h"

namespace {

bench::BenchConfig preset(const char* name, clouds::Quality quality) {
  bench::BenchConfig c;
  c.name = name;
  c.preset = true;
  c.quality = quality;
  return c;
}

void measure(bench::BenchResults& results, const char* config, double ms, double psnr) {
  bench::Measurement m;
  m.config = config;
  m.view = "overcast";
  m.medianMs = ms;
  m.psnr = m.minPsnr = psnr;
  results.measurements.push_back(m);
}

TEST(BenchLadder, EachRungMustCostAtMostSixTenthsAndGainTwoDecibels) {
  bench::BenchResults results;
  results.views = {"overcast"};
  // Listed out of order: the ladder goes by the presets' order, not the run's.
  results.configs = {preset("High", clouds::Quality::High), preset("Low", clouds::Quality::Low),
                     preset("Medium", clouds::Quality::Medium)};
  measure(results, "Low", 3.0, 31.0);
  measure(results, "Medium", 5.5, 33.5);  // 0.55x of High, but Low is 0.545x of it: fine
  measure(results, "High", 10.0, 35.0);   // only 1.5 dB above Medium
  const std::vector<bench::LadderStep> steps = bench::ladderSteps(results);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].lower, "Low");
  EXPECT_EQ(steps[0].upper, "Medium");
  EXPECT_NEAR(steps[0].costRatio, 3.0 / 5.5, 1e-12);
  EXPECT_TRUE(steps[0].cheapEnough());
  EXPECT_TRUE(steps[0].gainsEnough());
  EXPECT_EQ(steps[1].upper, "High");
  EXPECT_TRUE(steps[1].cheapEnough());
  EXPECT_FALSE(steps[1].gainsEnough());

  results.measurements[0].medianMs = 3.5;  // Low at 0.64x Medium: no longer a step
  EXPECT_FALSE(bench::ladderSteps(results)[0].cheapEnough());
}

// In a folder of this test's own (the system's temporary folder is shared with real series).
std::filesystem::path writeSeries(const std::string& name, const std::string& text) {
  const std::filesystem::path dir =
      std::filesystem::path(testing::TempDir()) / "clouds_bench_ladder_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

TEST(BenchLadder, AGovernedFlightIsSummarisedAfterItsWarmUp) {
  std::string csv = "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms\n";
  csv += "0,0.0,500.0,0.0,Medium,starting,33.3\n";  // warm-up: left out
  // 26 s at 20 fps: Medium at 30 ms, High from 12 s at 40 ms (over the target by 20%), back
  // to Medium from 15 s.
  for (int i = 1; i <= 520; ++i) {
    const double seconds = 0.05 * i;
    const bool high = i >= 240 && i < 300;
    csv += std::to_string(i) + "," + std::to_string(seconds) + "," + (high ? "40.0" : "30.0") +
           ",20.0," + (high ? "High" : "Medium") + ",holding,33.3\n";
  }
  const bench::GovernedFlight flight = bench::readGovernedFlight(writeSeries("governed.csv", csv));
  EXPECT_EQ(flight.frames, 520u);
  EXPECT_DOUBLE_EQ(flight.targetMs, 33.3);
  EXPECT_DOUBLE_EQ(flight.medianWallMs, 30.0);
  EXPECT_NEAR(flight.fractionOverTenPercent, 60.0 / 520.0, 1e-9);
  EXPECT_EQ(flight.presetChanges, 2u);
  EXPECT_EQ(flight.shortestGapFrames, 60u);
  ASSERT_EQ(flight.framesPerPreset.size(), 2u);
  EXPECT_EQ(flight.framesPerPreset[0].first, "Medium");
  EXPECT_EQ(flight.framesPerPreset[0].second, 460u);
  EXPECT_EQ(flight.framesPerPreset[1].second, 60u);
  // 0.05 to 26 s: two full 10 s stretches and the last 6 s.
  ASSERT_EQ(flight.tenSecondMedians.size(), 3u);
  EXPECT_DOUBLE_EQ(flight.tenSecondMedians[1], 30.0);
}

// The sample's series since the clouds' history became a column read the same (older ones have
// none), and so do those with the exposure after it; a header of something else is refused.
TEST(BenchLadder, ASeriesWithTheCloudsHistoryReadsTheSame) {
  std::string csv = "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms,clouds_history\n";
  for (int i = 1; i <= 40; ++i) {
    csv += std::to_string(i) + "," + std::to_string(0.05 * i) +
           ",30.0,20.0,Medium,holding,33.3,reprojected\n";
  }
  const bench::GovernedFlight flight = bench::readGovernedFlight(writeSeries("history.csv", csv));
  EXPECT_EQ(flight.frames, 40u);
  EXPECT_DOUBLE_EQ(flight.targetMs, 33.3);
  const std::string shortRow =
      "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms,"
      "clouds_history\n0,0.0,30.0,1,Low,holding,33\n";
  try {
    bench::readGovernedFlight(writeSeries("history_short.csv", shortRow));
    ADD_FAILURE() << "a row without the history column was read";
  } catch (const engine::Error& e) {
    EXPECT_NE(std::string(e.what()).find("history_short.csv:2: 8 fields"), std::string::npos)
        << e.what();
  }
  std::string withExposure =
      "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms,clouds_history,ev100,"
      "metered_ev100\n";
  for (int i = 1; i <= 40; ++i) {
    withExposure += std::to_string(i) + "," + std::to_string(0.05 * i) +
                    ",30.0,20.0,Medium,holding,33.3,reprojected,14.1,14.3\n";
  }
  EXPECT_EQ(bench::readGovernedFlight(writeSeries("exposure.csv", withExposure)).frames, 40u);
  for (const char* header : {"frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_msx\n",
                             "wall_ms,frame,seconds\n"}) {
    try {
      bench::readGovernedFlight(writeSeries("other_header.csv", header));
      ADD_FAILURE() << "read a series whose header is " << header;
    } catch (const engine::Error& e) {
      EXPECT_NE(std::string(e.what()).find("other_header.csv:1: the header does not start with"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(BenchLadder, AMalformedSeriesIsRefusedNamingFileAndLine) {
  const auto message = [](const std::filesystem::path& file) {
    try {
      bench::readGovernedFlight(file);
    } catch (const engine::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string header = "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms\n";
  EXPECT_NE(message(writeSeries("old.csv", "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor\n"))
                .find("old.csv:1: the header"),
            std::string::npos);
  EXPECT_NE(
      message(writeSeries("short.csv", header + "0,0.0,30.0\n")).find("short.csv:2: 7 fields"),
      std::string::npos);
  EXPECT_NE(message(writeSeries("nan.csv", header + "0,0.0,fast,1,Low,holding,33\n"))
                .find("nan.csv:2: wall_ms 'fast' is not a number"),
            std::string::npos);
  EXPECT_NE(message(writeSeries("ungoverned.csv", header + "0,0.0,30.0,1,Low,off,0\n"))
                .find("no governed frame"),
            std::string::npos);
  EXPECT_NE(message("/nonexistent/series.csv").find("cannot read"), std::string::npos);
}

}  // namespace
