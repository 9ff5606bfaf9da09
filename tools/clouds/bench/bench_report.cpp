#include "bench_report.h"

#include "bench_ladder.h"
#include "bench_shadow_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>
#include "engine/assets/image_metrics.h"
#include "engine/core/error.h"

namespace bench {
namespace {

const std::string kFlyThrough = "fly-through";

std::string format(const char* spec, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), spec, value);
  return text;
}

using engine::assets::meanSquaredFromPsnr;
using engine::assets::psnrFromMeanSquared;

std::ofstream openOrThrow(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw engine::Error("clouds_bench: cannot write " + file.string());
  return out;
}

double referenceMs(const BenchResults& results, const std::string& view) {
  for (const ReferenceMeasurement& r : results.references) {
    if (r.view == view) return r.medianMs;
  }
  return 0.0;
}

std::vector<std::string> staticViews(const BenchResults& results) {
  std::vector<std::string> views;
  for (const std::string& v : results.views) {
    if (v != kFlyThrough) views.push_back(v);
  }
  return views;
}

// A view every configuration renders exactly (the clear sky: no cloud to get wrong). Its
// PSNR of 200 would pull every pooled figure up, so pooling leaves it out.
bool cloudless(const BenchResults& results, const std::string& view) {
  for (const Measurement& m : results.measurements) {
    if (m.view == view && m.psnr < 200.0) return false;
  }
  return true;
}

// The static views whose errors are pooled.
std::vector<std::string> pooledViews(const BenchResults& results) {
  std::vector<std::string> views;
  for (const std::string& v : staticViews(results)) {
    if (!cloudless(results, v)) views.push_back(v);
  }
  return views;
}

double passMs(const Measurement& m, const char* pass) {
  const auto it = m.passMs.find(pass);
  return it == m.passMs.end() ? 0.0 : it->second;
}

}  // namespace

Aggregate aggregateStatic(const BenchResults& results, const std::string& config) {
  Aggregate a;
  double mse = 0.0;
  int count = 0;
  a.minPsnr = 1e9;
  int timedViews = 0;
  for (const std::string& view : staticViews(results)) {
    const Measurement* m = results.find(config, view);
    if (m == nullptr) continue;
    a.milliseconds += m->medianMs;
    ++timedViews;
  }
  for (const std::string& view : pooledViews(results)) {
    const Measurement* m = results.find(config, view);
    if (m == nullptr) continue;
    mse += meanSquaredFromPsnr(m->psnr);
    a.minPsnr = std::min(a.minPsnr, m->psnr);
    ++count;
  }
  if (timedViews == 0 || count == 0) return Aggregate{};
  a.milliseconds /= timedViews;
  a.psnr = psnrFromMeanSquared(mse / count);
  return a;
}

double timingNoise(const BenchResults& results) {
  std::vector<double> differences;
  double highSum = 0.0;
  for (const std::string& view : staticViews(results)) {
    const Measurement* high = results.find("High", view);
    const Measurement* again = results.find(kHighTimedAgain, view);
    if (high == nullptr || again == nullptr) continue;
    differences.push_back(again->medianMs - high->medianMs);
    highSum += high->medianMs;
  }
  const auto n = static_cast<double>(differences.size());
  if (differences.size() < 2 || highSum <= 0.0) return 0.0;
  double mean = 0.0;
  for (double d : differences) mean += d / n;
  double variance = 0.0;
  for (double d : differences) variance += (d - mean) * (d - mean) / (n - 1.0);
  const double standardError = std::sqrt(variance / n);
  return 2.0 * standardError / (highSum / n);
}

