#include "bench_shadow.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "cloud_shadow_march.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "shadow_cascades.h"

namespace bench {
namespace {

// Medium's value of each shadow knob: where Medium sits in each sweep.
const std::map<std::string, double>& mediumShadowKnobs() {
  static const std::map<std::string, double> knobs = {{"shadow resolution", 128.0},
                                                      {"shadow steps", 12.0},
                                                      {"shadow cascades", 4.0},
                                                      {"cascades per frame", 0.25}};
  return knobs;
}

struct ShadowView {
  std::string name;
  clouds::tools::CloudView view;
  clouds::Settings look;
};

// Broken cumulus seen from near the ground (the shadow tests' view), at two sun elevations.
std::vector<ShadowView> shadowViews() {
  std::vector<ShadowView> views;
  for (double elevation : {35.0, 12.0}) {
    ShadowView v;
    v.name = "cumulus, sun " + number(elevation) + " deg";
    v.view.position = {1200.0, 300.0, -800.0};
    v.view.sunElevationDegrees = elevation;
    v.view.sunAzimuthDegrees = 200.0;
    v.view.timeSeconds = 5.0;
    v.look.coverage = 0.55f;
    v.look.cloudType = 0.9f;
    views.push_back(v);
  }
  return views;
}

// Ground points (camera-relative, at sea level) in rings out to 100 km, the near ones denser.
std::vector<glm::vec3> groundPoints(const clouds::tools::CloudView& view) {
  std::vector<glm::vec3> points;
  for (double distance : {300.0, 1000.0, 2500.0, 5000.0, 9000.0, 15000.0, 25000.0, 40000.0, 60000.0,
                          80000.0, 100000.0}) {
    for (int k = 0; k < 36; ++k) {
      const double angle = (double(k) + 0.37) * 2.0 * 3.14159265358979 / 36.0;
      points.emplace_back(float(distance * std::cos(angle)), float(-view.position.y),
                          float(distance * std::sin(angle)));
    }
  }
  return points;
}

double mean(const std::vector<double>& values) {
  return values.empty()
             ? 0.0
             : std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

double shadowPassMs(const clouds::tools::CloudHarness& harness) {
  double ms = 0.0;
  for (const clouds::PassTiming& pass : harness.lastPassTimings()) {
    if (std::string(pass.name) == "shadow map") ms += pass.milliseconds;
  }
  return ms;
}

}  // namespace

const ShadowMeasurement* ShadowResults::find(const std::string& config,
                                             const std::string& view) const {
  for (const ShadowMeasurement& m : measurements) {
    if (m.config == config && m.view == view) return &m;
  }
  return nullptr;
}

std::vector<BenchConfig> shadowConfigs() {
  std::vector<BenchConfig> configs = presetConfigs();
  const auto sweep = [&](const char* knob, std::vector<double> values,
                         void (*adjust)(clouds::Settings&, double)) {
    for (double v : values) {
      BenchConfig c;
      c.sweep = knob;
      c.value = number(v);
      c.name = std::string(knob) + " " + c.value;
      c.quality = clouds::Quality::Medium;
      c.adjust = adjust;
      c.knob = v;
      configs.push_back(c);
    }
  };
  sweep("shadow resolution", {64.0, 256.0, 512.0},
        [](clouds::Settings& s, double n) { s.shadowMapResolution = std::uint32_t(n); });
  sweep("shadow steps", {4.0, 6.0, 24.0, 48.0},
        [](clouds::Settings& s, double n) { s.shadowSteps = std::uint32_t(n); });
  sweep("shadow cascades", {1.0, 2.0, 3.0},
        [](clouds::Settings& s, double n) { s.shadowCascades = std::uint32_t(n); });
  // The refresh rate in cascade turns a frame: below one, a turn spread over frames in slices.
  sweep("cascades per frame", {0.125, 0.5, 1.0, 2.0, 4.0}, [](clouds::Settings& s, double n) {
    s.shadowCascadesPerFrame = std::max(1u, std::uint32_t(n));
    s.shadowFramesPerCascade = std::max(1u, std::uint32_t(std::lround(1.0 / n)));
  });
  return configs;
}

std::vector<Sweep> shadowSweeps(const std::vector<BenchConfig>& configs) {
  return sweepsOf(configs, clouds::Quality::Medium, mediumShadowKnobs());
}

ShadowResults runShadowBenchmark(engine::gfx::Device& device,
                                 const std::vector<std::string>& onlyViews,
                                 const std::vector<std::string>& onlyConfigs,
                                 void (*progress)(const std::string& line)) {
  ShadowResults results;
  for (const BenchConfig& config : shadowConfigs()) {
    if (selected(onlyConfigs, config.name)) results.configs.push_back(config);
  }
  if (results.configs.empty()) return results;
  for (const ShadowView& view : shadowViews()) {
    if (!selected(onlyViews, view.name)) continue;
    results.views.push_back(view.name);
    // Every configuration has its own module (its own cascades); frames are interleaved across
    // them, one frame of each in turn.
    struct Instance {
      const BenchConfig* config;
      clouds::Settings settings;
      std::unique_ptr<clouds::tools::CloudHarness> harness;
      double cutMs = 0.0;
      std::vector<double> cycleMs;
    };
    std::vector<Instance> instances;
    for (const BenchConfig& c : results.configs) {
      clouds::tools::HarnessOptions harnessOptions;
      harnessOptions.passTimings = true;
      instances.push_back({&c,
                           c.settingsFor(view.look),
                           std::make_unique<clouds::tools::CloudHarness>(device, VkExtent2D{16, 16},
                                                                         harnessOptions),
                           0.0,
                           {}});
    }
    // A cut, then a whole cycle of turns (the finest every other turn) of each instance, timed:
    // eight frames, or eight turns of as many frames as one takes.
    const auto cycleFrames = [](const clouds::Settings& s) {
      return 2 * 4 * s.shadowFramesPerCascade;
    };
    std::uint32_t frames = 0;
    for (const Instance& instance : instances) {
      frames = std::max(frames, cycleFrames(instance.settings));
    }
    clouds::tools::CloudView pose = view.view;
    for (std::uint32_t frame = 0; frame <= frames; ++frame) {
      for (Instance& instance : instances) {
        instance.harness->renderShadowMap(pose, instance.settings, 1);
        const double ms = shadowPassMs(*instance.harness);
        if (frame == 0) instance.cutMs = ms;
        if (frame > 0 && frame <= cycleFrames(instance.settings)) instance.cycleMs.push_back(ms);
      }
      pose.timeSeconds += 1.0 / 30.0;
    }

    // The truth at the last frame's time: a 10 m march towards the sun from each point through
    // the clouds the maps were made from (every instance has the same field).
    clouds::tools::CloudHarness& first = *instances.front().harness;
    const clouds::tools::CpuTextures textures = clouds::tools::readTextures(first);
    const auto& impl = clouds::detail::ContextAccess::impl(first.context());
    const clouds::shader::CloudUniforms uniforms = impl.lastShadowUniforms();
    const glm::vec3 light = clouds::shader::shadowLightDirection(clouds::tools::sunDirection(pose));
    const std::vector<glm::vec3> points = groundPoints(pose);
    std::vector<double> truth;
    for (const glm::vec3& p : points) {
      truth.push_back(
          std::exp(-clouds::tools::cpuSunOpticalDepth(textures, uniforms, p, light, 10.0f)));
    }
    results.points = points.size();
    for (Instance& instance : instances) {
      const clouds::tools::ShadowMapImage map = instance.harness->readShadowMap();
      double squared = 0.0;
      double absolute = 0.0;
      double worst = 0.0;
      double nearAbsolute = 0.0;
      int near = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double d = std::abs(double(map.transmittance(points[i])) - truth[i]);
        squared += d * d;
        absolute += d;
        worst = std::max(worst, d);
        if (glm::length(glm::vec2(points[i].x, points[i].z)) <= 10000.0f) {
          nearAbsolute += d;
          ++near;
        }
      }
      ShadowMeasurement m;
      m.config = instance.config->name;
      m.view = view.name;
      m.meanMs = mean(instance.cycleMs);
      m.cutMs = instance.cutMs;
      const double rms = std::sqrt(squared / double(points.size()));
      m.psnr = rms > 0.0 ? std::min(200.0, -20.0 * std::log10(rms)) : 200.0;
      m.meanAbs = absolute / double(points.size());
      m.maxAbs = worst;
      m.nearMeanAbs = near > 0 ? nearAbsolute / near : 0.0;
      // Full strength until the last cascade's blend band: 0.4 of its side from its middle.
      const std::uint32_t cascades = instance.settings.shadowCascades;
      m.reachKm =
          cascades == 0
              ? 0.0
              : 0.4 * clouds::detail::cascadeSideMetres(instance.settings, cascades - 1) / 1000.0;
      results.measurements.push_back(m);
      char line[200];
      std::snprintf(line, sizeof(line),
                    "shadow map, %s, %s: %.2f ms a frame (%.2f at a cut), %.1f dB, mean |dT| %.3f",
                    view.name.c_str(), m.config.c_str(), m.meanMs, m.cutMs, m.psnr, m.meanAbs);
      progress(line);
    }
  }
  return results;
}

}  // namespace bench
