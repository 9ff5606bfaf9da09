#pragma once
// The preset ladder's conditions (issue 53): each rung a real step above the one below it,
// and the frame-time governor's flight that climbs it, summarised from the sample's frame
// series (sample_game --frame-series FILE) for the benchmark's targets table.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_run.h"

namespace bench {

// A rung costs at most this fraction of the next one's time (static mean)...
inline constexpr double kLadderCostRatio = 0.6;
// ...and the next one is at least this much more accurate (pooled static PSNR, dB).
inline constexpr double kLadderGainDb = 2.0;

struct LadderStep {
  std::string lower, upper;  // preset names, cheaper first
  double costRatio = 0.0;    // lower's static mean ms over upper's
  double gainDb = 0.0;       // upper's pooled PSNR minus lower's
  bool cheapEnough() const { return costRatio <= kLadderCostRatio; }
  bool gainsEnough() const { return gainDb >= kLadderGainDb; }
};

// Each pair of neighbouring presets this run measured, cheapest first.
std::vector<LadderStep> ladderSteps(const BenchResults& results);

// A governed flight: the frames after the governor's first judgement.
struct GovernedFlight {
  double targetMs = 0.0;                 // what the frames were governed to
  std::size_t frames = 0;                // frames judged (the warm-up left out)
  double seconds = 0.0;                  // how long they took
  double medianWallMs = 0.0;             // wall time a frame, median
  double fractionOverTenPercent = 0.0;   // of frames more than 10% over the target
  std::vector<double> tenSecondMedians;  // wall time a frame, median of each 10 s
  std::size_t presetChanges = 0;
  std::size_t shortestGapFrames = 0;  // between two changes (0 with fewer than two)
  std::vector<std::pair<std::string, std::size_t>> framesPerPreset;  // in order of first use
};

// Reads a frame series CSV (frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms and,
// in series written since, clouds_history).
// Throws engine::Error naming the file, and the line where one is wrong, when it cannot be
// read, has another header, or no governed frame.
GovernedFlight readGovernedFlight(const std::filesystem::path& file);

}  // namespace bench
