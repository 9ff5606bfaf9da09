#include "god_rays.h"

#include <algorithm>
#include <cmath>

namespace clouds::detail {
namespace {

constexpr float kOffScreenFade = 0.5f;        // of the screen, beyond its edge
constexpr float kHorizonFadeSine = 0.01745f;  // sin(1 degree), either side of the horizon

float smoothstep01(float x) {
  const float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

GodRaySun godRaySun(const glm::mat4& view, const glm::mat4& projection,
                    const glm::vec3& sunDirection) {
  GodRaySun sun;
  const float length = glm::length(sunDirection);
  if (!(length > 1e-6f) || !std::isfinite(length)) return sun;
  const glm::vec3 towardsSun = sunDirection / length;
  // A direction: the sun is a point at infinity (w = 0), so only the view's rotation matters.
  const glm::vec4 clip = projection * (view * glm::vec4(towardsSun, 0.0f));
  if (!(clip.w > 1e-6f * glm::length(glm::vec3(clip)))) return sun;  // behind the camera
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  if (!std::isfinite(ndc.x) || !std::isfinite(ndc.y)) return sun;
  // Vulkan's clip space has y down the screen, as pixels.
  const glm::vec2 uv = ndc * 0.5f + 0.5f;
  const glm::vec2 outside = glm::max(glm::max(-uv, uv - 1.0f), glm::vec2(0.0f));
  const float offScreen = std::max(outside.x, outside.y);
  const float onScreen = 1.0f - smoothstep01(offScreen / kOffScreenFade);
  const float aboveHorizon =
      smoothstep01((towardsSun.y + kHorizonFadeSine) / (2.0f * kHorizonFadeSine));
  sun.uv = glm::clamp(uv, glm::vec2(-4.0f), glm::vec2(5.0f));
  sun.fade = onScreen * aboveHorizon;
  return sun;
}

}  // namespace clouds::detail
