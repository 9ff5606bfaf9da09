#pragma once
// The benchmark's outputs: a CSV of every measurement, a Markdown report (targets, presets,
// knob sweeps, per-view detail) and the data of two plots of error against time (static
// views, fly-through) that plot_benchmark.py draws.
#include <filesystem>
#include <string>

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

void writeCsv(const std::filesystem::path& file, const BenchResults& results);
void writeMarkdown(const std::filesystem::path& file, const BenchResults& results);
// plots.json: for each plot its file name, title, axis labels and series (one per knob sweep,
// one for the presets) of points (GPU ms, PSNR dB, label).
void writePlotData(const std::filesystem::path& file, const BenchResults& results);

}  // namespace bench