Front checkFront(const BenchResults& results) {
  Front front;
  front.timingNoise = timingNoise(results);
  for (const BenchConfig& preset : results.configs) {
    if (!preset.preset) continue;
    const Aggregate p = aggregateStatic(results, preset.name);
    for (const BenchConfig& other : results.configs) {
      const Aggregate a = aggregateStatic(results, other.name);
      if (&other == &preset || other.timingRepeat || a.milliseconds >= p.milliseconds ||
          a.psnr <= p.psnr) {
        continue;
      }
      const bool beyondNoise = a.milliseconds < p.milliseconds * (1.0 - front.timingNoise);
      (beyondNoise ? front.beaten : front.withinNoise)
          .push_back(preset.name + " by " + other.name + " (" + format("%.1f", a.milliseconds) +
                     " ms, " + format("%.2f", a.psnr) + " dB against " +
                     format("%.1f", p.milliseconds) + " ms, " + format("%.2f", p.psnr) + " dB)");
    }
  }
  return front;
}

Aggregate aggregateFlyThrough(const BenchResults& results, const std::string& config) {
  const Measurement* m = results.find(config, kFlyThrough);
  if (m == nullptr) return Aggregate{};
  return Aggregate{m->medianMs, m->psnr, m->minPsnr};
}

void writeCsv(const std::filesystem::path& file, const BenchResults& results) {
  std::ofstream out = openOrThrow(file);
  out << "config,sweep,value,preset,view,gpu_ms_median,gpu_ms_min,gpu_ms_max,psnr_db,"
         "min_psnr_db,mean_abs,max_abs,view_samples_per_ray,light_samples_per_ray,"
         "early_exit_fraction,rays_per_frame,scene_distance_ms,march_ms,reconstruct_ms,"
         "upsample_ms,weather_ms_when_run,gpu_memory_mib\n";
  for (const Measurement& m : results.measurements) {
    const BenchConfig* config = nullptr;
    for (const BenchConfig& c : results.configs) {
      if (c.name == m.config) config = &c;
    }
    out << '"' << m.config << "\"," << (config ? config->sweep : "") << ','
        << (config ? config->value : "") << ',' << (config && config->preset ? 1 : 0) << ",\""
        << m.view << "\"," << m.medianMs << ',' << m.minMs << ',' << m.maxMs << ',' << m.psnr << ','
        << m.minPsnr << ',' << m.meanAbs << ',' << m.maxAbs << ',' << m.viewSamplesPerRay << ','
        << m.lightSamplesPerRay << ',' << m.earlyExitFraction << ',' << m.raysPerFrame << ','
        << passMs(m, "scene distance") << ',' << passMs(m, "march") << ','
        << passMs(m, "reconstruct") << ',' << passMs(m, "upsample") << ',' << passMs(m, "weather")
        << ',' << m.memoryMiB << '\n';
  }
  writeShadowCsv(out, results.shadows);
  writeVoxelCsv(out, results.voxels);
  // The Reference mode itself: one frame's time, and one frame against the averaged Reference.
  for (const ReferenceMeasurement& r : results.references) {
    // No error for the fly-through's Reference (it is not compared with itself).
    out << "\"Reference\",,,1,\"" << r.view << "\"," << r.medianMs << ",,,"
        << (r.view == kFlyThrough ? std::string() : std::to_string(r.singleFramePsnr))
        << ",,,,,,,,,,,,,\n";
  }
}

