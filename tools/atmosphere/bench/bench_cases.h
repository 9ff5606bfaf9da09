#pragma once
// What the atmosphere benchmark measures: the views (a camera, a sun, the ground the host drew)
// and the configurations (the quality presets, and one-knob sweeps around Medium), and how an
// image's error is scored against the converged Reference.
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "atmosphere_harness.h"

namespace atmosphere::bench {

struct View {
  std::string name;
  tools::SkyView sky;
};

struct Config {
  std::string name;   // e.g. "Medium", "sky-view samples 24"
  std::string sweep;  // the knob a sweep varies; empty for a preset
  bool preset = false;
  Settings settings;
};

std::vector<View> benchmarkViews();
// Low, Medium, High, then each sweep's values around Medium (Medium itself starts each sweep).
std::vector<Config> benchmarkConfigs();

// PSNR (dB) of `image` against `reference` after the same display mapping for both: exposed so
// that the reference's mean luminance maps to 0.18, then x / (1 + x) per channel (the sun's
// disc, thousands of times brighter than the sky, would otherwise be the whole peak).
double displayPsnr(const tools::FloatImage& image, const tools::FloatImage& reference);

}  // namespace atmosphere::bench
