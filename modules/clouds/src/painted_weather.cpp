// How much of the painted weather map moved between two frames.
#include "painted_weather.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace clouds::detail {

namespace {

struct Weight {
  VkImageView view;
  float weight;
};

// A map's weights over at most two images (the procedural map is the null image).
std::array<Weight, 2> weightsOf(const PaintedWeather& p) {
  if (p.to == VK_NULL_HANDLE || p.to == p.from) return {{{p.from, 1.0f}, {p.from, 0.0f}}};
  return {{{p.from, 1.0f - p.towards}, {p.to, p.towards}}};
}

float weightIn(const std::array<Weight, 2>& weights, VkImageView view) {
  float sum = 0.0f;
  for (const Weight& w : weights) sum += w.view == view ? w.weight : 0.0f;
  return sum;
}

}  // namespace

PaintedWeather PaintedWeather::of(const FrameInputs& in) {
  PaintedWeather p;
  p.from = in.weatherView;
  if (in.weatherView != VK_NULL_HANDLE && in.weatherBlendView != VK_NULL_HANDLE) {
    p.to = in.weatherBlendView;
    p.towards = std::clamp(in.weatherBlend, 0.0f, 1.0f);
  }
  return p;
}

float paintedWeatherChange(const PaintedWeather& a, const PaintedWeather& b) {
  const std::array<Weight, 2> wa = weightsOf(a);
  const std::array<Weight, 2> wb = weightsOf(b);
  // Over every image either frame weighs (each counted once).
  float distance = 0.0f;
  const VkImageView views[] = {wa[0].view, wa[1].view, wb[0].view, wb[1].view};
  for (std::size_t i = 0; i < 4; ++i) {
    if (std::find(views, views + i, views[i]) != views + i) continue;
    distance += std::abs(weightIn(wa, views[i]) - weightIn(wb, views[i]));
  }
  return 0.5f * distance;
}

}  // namespace clouds::detail
