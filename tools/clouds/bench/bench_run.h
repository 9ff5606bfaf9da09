#pragma once
// Running the benchmark: every configuration has its own module instance (its own temporal
// history), and frames are interleaved across configurations (one frame of each in turn), so
// drift of the machine's speed affects all of them alike. Times are the module's GPU time per
// frame from timestamp queries; errors are against the Reference mode of the same view,
// averaged over frames whose rays move inside their pixels (converged and supersampled).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench_setup.h"
#include "bench_shadow.h"
#include "bench_voxel.h"
#include "engine/gfx/device.h"

namespace bench {

struct RunOptions {
  VkExtent2D extent{640, 360};
  std::uint32_t convergeFrames = 32;  // static views: frames before timing (16 refresh all)
  // Static views, configurations with temporal upsampling: frames before timing (at High's
  // 1-in-16 refresh and half-resolution trace, 64 give every output pixel an own sample).
  std::uint32_t upsampledConvergeFrames = 128;
  std::uint32_t timedFrames = 9;        // static views: timed frames per configuration
  std::uint32_t referenceFrames = 16;   // frames averaged into each Reference image
  std::uint32_t flyFrames = 48;         // frames of the fly-through
  std::uint32_t flyReferenceEvery = 8;  // reference (and error) every n-th fly-through frame
  std::uint32_t flyWarmUpFrames = 16;   // no error measured before this frame of the path
  // When not empty, only these views ("fly-through" included) and configurations (by name, as
  // in the tables) run: for looking into one case without the whole quarter hour.
  std::vector<std::string> onlyViews;
  std::vector<std::string> onlyConfigs;
  // A governed flight's frame series (sample_game --frame-series), summarised in the targets
  // table when given.
  std::filesystem::path governorSeries;
};

// One configuration on one view (or on the fly-through, view "fly-through").
struct Measurement {
  std::string config;
  std::string view;
  double medianMs = 0.0;  // GPU time per frame: median of the timed frames
  double minMs = 0.0;
  double maxMs = 0.0;
  double psnr = 0.0;     // dB against the Reference, tonemapped; mean over frames for the path
  double minPsnr = 0.0;  // lowest of the frames measured (equal to psnr for static views)
  double meanAbs = 0.0;  // mean absolute error per channel (tonemapped, [0, 1])
  double maxAbs = 0.0;   // largest absolute error of any channel
  double viewSamplesPerRay = 0.0;  // work counters, per marched pixel
  double lightSamplesPerRay = 0.0;
  double earlyExitFraction = 0.0;
  double raysPerFrame = 0.0;
  std::map<std::string, double> passMs;  // median per pass
  double memoryMiB = 0.0;                // the module's GPU memory (Context::memoryUsage)
};

// How High converges on a static view: PSNR against the Reference after so many frames.
struct ConvergencePoint {
  std::uint32_t frames = 0;
  double psnr = 0.0;
};

struct ReferenceMeasurement {
  std::string view;
  double medianMs = 0.0;         // one Reference frame
  double singleFramePsnr = 0.0;  // one Reference frame against the averaged Reference
};

struct BenchResults {
  RunOptions options;
  std::vector<BenchConfig> configs;
  std::vector<std::string> views;  // static views, then "fly-through"
  std::vector<Measurement> measurements;
  std::vector<ReferenceMeasurement> references;
  std::map<std::string, std::vector<ConvergencePoint>> highConvergence;  // per static view
  ShadowResults shadows;  // the cloud shadow map's part (bench_shadow.h)
  VoxelResults voxels;    // hero clouds' optimisation ladder (bench_voxel.h)
  std::string device;
  double seconds = 0.0;  // wall time of the whole run

  const Measurement* find(const std::string& config, const std::string& view) const;
};

// Measurements that cannot be right: a non-finite or negative time, error or work counter, or
// no traced ray where there are clouds. One line per problem; empty when all is plausible.
std::vector<std::string> implausibleMeasurements(const BenchResults& results);

// Runs everything; `progress` gets one line per step.
BenchResults runBenchmark(engine::gfx::Device& device, const RunOptions& options,
                          void (*progress)(const std::string& line));

}  // namespace bench
