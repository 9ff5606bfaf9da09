// atmosphere_bench: what the atmosphere's accuracy costs. Renders five views (noon, looking down
// through haze, sunset, twilight, from 12 km) at each quality preset and along one-knob sweeps
// around Medium, times the module on the GPU (pass timestamps; configurations interleaved round
// by round) and scores each image against the converged Reference preset, then writes
// results.md, results.csv and plots.json into the output folder and draws plot.png from it with
// tools/plot_benchmark.py.
// Usage: atmosphere_bench OUT_DIR [--width 640 --height 360] [--rounds 5] [--quick]
//                         [--validation]
// A benchmark, not a test: it exits non-zero only when it cannot measure (an error, a Vulkan
// validation message under --validation, a time or error that is not a number).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "bench_cases.h"
#include "engine/assets/image_metrics.h"
#include "engine/core/error.h"
#include "engine/gfx/instance.h"

namespace {

using namespace atmosphere;

struct Measurement {
  std::vector<double> frameMs;   // per timed frame: dispatch()'s per-frame passes
  std::vector<double> renderMs;  // per timed frame: render() over the host's colour
  std::vector<double> lutMs;     // per rebuild: transmittance + multiple scattering
  double psnr = 0.0;
};

struct Options {
  VkExtent2D extent{640, 360};
  std::uint32_t rounds = 5;  // interleaved rounds; each times every configuration
  std::uint32_t framesPerRound = 3;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::ofstream openOrThrow(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw engine::Error("atmosphere_bench: cannot write " + file.string());
  return out;
}

// One view's frame: dispatch()'s per-frame passes (sky view, froxels, sky map), render(), and
// the parameter-only LUTs when they ran (that frame is not a per-frame sample).
void addTimings(const std::vector<PassTiming>& timings, Measurement& m) {
  double frame = 0.0, render = 0.0, luts = 0.0;
  for (const PassTiming& t : timings) {
    const std::string name = t.name;
    if (name == "transmittance" || name == "multiple scattering") {
      luts += t.milliseconds;
    } else if (name == "render") {
      render += t.milliseconds;
    } else {
      frame += t.milliseconds;
    }
  }
  if (luts > 0.0) {
    m.lutMs.push_back(luts);
    return;
  }
  m.frameMs.push_back(frame);
  m.renderMs.push_back(render);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  CLI::App cli{
      "atmosphere_bench: accuracy versus cost of the atmosphere module's presets and knobs"};
  std::string outDir;
  cli.add_option("out_dir", outDir, "Folder for results.md, results.csv and the plot")->required();
  Options options;
  cli.add_option("--width", options.extent.width, "Render width")->check(CLI::Range(16u, 4096u));
  cli.add_option("--height", options.extent.height, "Render height")->check(CLI::Range(16u, 4096u));
  cli.add_option("--rounds", options.rounds, "Interleaved timing rounds")
      ->check(CLI::Range(1u, 100u));
  bool quick = false;
  cli.add_flag("--quick", quick, "320x180, two rounds");
  bool validation = false;
  cli.add_flag("--validation", validation, "Vulkan validation layers (slower; for debugging)");
  CLI11_PARSE(cli, argc, argv);
  if (quick) {
    options.extent = {320, 180};
    options.rounds = 2;
  }

  try {
    const auto start = std::chrono::steady_clock::now();
    const std::filesystem::path out(outDir);
    std::filesystem::create_directories(out);
    engine::gfx::InstanceDesc instanceDesc;
    instanceDesc.appName = "atmosphere_bench";
    instanceDesc.validation = validation;
    engine::gfx::Instance instance(instanceDesc);
    engine::gfx::Device device(instance, engine::gfx::DeviceDesc{});
    tools::AtmosphereHarness harness(device, options.extent, /*passTimings=*/true);

    const std::vector<bench::View> views = bench::benchmarkViews();
    const std::vector<bench::Config> configs = bench::benchmarkConfigs();
    const Settings reference = settingsFor(Quality::Reference);
    // Two airs a hair apart: switching between them rebuilds the parameter-only LUTs, whose
    // cost is measured on that frame (a frame of the time of day never pays it).
    Parameters airs[2];
    airs[1].miePhaseG = airs[0].miePhaseG + 1e-4f;

    std::map<std::pair<std::size_t, std::size_t>, Measurement> results;  // (config, view)
    std::vector<std::uint64_t> memory(configs.size(), 0);
    for (std::size_t v = 0; v < views.size(); ++v) {
      const tools::SkyView& sky = views[v].sky;
      const tools::FloatImage truth = harness.render(sky, airs[0], reference, options.extent);
      for (std::size_t c = 0; c < configs.size(); ++c) {
        const tools::FloatImage image =
            harness.render(sky, airs[0], configs[c].settings, options.extent);
        results[{c, v}].psnr = bench::displayPsnr(image, truth);
        memory[c] = harness.context().memoryUsage().totalBytes();
      }
      for (std::uint32_t round = 0; round < options.rounds; ++round) {
        for (std::size_t c = 0; c < configs.size(); ++c) {
          Measurement& m = results[{c, v}];
          const Parameters& air = airs[(round + c) % 2];
          harness.render(sky, air, configs[c].settings, options.extent);  // new settings, LUTs
          addTimings(harness.lastPassTimings(), m);
          for (std::uint32_t f = 0; f < options.framesPerRound; ++f) {
            harness.render(sky, air, configs[c].settings, options.extent);
            addTimings(harness.lastPassTimings(), m);
          }
        }
      }
      std::printf("%s: done\n", views[v].name.c_str());
    }

    // Per configuration: the mean of the views' median frame times, the PSNR pooled from the
    // views' mean squared errors, the worst view.
    struct Row {
      double frameMs = 0.0, renderMs = 0.0, lutMs = 0.0, psnr = 0.0, worst = 1e9;
    };
    std::vector<Row> rows(configs.size());
    for (std::size_t c = 0; c < configs.size(); ++c) {
      double ms = 0.0, renderMs = 0.0, mse = 0.0;
      std::vector<double> luts;
      for (std::size_t v = 0; v < views.size(); ++v) {
        const Measurement& m = results[{c, v}];
        ms += median(m.frameMs);
        renderMs += median(m.renderMs);
        mse += engine::assets::meanSquaredFromPsnr(m.psnr);
        luts.insert(luts.end(), m.lutMs.begin(), m.lutMs.end());
        rows[c].worst = std::min(rows[c].worst, m.psnr);
      }
      rows[c].frameMs = ms / double(views.size());
      rows[c].renderMs = renderMs / double(views.size());
      rows[c].psnr = engine::assets::psnrFromMeanSquared(mse / double(views.size()));
      rows[c].lutMs = median(luts);
    }

    for (std::size_t c = 0; c < configs.size(); ++c) {
      if (!(rows[c].frameMs > 0.0) || !std::isfinite(rows[c].frameMs) || std::isnan(rows[c].psnr)) {
        std::fprintf(stderr, "atmosphere_bench: implausible measurement of %s\n",
                     configs[c].name.c_str());
        return 2;
      }
    }

    std::ofstream csv = openOrThrow(out / "results.csv");
    csv << "config,sweep,preset,view,dispatch_ms_median,render_ms_median,lut_ms_median,psnr_db\n";
    for (std::size_t c = 0; c < configs.size(); ++c) {
      for (std::size_t v = 0; v < views.size(); ++v) {
        const Measurement& m = results[{c, v}];
        csv << '"' << configs[c].name << "\",\"" << configs[c].sweep << "\","
            << (configs[c].preset ? 1 : 0) << ",\"" << views[v].name << "\"," << median(m.frameMs)
            << ',' << median(m.renderMs) << ',' << median(m.lutMs) << ',' << m.psnr << '\n';
      }
    }

    std::ofstream md = openOrThrow(out / "results.md");
    md << "# Atmosphere: accuracy against cost\n\n"
       << "Generated by `atmosphere_bench` at " << options.extent.width << "x"
       << options.extent.height << " on " << device.name() << ". Time: GPU timestamps of "
       << "dispatch()'s per-frame passes (sky-view LUT, froxels, sky map), the median of "
       << options.rounds << " x " << options.framesPerRound
       << " frames per view, configurations interleaved round by "
       << "round, averaged over the views; render() (the compute pass that draws the sky and hazes "
       << "the host's colour at full resolution; no knob here changes it) separately. LUT "
       << "rebuild: the transmittance and multiple-"
       << "scattering LUTs, recorded only when the air's parameters change (median of the "
       << "rebuilds). Error: PSNR against the Reference preset after exposing the reference's "
       << "mean luminance to 0.18 and x/(1+x) per channel; pooled over the views, and the "
       << "worst view.\n\n"
       << "| configuration | dispatch ms | render() ms | LUT rebuild ms | "
       << "PSNR pooled / worst (dB) | GPU memory (KiB) |\n|---|---|---|---|---|---|\n";
    char line[256];
    for (std::size_t c = 0; c < configs.size(); ++c) {
      std::snprintf(line, sizeof(line), "| %s%s%s | %.2f | %.2f | %.2f | %.1f / %.1f | %llu |\n",
                    configs[c].preset ? "**" : "", configs[c].name.c_str(),
                    configs[c].preset ? "**" : "", rows[c].frameMs, rows[c].renderMs, rows[c].lutMs,
                    rows[c].psnr, rows[c].worst, static_cast<unsigned long long>(memory[c] / 1024));
      md << line;
    }
    md << "\n| view | ";
    for (std::size_t c = 0; c < 3; ++c) md << configs[c].name << " dB | ";
    md << "\n|---|---|---|---|\n";
    for (std::size_t v = 0; v < views.size(); ++v) {
      md << "| " << views[v].name << " | ";
      for (std::size_t c = 0; c < 3; ++c) {
        std::snprintf(line, sizeof(line), "%.1f | ", results[{c, v}].psnr);
        md << line;
      }
      md << '\n';
    }

    nlohmann::json series = nlohmann::json::array();
    std::map<std::string, nlohmann::json> sweeps;
    const std::size_t mediumIndex = 1;
    const auto point = [&](std::size_t c, const std::string& label) {
      return nlohmann::json{
          {"gpu_ms", rows[c].frameMs}, {"psnr_db", rows[c].psnr}, {"label", label}};
    };
    std::vector<std::string> order;
    for (std::size_t c = 0; c < configs.size(); ++c) {
      if (configs[c].preset) continue;
      if (!sweeps.count(configs[c].sweep)) {
        sweeps[configs[c].sweep] = nlohmann::json::array({point(mediumIndex, "")});
        order.push_back(configs[c].sweep);
      }
      sweeps[configs[c].sweep].push_back(
          point(c, configs[c].name.substr(configs[c].sweep.size() + 1)));
    }
    for (const std::string& name : order) {
      std::sort(sweeps[name].begin(), sweeps[name].end(),
                [](const nlohmann::json& a, const nlohmann::json& b) {
                  return a["gpu_ms"].get<double>() < b["gpu_ms"].get<double>();
                });
      series.push_back({{"name", name}, {"presets", false}, {"points", sweeps[name]}});
    }
    nlohmann::json presets = nlohmann::json::array();
    for (std::size_t c = 0; c < configs.size(); ++c) {
      if (configs[c].preset) presets.push_back(point(c, configs[c].name));
    }
    series.push_back({{"name", "quality presets"}, {"presets", true}, {"points", presets}});
    const nlohmann::json plots = {
        {"plots",
         {{{"file", "plot.png"},
           {"title", "Atmosphere: error against the Reference and GPU time per frame"},
           {"x_label", "GPU time per frame (ms, dispatch()'s per-frame passes, log scale)"},
           {"y_label", "PSNR against the Reference (dB, pooled over the views)"},
           {"series", series}}}}};
    openOrThrow(out / "plots.json") << plots.dump(2) << '\n';

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s/{results.md, results.csv, plots.json} in %.0f s\n",
                std::filesystem::absolute(out).string().c_str(), seconds);
    const std::string draw = std::string("\"") + ATMOSPHERE_PLOT_PYTHON + "\" \"" +
                             ATMOSPHERE_PLOT_SCRIPT + "\" \"" + (out / "plots.json").string() +
                             "\"";
    if (std::system(draw.c_str()) != 0) {
      std::fprintf(stderr, "atmosphere_bench: the plot was not drawn (see above)\n");
      return 4;
    }
    if (validation && instance.validationMessageCount() > 0) {
      std::fprintf(stderr, "%u Vulkan validation message(s)\n",
                   unsigned(instance.validationMessageCount()));
      return 3;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "atmosphere_bench: %s\n", e.what());
    return 1;
  }
}
