#pragma once
// The module's passes as its pass timer and Context::passTimings() name them.
#include <array>
#include <cstdint>

namespace clouds::detail {

enum class Pass : std::uint32_t {
  Noise,
  Weather,
  SkyAmbient,
  ClearSky,
  SceneDistance,
  March,
  Reconstruct,
  Upsample,
  ShadowMap,
  TerrainShadow,
  GodRays,
  Lightning,
  LightningBolts,
  HeroLight,
  HeroNoise,
  NearField,
  SkyLight,
  Count
};

inline constexpr std::array<const char*, static_cast<std::size_t>(Pass::Count)> kPassNames = {
    "noise",           "weather",    "sky ambient", "clear sky",      "scene distance", "march",
    "reconstruct",     "upsample",   "shadow map",  "terrain shadow", "god rays",       "lightning",
    "lightning bolts", "hero light", "hero noise",  "near field",     "sky light"};

constexpr std::uint32_t index(Pass pass) {
  return static_cast<std::uint32_t>(pass);
}

}  // namespace clouds::detail