namespace {

// The ladder's rows of the targets table: each preset a real step above the one below,
// Medium's worst view, and the governed flight when the run was given one.
void writeLadderTargets(std::ostream& out, const BenchResults& results) {
  const auto verdict = [](bool met) { return met ? "met" : "**not met**"; };
  for (const LadderStep& step : ladderSteps(results)) {
    out << "| " << step.lower << " at most " << format("%.1f", kLadderCostRatio) << "x "
        << step.upper << "'s time, " << step.upper << " at least " << format("%.0f", kLadderGainDb)
        << " dB more accurate (pooled) | " << format("%.2f", step.costRatio) << "x, +"
        << format("%.1f", step.gainDb) << " dB | "
        << verdict(step.cheapEnough() && step.gainsEnough()) << " |\n";
  }
  const Aggregate medium = aggregateStatic(results, "Medium");
  if (medium.milliseconds > 0.0) {
    out << "| Medium PSNR >= 33 dB on every static view | " << format("%.1f", medium.minPsnr)
        << " dB worst, " << format("%.1f", medium.psnr) << " dB pooled | "
        << verdict(medium.minPsnr >= 33.0) << " |\n";
  }
  if (results.options.governorSeries.empty()) return;
  const GovernedFlight flight = readGovernedFlight(results.options.governorSeries);
  std::string medians, presets;
  for (double m : flight.tenSecondMedians)
    medians += (medians.empty() ? "" : ", ") + format("%.1f", m);
  for (const auto& [name, frames] : flight.framesPerPreset) {
    presets += (presets.empty() ? "" : ", ") + name + " " +
               format("%.0f%%", 100.0 * double(frames) / double(flight.frames));
  }
  out << "| The governor holds the sample's frame within 10% of its "
      << format("%.1f", flight.targetMs) << " ms target ("
      << results.options.governorSeries.filename().string() << ": " << flight.frames << " frames, "
      << format("%.0f", flight.seconds) << " s; at least 95% of frames) | "
      << format("%.1f%%", 100.0 * flight.fractionOverTenPercent)
      << " of frames more than 10% over; wall time a frame median "
      << format("%.1f", flight.medianWallMs) << " ms, by 10 s " << medians << "; presets "
      << presets << "; " << flight.presetChanges << " changes";
  if (flight.shortestGapFrames > 0)
    out << ", at least " << flight.shortestGapFrames << " frames apart";
  out << " | " << verdict(flight.fractionOverTenPercent <= 0.05) << " |\n";
}

}  // namespace

