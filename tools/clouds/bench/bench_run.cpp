#include "bench_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "bench_reference.h"
#include "engine/core/error.h"

namespace bench {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// A configuration's own module instance.
struct Instance {
  const BenchConfig* config = nullptr;
  std::unique_ptr<clouds::tools::CloudHarness> harness;
};

// What the timed frames of one configuration on one view recorded.
struct Samples {
  std::vector<double> milliseconds;
  std::map<std::string, std::vector<double>> passMilliseconds;
  clouds::WorkCounters work;
  std::uint64_t memoryBytes = 0;

  void record(const clouds::tools::CloudHarness& harness) {
    milliseconds.push_back(harness.lastGpuMilliseconds());
    memoryBytes = harness.memoryUsage().totalBytes();
    for (const clouds::PassTiming& pass : harness.lastPassTimings()) {
      passMilliseconds[pass.name].push_back(pass.milliseconds);
    }
    const clouds::WorkCounters w = harness.lastWorkCounters();
    work.viewSamples += w.viewSamples;
    work.lightSamples += w.lightSamples;
    work.tracedPixels += w.tracedPixels;
    work.earlyExits += w.earlyExits;
    work.skippedCells += w.skippedCells;
  }
};

Measurement summarise(const std::string& config, const std::string& view, const Samples& s) {
  Measurement m;
  m.config = config;
  m.view = view;
  m.medianMs = median(s.milliseconds);
  if (!s.milliseconds.empty()) {
    const auto [lo, hi] = std::minmax_element(s.milliseconds.begin(), s.milliseconds.end());
    m.minMs = *lo;
    m.maxMs = *hi;
  }
  const double rays = double(std::max<std::uint64_t>(s.work.tracedPixels, 1));
  m.viewSamplesPerRay = double(s.work.viewSamples) / rays;
  m.lightSamplesPerRay = double(s.work.lightSamples) / rays;
  m.earlyExitFraction = double(s.work.earlyExits) / rays;
  m.raysPerFrame =
      double(s.work.tracedPixels) / double(std::max<std::size_t>(s.milliseconds.size(), 1));
  for (const auto& [name, values] : s.passMilliseconds) m.passMs[name] = median(values);
  m.memoryMiB = double(s.memoryBytes) / (1024.0 * 1024.0);
  return m;
}

void renderOrThrow(clouds::tools::CloudHarness& harness, const clouds::tools::CloudView& view,
                   const clouds::Settings& settings, VkExtent2D extent) {
  const std::string error = harness.tryRender(view, settings, extent);
  if (!error.empty()) throw engine::Error("clouds_bench: " + error);
}

}  // namespace

Reference renderReference(clouds::tools::CloudHarness& harness,
                          const clouds::tools::CloudView& view, const clouds::Settings& look,
                          VkExtent2D extent, std::uint32_t frames) {
  clouds::Settings settings = clouds::settingsFor(clouds::Quality::Reference, look);
  // Rays at their pixels' centres: the bench moves them (bench_reference.h).
  settings.jitter = clouds::Jitter::BayerHalton;
  harness.cut();
  clouds::tools::CloudFrame sum;
  Reference reference;
  for (std::uint32_t i = 0; i < frames; ++i) {
    clouds::tools::CloudView jittered = view;
    jittered.projectionJitterPixels = referenceSubpixelOffset(i);
    const clouds::tools::CloudFrame frame = harness.render(jittered, settings, extent);
    reference.milliseconds.push_back(harness.lastGpuMilliseconds());
    if (i == 0) {
      sum = frame;
      reference.firstPixels = clouds::tools::tonemappedPixels(frame, view);
      continue;
    }
    for (std::size_t p = 0; p < frame.radiance.size(); ++p) sum.radiance[p] += frame.radiance[p];
  }
  for (glm::vec4& p : sum.radiance) p /= float(std::max(frames, 1u));
  reference.pixels = clouds::tools::tonemappedPixels(sum, view);
  return reference;
}

