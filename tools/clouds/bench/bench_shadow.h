#pragma once
// The cloud shadow map's accuracy against its cost, the benchmark's third part: every quality
// preset and one-knob sweeps of the map's own knobs around Medium (texels per side, samples
// along each ray, cascades, cascades remade per frame), on two views of broken cumulus (the
// sun 35 and 12 degrees up). Cost: the "shadow map" pass's GPU time per frame, the mean over a
// whole cycle of cascade turns after a cut (and the cut frame itself, which remakes them all).
// Error: the receivers' lookup (fxcontracts/cloud_shadow.h) at ground points out to 100 km against
// a 10 m march towards the sun through the same low-frequency clouds (the CPU reference), as a PSNR
// of the transmittance (peak 1) and a mean absolute difference.
#include <string>
#include <vector>

#include "bench_setup.h"
#include "engine/gfx/device.h"

namespace bench {

struct ShadowMeasurement {
  std::string config;
  std::string view;
  double meanMs = 0.0;  // per frame, over a full cycle of turns
  double cutMs = 0.0;   // the frame after a cut: every cascade at once
  double psnr = 0.0;    // transmittance at the ground points, peak 1
  double meanAbs = 0.0;
  double maxAbs = 0.0;
  double nearMeanAbs = 0.0;  // over the points within 10 km (the finest cascade's reach)
  double reachKm = 0.0;      // where the last cascade's full-strength shadows end
};

struct ShadowResults {
  std::vector<BenchConfig> configs;
  std::vector<std::string> views;
  std::vector<ShadowMeasurement> measurements;
  std::size_t points = 0;  // ground points per view

  const ShadowMeasurement* find(const std::string& config, const std::string& view) const;
};

// Low, Medium, High, Ultra, then the sweeps (shadow resolution, shadow steps, shadow cascades,
// cascades per frame), each through Medium.
std::vector<BenchConfig> shadowConfigs();
std::vector<Sweep> shadowSweeps(const std::vector<BenchConfig>& configs);

// `onlyViews`, `onlyConfigs`: when not empty, only these views and configurations (by name, as
// in shadowConfigs()) run, as the rest of the benchmark's --view and --config; a selection
// that leaves no configuration leaves the section empty.
ShadowResults runShadowBenchmark(engine::gfx::Device& device,
                                 const std::vector<std::string>& onlyViews,
                                 const std::vector<std::string>& onlyConfigs,
                                 void (*progress)(const std::string& line));

}  // namespace bench