void writeMarkdown(const std::filesystem::path& file, const BenchResults& results) {
  std::ofstream out = openOrThrow(file);
  const RunOptions& o = results.options;
  const std::vector<std::string> views = staticViews(results);
  out << "# Clouds: accuracy versus cost\n\n"
      << "Generated by `build/bin/clouds_bench` on " << results.device << " at " << o.extent.width
      << "x" << o.extent.height << " (whole run " << format("%.0f", results.seconds)
      << " s). GPU time is the module's time per frame from timestamp queries: the median of "
      << o.timedFrames << " frames after " << o.convergeFrames << " frames of convergence ("
      << o.upsampledConvergeFrames
      << " for configurations with temporal upsampling, which accumulate each output pixel's own "
         "samples over a longer time), frames interleaved across configurations so that drift of "
         "the machine's speed cancels. Error is against the Reference mode of the same view "
         "averaged over "
      << o.referenceFrames
      << " frames whose rays move over a 4 x 4 grid inside their pixels (converged and "
         "supersampled; the grid's points are not the presets' own, bench_reference.h), on the "
         "tonemapped image (values in [0, 1]); PSNR over several views is pooled from their mean "
         "squared error, leaving out the clear sky (identical in every configuration, PSNR 200). "
         "Pass times are medians over the frames that ran the pass (the weather map is made "
         "on some frames only). The fly-through ("
      << o.flyFrames
      << " frames at 30 fps, from below the cloud base into the layer, turning) is timed on every "
         "frame and compared with its own Reference every "
      << o.flyReferenceEvery << " frames from frame " << o.flyWarmUpFrames << ".\n\n";

  // --- Targets ---------------------------------------------------------------------------
  const Aggregate high = aggregateStatic(results, "High");
  const Aggregate highFly = aggregateFlyThrough(results, "High");
  // Per frame over the static views (the clear sky costs both modes next to nothing), and
  // the least ratio among the views that show clouds.
  double referenceMean = 0.0;
  for (const std::string& view : views) referenceMean += referenceMs(results, view);
  referenceMean /= double(std::max<std::size_t>(views.size(), 1));
  const double meanRatio = referenceMean / std::max(high.milliseconds, 1e-9);
  double worstRatio = 1e30;
  std::string worstRatioView;
  for (const std::string& view : views) {
    const Measurement* m = results.find("High", view);
    if (m == nullptr || m->medianMs <= 0.0 || m->psnr >= 199.0) continue;  // no clouds
    const double ratio = referenceMs(results, view) / m->medianMs;
    if (ratio < worstRatio) {
      worstRatio = ratio;
      worstRatioView = view;
    }
  }
  const auto verdict = [](bool met) { return met ? "met" : "**not met**"; };
  const Aggregate highAgain = aggregateStatic(results, kHighTimedAgain);
  const Front front = checkFront(results);
  const auto joined = [](const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : "; ") + item;
    return text.empty() ? std::string("none") : text;
  };
  out << "## Targets\n\n| target | measured | |\n|---|---|---|\n";
  if (worstRatioView.empty()) {  // a run of chosen views (--view) without a cloudy static one
    out << "| High against the Reference on the static views | no static view with clouds in "
           "this run | |\n";
  } else {
    out << "| High at least 150x cheaper than Reference per frame | " << format("%.0f", meanRatio)
        << "x over the static views (least on one view: " << format("%.0f", worstRatio) << "x, "
        << worstRatioView << ") | " << verdict(meanRatio >= 150.0) << " |\n"
        << "| High PSNR >= 38 dB on every static view | " << format("%.1f", high.minPsnr)
        << " dB worst, " << format("%.1f", high.psnr) << " dB pooled | "
        << verdict(high.minPsnr >= 38.0) << " |\n";
  }
  if (highFly.milliseconds > 0.0) {
    out << "| High PSNR >= 33 dB along the fly-through | " << format("%.1f", highFly.psnr)
        << " dB mean, " << format("%.1f", highFly.minPsnr) << " dB worst frame | "
        << verdict(highFly.psnr >= 33.0) << " |\n";
  }
  out << "| No configuration cheaper and more accurate than a preset (static mean ms, pooled "
         "PSNR; cheaper by more than this run's timing noise) | "
      << joined(front.beaten);
  if (highAgain.milliseconds > 0.0) {
    out << ". Timing noise: High timed twice, " << format("%.2f", high.milliseconds) << " and "
        << format("%.2f", highAgain.milliseconds)
        << " ms; twice the standard error of their mean difference over the views, "
        << format("%.1f", 100.0 * front.timingNoise)
        << "% of High's time; within it, so not counted: " << joined(front.withinNoise);
  }
  out << " | " << verdict(front.beaten.empty()) << " |\n";
  writeLadderTargets(out, results);
  for (const BenchConfig& c : results.configs) {
    if (!c.preset) continue;
    const Measurement* clear = results.find(c.name, "clear sky");
    const Measurement* overcast = results.find(c.name, "overcast");
    if (clear == nullptr || overcast == nullptr || overcast->medianMs <= 0.0) continue;
    const double ratio = clear->medianMs / overcast->medianMs;
    out << "| " << c.name << ": clear sky < 1/10 of overcast | " << format("%.2f", clear->medianMs)
        << " ms vs " << format("%.2f", overcast->medianMs) << " ms (" << format("%.3f", ratio)
        << ") | " << verdict(ratio < 0.1) << " |\n";
  }

  // --- Presets ---------------------------------------------------------------------------
  out << "\n## Presets\n\n| preset | ms per frame (static mean) | x cheaper than Reference | "
         "PSNR static (pooled / worst) | fly-through ms | fly-through PSNR (mean / worst) | "
         "view samples per ray | light samples per ray | early exits | GPU memory (MiB) |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchConfig& c : results.configs) {
    if (!c.preset) continue;
    const Aggregate s = aggregateStatic(results, c.name);
    const Aggregate f = aggregateFlyThrough(results, c.name);
    double viewSamples = 0.0, lightSamples = 0.0, exits = 0.0, memory = 0.0;
    for (const std::string& view : views) {
      const Measurement* m = results.find(c.name, view);
      if (m == nullptr) continue;
      memory = std::max(memory, m->memoryMiB);
      viewSamples += m->viewSamplesPerRay / double(views.size());
      lightSamples += m->lightSamplesPerRay / double(views.size());
      exits += m->earlyExitFraction / double(views.size());
    }
    out << "| " << c.name << " | " << format("%.1f", s.milliseconds) << " | "
        << format("%.0f", referenceMean / std::max(s.milliseconds, 1e-9)) << " | "
        << format("%.1f", s.psnr) << " / " << format("%.1f", s.minPsnr) << " | "
        << format("%.1f", f.milliseconds) << " | " << format("%.1f", f.psnr) << " / "
        << format("%.1f", f.minPsnr) << " | " << format("%.1f", viewSamples) << " | "
        << format("%.1f", lightSamples) << " | " << format("%.0f%%", exits * 100.0) << " | "
        << format("%.1f", memory) << " |\n";
  }
  out << "| Reference (one frame) | " << format("%.0f", referenceMean) << " | 1 | ";
  double referenceMse = 0.0;
  int referenceViews = 0;
  for (const ReferenceMeasurement& r : results.references) {
    if (r.view == kFlyThrough || cloudless(results, r.view)) continue;
    referenceMse += meanSquaredFromPsnr(r.singleFramePsnr);
    ++referenceViews;
  }
  out << format("%.1f", psnrFromMeanSquared(referenceMse / std::max(referenceViews, 1)))
      << " (one frame against the average of " << o.referenceFrames << ") | "
      << format("%.0f", referenceMs(results, kFlyThrough)) << " | | | | | |\n";

  // --- Convergence ------------------------------------------------------------------------
  if (!results.highConvergence.empty()) {
    std::vector<std::uint32_t> frames;
    for (const auto& [view, points] : results.highConvergence) {
      for (const ConvergencePoint& point : points) {
        if (std::find(frames.begin(), frames.end(), point.frames) == frames.end())
          frames.push_back(point.frames);
      }
    }
    std::sort(frames.begin(), frames.end());
    out << "\n## How High converges on a static view\n\nPSNR (dB) against the Reference after "
           "so many frames of a static camera (at 30 fps, 128 frames are 4.3 s):\n\n| view |";
    for (std::uint32_t n : frames) out << ' ' << n << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < frames.size(); ++i) out << "---|";
    out << '\n';
    for (const std::string& view : pooledViews(results)) {
      const auto it = results.highConvergence.find(view);
      if (it == results.highConvergence.end()) continue;
      out << "| " << view << " |";
      for (std::uint32_t n : frames) {
        std::string cell;
        for (const ConvergencePoint& point : it->second) {
          if (point.frames == n) cell = format("%.1f", point.psnr);
        }
        out << ' ' << cell << " |";
      }
      out << '\n';
    }
  }

  // --- Knob sweeps -----------------------------------------------------------------------
  out << "\n## Cost knobs (one at a time, around High)\n\n"
         "| knob | value | ms per frame (static mean) | PSNR static (pooled / worst) | "
         "fly-through ms | fly-through PSNR |\n|---|---|---|---|---|---|\n";
  for (const Sweep& sweep : sweepsOf(results.configs)) {
    for (std::size_t index : sweep.configs) {
      const BenchConfig& c = results.configs[index];
      const Aggregate s = aggregateStatic(results, c.name);
      const Aggregate f = aggregateFlyThrough(results, c.name);
      out << "| " << sweep.name << " | " << (c.preset ? "High" : c.value) << " | "
          << format("%.1f", s.milliseconds) << " | " << format("%.1f", s.psnr) << " / "
          << format("%.1f", s.minPsnr) << " | " << format("%.1f", f.milliseconds) << " | "
          << format("%.1f", f.psnr) << " |\n";
    }
  }

  // --- Per view --------------------------------------------------------------------------
  out << "\n## Per view (ms / PSNR dB)\n\n| configuration |";
  for (const std::string& view : results.views) out << ' ' << view << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < results.views.size(); ++i) out << "---|";
  out << '\n';
  for (const BenchConfig& c : results.configs) {
    out << "| " << c.name << " |";
    for (const std::string& view : results.views) {
      const Measurement* m = results.find(c.name, view);
      out << ' ' << (m ? format("%.1f", m->medianMs) + " / " + format("%.1f", m->psnr) : "")
          << " |";
    }
    out << '\n';
  }
  out << "| Reference (one frame) |";
  for (const std::string& view : results.views)
    out << ' ' << format("%.0f", referenceMs(results, view)) << " |";
  out << "\n\nPSNR 200 means identical images (the clear sky has no clouds to get wrong).\n";
  writeShadowMarkdown(out, results.shadows);
  writeVoxelMarkdown(out, results.voxels);
}