std::vector<std::string> implausibleMeasurements(const BenchResults& results) {
  std::vector<std::string> problems;
  const auto check = [&](const Measurement& m, const char* field, double value) {
    if (!std::isfinite(value) || value < 0.0) {
      problems.push_back(m.config + " on " + m.view + ": " + field + " = " + std::to_string(value));
    }
  };
  for (const Measurement& m : results.measurements) {
    check(m, "median ms", m.medianMs);
    check(m, "PSNR", m.psnr);
    check(m, "min PSNR", m.minPsnr);
    check(m, "mean abs error", m.meanAbs);
    check(m, "max abs error", m.maxAbs);
    check(m, "view samples per ray", m.viewSamplesPerRay);
    check(m, "light samples per ray", m.lightSamplesPerRay);
    for (const auto& [pass, ms] : m.passMs) check(m, pass.c_str(), ms);
    if (m.view != "clear sky" && m.raysPerFrame <= 0.0) {
      problems.push_back(m.config + " on " + m.view + ": no ray traced");
    }
  }
  for (const ReferenceMeasurement& r : results.references) {
    if (!std::isfinite(r.medianMs) || r.medianMs <= 0.0) {
      problems.push_back("Reference on " + r.view + ": median ms = " + std::to_string(r.medianMs));
    }
  }
  for (const ShadowMeasurement& m : results.shadows.measurements) {
    for (const auto& [field, value] : {std::pair{"ms", m.meanMs},
                                       {"cut ms", m.cutMs},
                                       {"PSNR", m.psnr},
                                       {"mean abs", m.meanAbs}}) {
      if (!std::isfinite(value) || value < 0.0) {
        problems.push_back("shadow map " + m.config + " on " + m.view + ": " + field + " = " +
                           std::to_string(value));
      }
    }
    if (m.cutMs <= 0.0)
      problems.push_back("shadow map " + m.config + " on " + m.view + ": untimed");
  }
  if (results.measurements.empty()) problems.emplace_back("no measurement");
  return problems;
}

const Measurement* BenchResults::find(const std::string& config, const std::string& view) const {
  for (const Measurement& m : measurements) {
    if (m.config == config && m.view == view) return &m;
  }
  return nullptr;
}

