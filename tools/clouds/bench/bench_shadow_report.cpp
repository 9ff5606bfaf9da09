#include "bench_shadow_report.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace bench {
namespace {

std::string format(const char* spec, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), spec, value);
  return text;
}

// A configuration over the views: mean time, PSNR pooled from the mean squared error, the
// worst view's PSNR, the mean of the mean absolute errors.
struct ShadowAggregate {
  double meanMs = 0.0;
  double cutMs = 0.0;
  double psnr = 0.0;
  double minPsnr = 200.0;
  double meanAbs = 0.0;
  double nearMeanAbs = 0.0;
  double reachKm = 0.0;
};

ShadowAggregate aggregate(const ShadowResults& shadows, const std::string& config) {
  ShadowAggregate a;
  double squared = 0.0;
  int views = 0;
  for (const std::string& view : shadows.views) {
    const ShadowMeasurement* m = shadows.find(config, view);
    if (m == nullptr) continue;
    a.meanMs += m->meanMs;
    a.cutMs += m->cutMs;
    a.meanAbs += m->meanAbs;
    a.nearMeanAbs += m->nearMeanAbs;
    a.minPsnr = std::min(a.minPsnr, m->psnr);
    a.reachKm = m->reachKm;
    squared += std::pow(10.0, -m->psnr / 10.0);
    ++views;
  }
  if (views == 0) return a;
  a.meanMs /= views;
  a.cutMs /= views;
  a.meanAbs /= views;
  a.nearMeanAbs /= views;
  a.psnr = std::min(200.0, -10.0 * std::log10(std::max(squared / views, 1e-20)));
  return a;
}

}  // namespace

void writeShadowCsv(std::ostream& out, const ShadowResults& shadows) {
  for (const ShadowMeasurement& m : shadows.measurements) {
    const BenchConfig* config = nullptr;
    for (const BenchConfig& c : shadows.configs) {
      if (c.name == m.config) config = &c;
    }
    out << "\"shadow " << m.config << "\"," << (config ? config->sweep : "") << ','
        << (config ? config->value : "") << ',' << (config && config->preset ? 1 : 0)
        << ",\"shadow map: " << m.view << "\"," << m.meanMs << ",," << m.cutMs << ',' << m.psnr
        << ',' << m.psnr << ',' << m.meanAbs << ',' << m.maxAbs << ",,,,,,,,,,\n";
  }
}

void writeShadowMarkdown(std::ostream& out, const ShadowResults& shadows) {
  if (shadows.views.empty()) return;
  out << "\n## The cloud shadow map\n\nThe map's own knobs, one at a time around Medium (the "
         "default scene's preset), and the presets, on ";
  for (std::size_t i = 0; i < shadows.views.size(); ++i) {
    out << (i == 0 ? "" : " and ") << shadows.views[i];
  }
  out << ". GPU time is the \"shadow map\" pass per frame, the mean over the frames of a "
         "whole cycle of cascade turns after a cut (eight turns, the finest cascade every other "
         "one; a turn takes shadowFramesPerCascade frames: \"cascades per frame\" below 1), and "
         "at the cut itself (every cascade at once; one frame, so noisy). Every configuration "
         "has its own "
         "module and frames are interleaved across them, so times are higher than the same "
         "pass run alone in the sample. Error is the receivers' lookup at "
      << shadows.points
      << " ground points in rings out to 100 km against a 10 m march towards the sun through "
         "the same clouds (the CPU reference): PSNR of the transmittance (peak 1, pooled over "
         "the views) and the mean absolute difference. Points beyond a configuration's reach "
         "count as unshadowed.\n\n"
         "| configuration | ms per frame | ms at a cut | PSNR (pooled / worst) | mean abs | "
         "mean abs within 10 km | reach (km) |\n|---|---|---|---|---|---|---|\n";
  const auto row = [&](const std::string& label, const std::string& config) {
    const ShadowAggregate a = aggregate(shadows, config);
    out << "| " << label << " | " << format("%.2f", a.meanMs) << " | " << format("%.1f", a.cutMs)
        << " | " << format("%.1f", a.psnr) << " / " << format("%.1f", a.minPsnr) << " | "
        << format("%.3f", a.meanAbs) << " | " << format("%.3f", a.nearMeanAbs) << " | "
        << format("%.0f", a.reachKm) << " |\n";
  };
  for (const BenchConfig& c : shadows.configs) {
    if (c.preset) row(c.name, c.name);
  }
  for (const Sweep& sweep : shadowSweeps(shadows.configs)) {
    for (std::size_t index : sweep.configs) {
      const BenchConfig& c = shadows.configs[index];
      row(sweep.name + " " + (c.preset ? "(Medium)" : c.value), c.name);
    }
  }
}

nlohmann::json shadowPlot(const ShadowResults& shadows, const char* png) {
  const auto point = [&](const std::string& config, const std::string& label) {
    const ShadowAggregate a = aggregate(shadows, config);
    return nlohmann::json{{"gpu_ms", a.meanMs}, {"psnr_db", a.psnr}, {"label", label}};
  };
  nlohmann::json series = nlohmann::json::array();
  for (const Sweep& sweep : shadowSweeps(shadows.configs)) {
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t index : sweep.configs) {
      const BenchConfig& c = shadows.configs[index];
      points.push_back(point(c.name, c.preset ? "" : c.value));
    }
    series.push_back({{"name", sweep.name}, {"presets", false}, {"points", points}});
  }
  nlohmann::json presets = nlohmann::json::array();
  for (const BenchConfig& c : shadows.configs) {
    if (c.preset) presets.push_back(point(c.name, c.name));
  }
  series.push_back({{"name", "quality presets"}, {"presets", true}, {"points", presets}});
  return nlohmann::json{
      {"file", png},
      {"title", "Cloud shadow map: error against time (ground transmittance to 100 km)"},
      {"x_label", "GPU time of the shadow-map pass per frame (ms, mean over a cycle, log scale)"},
      {"y_label", "PSNR of the transmittance against a 10 m march (dB, pooled over views)"},
      {"series", series}};
}

}  // namespace bench
