#include "bench_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace bench {

std::vector<BenchView> canonicalViews() {
  std::vector<BenchView> views;
  const auto add = [&](const char* name, clouds::tools::CloudView view, clouds::Settings look) {
    views.push_back(BenchView{name, view, look});
  };
  clouds::tools::CloudView ground;
  ground.position = {0.0, 300.0, 0.0};
  ground.pitchDegrees = 18.0;
  ground.yawDegrees = 270.0;
  ground.timeSeconds = 5.0;

  clouds::Settings clear;
  clear.coverage = 0.0f;
  add("clear sky", ground, clear);

  add("scattered cumulus", ground, clouds::Settings{});

  clouds::Settings overcast;
  overcast.coverage = 1.0f;
  overcast.cloudType = 0.15f;  // a stratus deck
  add("overcast", ground, overcast);

  clouds::tools::CloudView sunset = ground;
  sunset.pitchDegrees = 8.0;
  sunset.sunElevationDegrees = 3.0;
  sunset.sunAzimuthDegrees = 300.0;  // low in front of the camera, a little to the side
  sunset.sunIlluminance = {9.0f, 5.0f, 2.5f};
  sunset.ambientTop = {0.25f, 0.3f, 0.5f};
  sunset.ambientBottom = {0.3f, 0.2f, 0.15f};
  clouds::Settings stratocumulus;
  stratocumulus.coverage = 0.6f;
  stratocumulus.cloudType = 0.5f;
  add("sunset", sunset, stratocumulus);

  clouds::tools::CloudView inside = ground;
  inside.position.y = 2300.0;
  inside.pitchDegrees = 0.0;
  clouds::Settings dense;
  dense.coverage = 0.85f;
  add("inside a cloud", inside, dense);

  clouds::tools::CloudView above = ground;
  above.position.y = 6500.0;
  above.pitchDegrees = -25.0;
  add("above the layer", above, clouds::Settings{});

  // Where empty-space skipping should pay: sparse cumulus far below, the rays crossing long
  // empty stretches of the layer between them.
  clouds::Settings sparse;
  sparse.coverage = 0.4f;
  add("sparse cumulus from above", above, sparse);

  // Flying inside a tall cumulus layer, looking down through thin cloud at the ground: cloud
  // all around, near and far, and the ground (the host's depth) seen through it.
  clouds::tools::CloudView insideLayer = ground;
  insideLayer.position.y = 4000.0;
  insideLayer.pitchDegrees = -35.0;
  insideLayer.groundDepth = true;
  clouds::Settings tallLayer;
  tallLayer.coverage = 0.62f;
  tallLayer.cloudType = 0.85f;
  tallLayer.layerTopMetres = 7000.0f;
  add("inside the layer", insideLayer, tallLayer);

  // Near clouds: 300 m below the base, looking up at a cumulus a few hundred metres away (its
  // detail must survive the reduced trace).
  clouds::tools::CloudView nearCloud = ground;
  nearCloud.position.y = 1200.0;
  nearCloud.pitchDegrees = 40.0;
  nearCloud.yawDegrees = 90.0;
  clouds::Settings nearCumulus;
  nearCumulus.coverage = 0.6f;
  add("near cumulus", nearCloud, nearCumulus);
  return views;
}

FlyThrough flyThrough(std::uint32_t frames) {
  FlyThrough path;
  path.look.coverage = 0.65f;
  path.frames = frames;
  return path;
}

clouds::tools::CloudView FlyThrough::poseAt(std::uint32_t frame) const {
  const double t = double(frame) / framesPerSecond;
  clouds::tools::CloudView view;
  view.yawDegrees = 250.0 + 12.0 * t;  // a slow left turn
  const double yaw = view.yawDegrees * 3.14159265358979 / 180.0;
  // Forward along the yaw (yaw 0 looks along -Z), climbing: 1380 m, the base is at 1500 m.
  view.position = {-std::sin(yaw) * 150.0 * t, 1380.0 + 100.0 * t, -std::cos(yaw) * 150.0 * t};
  view.pitchDegrees = 10.0;
  view.timeSeconds = 5.0 + t;
  return view;
}

clouds::Settings BenchConfig::settingsFor(const clouds::Settings& look) const {
  clouds::Settings s = clouds::settingsFor(quality, look);
  if (adjust != nullptr) adjust(s, knob);
  return s;
}

namespace {

// High's value of each knob: where High sits in each sweep (a feature: 1 on, 0 off).
const std::map<std::string, double>& highKnobs() {
  static const std::map<std::string, double> knobs = [] {
    const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
    const auto on = [](bool feature) { return feature ? 1.0 : 0.0; };
    return std::map<std::string, double>{{"view step", 1.0},
                                         {"light steps", double(high.lightSteps)},
                                         {"trace scale", double(high.traceScale)},
                                         {"update interval", double(high.updateInterval)},
                                         {"temporal reuse", on(high.temporalReuse)},
                                         {"empty-space skipping", on(high.emptySpaceSkipping)},
                                         {"temporal upsampling", on(high.temporalUpsampling)},
                                         {"noise level of detail", on(high.noiseLevelOfDetail)},
                                         {"light reuse", on(high.lightEveryOtherStep)},
                                         {"edge rays", double(high.edgeRays)}};
  }();
  return knobs;
}

}  // namespace

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

