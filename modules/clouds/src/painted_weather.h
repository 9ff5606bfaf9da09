#pragma once
// The painted weather map a frame asks for (FrameInputs::weatherView, blended towards
// weatherBlendView by weatherBlend), and how much of the map moved between two frames: half the
// L1 distance between their weights over the images (0: the same map; 1: another one). A host
// blending one painting into another over seconds moves it a little each frame and keeps the
// history (TemporalState) and the shadow cascades (ShadowCascades); a swap at once does not.
#include <vulkan/vulkan.h>

#include "clouds/clouds.h"

namespace clouds::detail {

// The most of the map that may move in one frame with the history kept: as the settings' 1%.
inline constexpr float kPaintedWeatherTolerance = 0.01f;

struct PaintedWeather {
  VkImageView from = VK_NULL_HANDLE;  // null: the procedural map
  VkImageView to = VK_NULL_HANDLE;    // null: no blend
  float towards = 0.0f;               // [0, 1] the weight of `to`

  static PaintedWeather of(const FrameInputs& in);
};

float paintedWeatherChange(const PaintedWeather& a, const PaintedWeather& b);

}  // namespace clouds::detail