BenchResults runBenchmark(engine::gfx::Device& device, const RunOptions& options,
                          void (*progress)(const std::string& line)) {
  const auto start = std::chrono::steady_clock::now();
  BenchResults results;
  results.options = options;
  for (const BenchConfig& config : benchConfigs()) {
    if (selected(options.onlyConfigs, config.name)) results.configs.push_back(config);
  }
  if (results.configs.empty()) throw engine::Error("clouds_bench: no configuration selected");
  results.device = device.properties().deviceName;
  const VkExtent2D extent = options.extent;

  clouds::tools::HarnessOptions harnessOptions;
  harnessOptions.workCounters = true;
  harnessOptions.passTimings = true;
  std::vector<Instance> instances;
  for (const BenchConfig& config : results.configs) {
    instances.push_back(Instance{
        &config, std::make_unique<clouds::tools::CloudHarness>(device, extent, harnessOptions)});
  }
  clouds::tools::CloudHarness referenceHarness(device, extent, harnessOptions);

  // --- Static views: converge, time interleaved, then compare the last frame. ---------------
  for (const BenchView& view : canonicalViews()) {
    if (!selected(options.onlyViews, view.name)) continue;
    results.views.push_back(view.name);
    progress(view.name + ": Reference (" + std::to_string(options.referenceFrames) + " frames)");
    const Reference reference =
        renderReference(referenceHarness, view.view, view.look, extent, options.referenceFrames);
    results.references.push_back(ReferenceMeasurement{
        view.name, median(reference.milliseconds),
        clouds::tools::imageError(reference.firstPixels, reference.pixels).psnr()});

    progress(view.name + ": " + std::to_string(instances.size()) + " configurations");
    std::vector<clouds::Settings> settings;
    for (Instance& instance : instances) {
      settings.push_back(instance.config->settingsFor(view.look));
      instance.harness->cut();
    }
    // Converge: each configuration for its own number of frames; High's error is also
    // taken on the way (the time it takes to converge is part of what it costs).
    std::vector<std::uint32_t> converge(instances.size());
    for (std::size_t i = 0; i < instances.size(); ++i) {
      converge[i] = clouds::upsamplesTemporally(settings[i])
                        ? std::max(options.convergeFrames, options.upsampledConvergeFrames)
                        : options.convergeFrames;
    }
    const std::uint32_t longest = *std::max_element(converge.begin(), converge.end());
    for (std::uint32_t frame = 0; frame < longest; ++frame) {
      for (std::size_t i = 0; i < instances.size(); ++i) {
        if (frame >= converge[i]) continue;
        clouds::tools::CloudHarness& harness = *instances[i].harness;
        const std::uint32_t rendered = frame + 1;
        const bool high =
            instances[i].config->preset && instances[i].config->quality == clouds::Quality::High;
        if (high && (rendered & (rendered - 1)) == 0 && rendered >= 8) {  // 8, 16, 32, ...
          const clouds::tools::CloudFrame out = harness.render(view.view, settings[i], extent);
          const double psnr = clouds::tools::imageError(
                                  clouds::tools::tonemappedPixels(out, view.view), reference.pixels)
                                  .psnr();
          results.highConvergence[view.name].push_back(ConvergencePoint{rendered, psnr});
        } else {
          renderOrThrow(harness, view.view, settings[i], extent);
        }
      }
    }
    std::vector<Samples> samples(instances.size());
    for (std::uint32_t frame = 0; frame < options.timedFrames; ++frame) {
      for (std::size_t i = 0; i < instances.size(); ++i) {
        renderOrThrow(*instances[i].harness, view.view, settings[i], extent);
        samples[i].record(*instances[i].harness);
      }
    }
    for (std::size_t i = 0; i < instances.size(); ++i) {
      const clouds::tools::CloudFrame last =
          instances[i].harness->render(view.view, settings[i], extent);
      const engine::assets::ImageError error = clouds::tools::imageError(
          clouds::tools::tonemappedPixels(last, view.view), reference.pixels);
      Measurement m = summarise(instances[i].config->name, view.name, samples[i]);
      m.psnr = m.minPsnr = error.psnr();
      m.meanAbs = error.meanAbs;
      m.maxAbs = error.maxAbs;
      results.measurements.push_back(m);
    }
  }

  // --- The cloud shadow map's knobs (its own views and error; none with --view elsewhere). ----
  results.shadows = runShadowBenchmark(device, options.onlyViews, options.onlyConfigs, progress);

  // --- Hero clouds: seed 002's optimisation ladder (its own views and Reference). ------------
  results.voxels = runVoxelLadder(device, options.extent, options.timedFrames,
                                  options.referenceFrames, options.onlyViews, progress);

  // --- The fly-through: every frame timed, the error at regular frames. ----------------------
  const std::string flyName = "fly-through";
  if (!selected(options.onlyViews, flyName)) {
    results.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return results;
  }
  const FlyThrough path = flyThrough(options.flyFrames);
  results.views.push_back(flyName);
  std::vector<clouds::Settings> settings;
  for (Instance& instance : instances) {
    settings.push_back(instance.config->settingsFor(path.look));
    instance.harness->cut();
  }
  std::vector<Samples> samples(instances.size());
  std::vector<std::vector<engine::assets::ImageError>> errors(instances.size());
  std::vector<double> referenceMs;
  for (std::uint32_t frame = 0; frame < path.frames; ++frame) {
    const clouds::tools::CloudView pose = path.poseAt(frame);
    const bool measured = frame >= options.flyWarmUpFrames &&
                          ((frame - options.flyWarmUpFrames) % options.flyReferenceEvery == 0 ||
                           frame + 1 == path.frames);
    Reference reference;
    if (measured) {
      progress(flyName + ": frame " + std::to_string(frame) + ", Reference");
      reference =
          renderReference(referenceHarness, pose, path.look, extent, options.referenceFrames);
      referenceMs.insert(referenceMs.end(), reference.milliseconds.begin(),
                         reference.milliseconds.end());
    }
    for (std::size_t i = 0; i < instances.size(); ++i) {
      clouds::tools::CloudHarness& harness = *instances[i].harness;
      if (measured) {
        const clouds::tools::CloudFrame out = harness.render(pose, settings[i], extent);
        errors[i].push_back(clouds::tools::imageError(clouds::tools::tonemappedPixels(out, pose),
                                                      reference.pixels));
      } else {
        renderOrThrow(harness, pose, settings[i], extent);
      }
      samples[i].record(harness);
    }
  }
  results.references.push_back(ReferenceMeasurement{flyName, median(referenceMs), 0.0});
  for (std::size_t i = 0; i < instances.size(); ++i) {
    Measurement m = summarise(instances[i].config->name, flyName, samples[i]);
    m.minPsnr = 1e9;
    for (const engine::assets::ImageError& e : errors[i]) {
      m.psnr += e.psnr() / double(errors[i].size());
      m.meanAbs += e.meanAbs / double(errors[i].size());
      m.maxAbs = std::max(m.maxAbs, e.maxAbs);
      m.minPsnr = std::min(m.minPsnr, e.psnr());
    }
    results.measurements.push_back(m);
  }
  results.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return results;
}

}  // namespace bench