bool selected(const std::vector<std::string>& only, const std::string& name) {
  return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
}

std::vector<BenchConfig> presetConfigs() {
  std::vector<BenchConfig> configs;
  for (clouds::Quality q : {clouds::Quality::Low, clouds::Quality::Medium, clouds::Quality::High,
                            clouds::Quality::Ultra}) {
    BenchConfig c;
    c.name = clouds::qualityName(q);
    c.preset = true;
    c.quality = q;
    configs.push_back(c);
  }
  return configs;
}

std::vector<BenchConfig> benchConfigs() {
  std::vector<BenchConfig> configs = presetConfigs();
  const auto sweep = [&](const char* knob, std::vector<double> values, const char* unit,
                         void (*adjust)(clouds::Settings&, double)) {
    for (double v : values) {
      BenchConfig c;
      c.sweep = knob;
      c.value = number(v) + unit;
      c.name = std::string(knob) + " " + c.value;
      c.adjust = adjust;
      c.knob = v;
      configs.push_back(c);
    }
  };
  // View steps: the step length (and its growth with distance) scaled by the factor, the step
  // budget by its inverse, so the same distance is covered with more or fewer samples.
  sweep("view step", {4.0, 2.0, 0.5, 0.25}, "x", [](clouds::Settings& s, double f) {
    s.viewStepMetres = float(s.viewStepMetres * f);
    s.viewStepGrowth = float(s.viewStepGrowth * f);
    s.maxViewSteps = std::uint32_t(std::lround(s.maxViewSteps / f));
  });
  sweep("light steps", {1.0, 2.0, 6.0, 10.0, 16.0}, "",
        [](clouds::Settings& s, double n) { s.lightSteps = std::uint32_t(n); });
  sweep("trace scale", {0.25, 1.0}, "",
        [](clouds::Settings& s, double scale) { s.traceScale = float(scale); });
  sweep("update interval", {4.0, 1.0}, "",
        [](clouds::Settings& s, double n) { s.updateInterval = std::uint32_t(n); });
  // A feature switched the other way from High's: one point, named "<feature> off" or
  // "<feature> on".
  const auto toggled = [&](const char* feature, void (*set)(clouds::Settings&, double)) {
    const bool highHasIt = highKnobs().at(feature) != 0.0;
    sweep(feature, {highHasIt ? 0.0 : 1.0}, "", set);
    configs.back().value = highHasIt ? "off" : "on";
    configs.back().name = std::string(feature) + " " + configs.back().value;
  };
  // Off: every pixel marched every frame with no history (what reuse saves).
  toggled("temporal reuse", [](clouds::Settings& s, double on) {
    s.temporalReuse = on != 0.0;
    if (!s.temporalReuse) s.updateInterval = 1;
  });
  toggled("empty-space skipping",
          [](clouds::Settings& s, double on) { s.emptySpaceSkipping = on != 0.0; });
  toggled("temporal upsampling",
          [](clouds::Settings& s, double on) { s.temporalUpsampling = on != 0.0; });
  toggled("noise level of detail",
          [](clouds::Settings& s, double on) { s.noiseLevelOfDetail = on != 0.0; });
  toggled("light reuse", [](clouds::Settings& s, double on) { s.lightEveryOtherStep = on != 0.0; });
  toggled("edge rays", [](clouds::Settings& s, double on) {
    s.edgeRays = on != 0.0 ? std::max(s.edgeRays, 2u) : 0u;
  });
  sweep("edge rays", {1.0}, "",
        [](clouds::Settings& s, double n) { s.edgeRays = std::uint32_t(n); });
  BenchConfig again;
  again.name = kHighTimedAgain;
  again.timingRepeat = true;
  configs.push_back(again);
  return configs;
}

std::vector<Sweep> sweepsOf(const std::vector<BenchConfig>& configs) {
  return sweepsOf(configs, clouds::Quality::High, highKnobs());
}

std::vector<Sweep> sweepsOf(const std::vector<BenchConfig>& configs, clouds::Quality base,
                            const std::map<std::string, double>& baseKnobs) {
  std::size_t baseIndex = 0;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    if (configs[i].preset && configs[i].quality == base) baseIndex = i;
  }
  std::vector<Sweep> sweeps;
  for (const auto& [name, baseValue] : baseKnobs) {
    std::vector<std::pair<double, std::size_t>> points = {{baseValue, baseIndex}};
    for (std::size_t i = 0; i < configs.size(); ++i) {
      if (configs[i].sweep == name) points.emplace_back(configs[i].knob, i);
    }
    if (points.size() < 2) continue;
    std::sort(points.begin(), points.end());
    Sweep sweep{name, {}};
    for (const auto& point : points) sweep.configs.push_back(point.second);
    sweeps.push_back(sweep);
  }
  return sweeps;
}

}  // namespace bench
