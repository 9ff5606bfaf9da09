// clouds_bench: what accuracy costs. Renders the canonical views and a fly-through at each
// quality preset and along one-knob sweeps, times the module on the GPU (timestamps, median,
// interleaved) and measures the error against the converged Reference mode, then writes
// results.csv, results.md and plots.json into the output folder, then draws plot_static.png and
// plot_fly_through.png from plots.json with tools/plot_benchmark.py.
// Usage: clouds_bench OUT_DIR [--width 640 --height 360] [--quick] [--validation]
// A benchmark, not a test: it asserts nothing, and a full run takes about a quarter of an hour
// on the 2-core lavapipe machine (--quick: 320x180 and fewer frames, a few minutes).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "bench_report.h"
#include "bench_run.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gfx/instance.h"

int main(int argc, char** argv) {
  // Line-buffered so progress shows up promptly when stdout is a file (long runs under nohup).
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  CLI::App cli{"clouds_bench: accuracy versus cost of the clouds module's presets and knobs"};
  std::string outDir;
  cli.add_option("out_dir", outDir, "Folder for results.csv, results.md and the plots")->required();
  bench::RunOptions options;
  cli.add_option("--width", options.extent.width, "Render width")->check(CLI::Range(16u, 4096u));
  cli.add_option("--height", options.extent.height, "Render height")->check(CLI::Range(16u, 4096u));
  cli.add_option("--converge-frames", options.convergeFrames, "Static views: frames before timing")
      ->check(CLI::Range(0u, 1000u));
  cli.add_option("--upsampled-converge-frames", options.upsampledConvergeFrames,
                 "Static views: frames before timing with temporal upsampling (High)")
      ->check(CLI::Range(0u, 4000u));
  cli.add_option("--timed-frames", options.timedFrames, "Static views: timed frames")
      ->check(CLI::Range(1u, 1000u));
  cli.add_option("--reference-frames", options.referenceFrames, "Frames averaged per Reference")
      ->check(CLI::Range(1u, 256u));
  cli.add_option("--fly-frames", options.flyFrames, "Frames of the fly-through")
      ->check(CLI::Range(2u, 10000u));
  cli.add_option(
      "--view", options.onlyViews,
      "Run only this view (repeatable; names as in results.md, e.g. \"above the layer\", "
      "\"fly-through\")");
  cli.add_option("--config", options.onlyConfigs,
                 "Run only this configuration (repeatable; e.g. High, \"light steps 10\")");
  cli.add_option("--governor-series", options.governorSeries,
                 "A governed flight's frame series (sample_game --frame-series FILE): its summary "
                 "joins the targets")
      ->check(CLI::ExistingFile);
  bool quick = false;
  cli.add_flag("--quick", quick, "320x180, fewer frames: a few minutes instead of a quarter hour");
  bool validation = false;
  cli.add_flag("--validation", validation, "Vulkan validation layers (slower; for debugging)");
  CLI11_PARSE(cli, argc, argv);
  if (quick) {
    options.extent = {320, 180};
    options.convergeFrames = 20;
    options.upsampledConvergeFrames = 64;
    options.timedFrames = 5;
    options.referenceFrames = 4;
    options.flyFrames = 32;
  }
  options.flyWarmUpFrames = std::min(options.flyWarmUpFrames, options.flyFrames - 1);

  try {
    const std::filesystem::path out(outDir);
    std::filesystem::create_directories(out);
    engine::gfx::InstanceDesc instanceDesc;
    instanceDesc.appName = "clouds_bench";
    instanceDesc.validation = validation;
    engine::gfx::Instance instance(instanceDesc);
    engine::gfx::Device device(instance, engine::gfx::DeviceDesc{});
    const bench::BenchResults results = bench::runBenchmark(
        device, options, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
    bench::writeCsv(out / "results.csv", results);
    bench::writeMarkdown(out / "results.md", results);
    bench::writePlotData(out / "plots.json", results);
    std::printf("wrote %s/{results.csv, results.md, plots.json} in %.0f s\n",
                std::filesystem::absolute(out).string().c_str(), results.seconds);
    // The plots are drawn by matplotlib (Debian's python3-matplotlib) from plots.json.
    const std::string draw = std::string("\"") + CLOUDS_PLOT_PYTHON + "\" \"" + CLOUDS_PLOT_SCRIPT +
                             "\" \"" + (out / "plots.json").string() + "\"";
    if (std::system(draw.c_str()) != 0) {
      std::fprintf(stderr, "clouds_bench: drawing the plots failed (%s)\n", draw.c_str());
      return 4;
    }
    const std::vector<std::string> problems = bench::implausibleMeasurements(results);
    for (const std::string& problem : problems)
      std::fprintf(stderr, "implausible: %s\n", problem.c_str());
    if (!problems.empty()) return 2;
    if (validation && instance.validationMessageCount() > 0) {
      std::fprintf(stderr, "%u Vulkan validation message(s)\n",
                   unsigned(instance.validationMessageCount()));
      return 3;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clouds_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