void writePlotData(const std::filesystem::path& file, const BenchResults& results) {
  const auto plot = [&](bool fly, const char* png) {
    const auto aggregate = [&](const std::string& config) {
      return fly ? aggregateFlyThrough(results, config) : aggregateStatic(results, config);
    };
    const auto point = [](const Aggregate& a, const std::string& label) {
      return nlohmann::json{{"gpu_ms", a.milliseconds}, {"psnr_db", a.psnr}, {"label", label}};
    };
    nlohmann::json series = nlohmann::json::array();
    for (const Sweep& sweep : sweepsOf(results.configs)) {
      nlohmann::json points = nlohmann::json::array();
      for (std::size_t index : sweep.configs) {
        const BenchConfig& c = results.configs[index];
        // The High point that starts every sweep is labelled by the presets series.
        points.push_back(point(aggregate(c.name), c.preset ? "" : c.value));
      }
      series.push_back({{"name", sweep.name}, {"presets", false}, {"points", points}});
    }
    nlohmann::json presets = nlohmann::json::array();
    for (const BenchConfig& c : results.configs) {
      if (c.preset) presets.push_back(point(aggregate(c.name), c.name));
    }
    series.push_back({{"name", "quality presets"}, {"presets", true}, {"points", presets}});
    double reference = referenceMs(results, kFlyThrough);
    if (!fly) {
      const std::vector<std::string> views = staticViews(results);
      reference = 0.0;
      for (const std::string& view : views)
        reference += referenceMs(results, view) / double(views.size());
    }
    return nlohmann::json{
        {"file", png},
        {"title", std::string(fly ? "Fly-through" : "Static views") + ": error against time, " +
                      std::to_string(results.options.extent.width) + "x" +
                      std::to_string(results.options.extent.height) + " (Reference " +
                      format("%.0f", reference) + " ms)"},
        {"x_label", fly ? "GPU time per frame (ms, median over the path, log scale)"
                        : "GPU time per frame (ms, mean over the static views, log scale)"},
        {"y_label", fly ? "PSNR against the Reference (dB, mean over measured frames)"
                        : "PSNR against the Reference (dB, pooled over views)"},
        {"series", series}};
  };
  // The ladder alone: each preset's cost against its pooled and its worst static view.
  const auto ladder = [&]() {
    nlohmann::json pooled = nlohmann::json::array(), worst = nlohmann::json::array();
    for (const BenchConfig& c : results.configs) {
      if (!c.preset) continue;
      const Aggregate a = aggregateStatic(results, c.name);
      pooled.push_back({{"gpu_ms", a.milliseconds}, {"psnr_db", a.psnr}, {"label", c.name}});
      worst.push_back({{"gpu_ms", a.milliseconds}, {"psnr_db", a.minPsnr}, {"label", ""}});
    }
    return nlohmann::json{
        {"file", "plot_ladder.png"},
        {"title", "The preset ladder, static views, " +
                      std::to_string(results.options.extent.width) + "x" +
                      std::to_string(results.options.extent.height) + " (each rung at most " +
                      format("%.1f", kLadderCostRatio) + "x the next one's time, " +
                      format("%.0f", kLadderGainDb) + " dB below it)"},
        {"x_label", "GPU time per frame (ms, mean over the static views, log scale)"},
        {"y_label", "PSNR against the Reference (dB)"},
        {"series",
         {{{"name", "worst static view"}, {"presets", false}, {"points", worst}},
          {{"name", "pooled over the static views"}, {"presets", true}, {"points", pooled}}}}};
  };
  nlohmann::json plots = {plot(false, "plot_static.png"), plot(true, "plot_fly_through.png"),
                          ladder()};
  if (!results.shadows.views.empty())
    plots.push_back(shadowPlot(results.shadows, "plot_shadow.png"));
  const nlohmann::json data = {{"plots", plots}};
  openOrThrow(file) << data.dump(2) << '\n';
}

}  // namespace bench
