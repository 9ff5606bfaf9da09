#pragma once
// The benchmark's outputs: a CSV of every measurement, a Markdown report (targets, presets,
// knob sweeps, per-view detail) and the data of two plots of error against time (static
// views, fly-through) that plot_benchmark.py draws.
#include <filesystem>
#include <string>
#include <vector>

#include "bench_run.h"

namespace bench {

// A configuration over a set of views: time is the mean of the per-view medians; PSNR is
// pooled from the mean squared error over the views that have clouds (the clear sky matches
// exactly in every configuration and would only flatter the figure); min PSNR is the worst.
struct Aggregate {
  double milliseconds = 0.0;
  double psnr = 0.0;
  double minPsnr = 0.0;
};
Aggregate aggregateStatic(const BenchResults& results, const std::string& config);
Aggregate aggregateFlyThrough(const BenchResults& results, const std::string& config);

// The timing noise of a comparison of two static means in this run, as a fraction of High's:
// twice the standard error of the mean difference between High's two timings (kHighTimedAgain)
// view by view, so two timings of the same work land within it about 19 times in 20. 0 when
// the run timed High once, or on fewer than two static views.
double timingNoise(const BenchResults& results);

// Whether the presets are on the accuracy-versus-cost front: the configurations (presets and
// one-knob sweeps, not the second timing of High) more accurate than a preset over the static
// views (pooled PSNR) and cheaper, as "Preset by configuration (its ms, dB against the
// preset's)". Cheaper by more than the timing noise: `beaten`; by less, `withinNoise` (this
// run cannot tell whether they are cheaper).
struct Front {
  double timingNoise = 0.0;
  std::vector<std::string> beaten;
  std::vector<std::string> withinNoise;
};
Front checkFront(const BenchResults& results);

void writeCsv(const std::filesystem::path& file, const BenchResults& results);
void writeMarkdown(const std::filesystem::path& file, const BenchResults& results);
// plots.json: for each plot its file name, title, axis labels and series (one per knob sweep,
// one for the presets) of points (GPU ms, PSNR dB, label).
void writePlotData(const std::filesystem::path& file, const BenchResults& results);

}  // namespace bench
