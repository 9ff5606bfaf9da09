#pragma once
// The module's compute programs as one table: each pass's shader, its descriptor bindings
// (slots from cloud_types.h) and its push-constant block. Programs without specialization
// constants are prepared with the table; the march, reconstruction and upsample variants a
// Settings selects are prepared by Context::prepare().
#include <array>
#include <cstdint>
#include <memory>

#include "kit.h"

namespace clouds::detail {

enum class Program : std::uint32_t {
  ShapeNoise,       // noise_shape.comp: 128^3 low-frequency Perlin-Worley + Worley fBm
  DetailNoise,      // noise_detail.comp: 32^3 high-frequency Worley fBm
  CurlNoise,        // noise_curl.comp: 128^2 curl noise
  NoiseMip,         // noise_mip.comp: one level of a 3D noise's mip chain
  Weather,          // weather_procedural.comp: rows of the procedural weather map
  WeatherResample,  // weather_resample.comp: the host's painted map into the module's
  WeatherMaxima,    // weather_max.comp: one level of the empty-space-skipping grid
  SkyAmbient,       // sky_ambient.comp: ambient colours from the host's sky image
  SkyLight,         // sky_light.comp: the sky light's map from the host's sky and the clouds
  SceneDistance,    // depth_downsample.comp: conservative scene distance at trace resolution
  March,            // cloud_march.comp: the ray-march, one pixel per tile
  Reconstruct,      // reconstruct.comp: temporal reconstruction at trace resolution
  NearResolve,      // near_field_resolve.comp: the near field's temporal resolve
  Upsample,         // upsample.comp: depth-aware (and temporal) upsampling to the output
  Composite,        // composite.comp: the clouds over the host's colour
  ShadowMap,        // cloud_shadow_map.comp: one cascade of the cloud shadow map
  TerrainShadow,    // terrain_shadow_map.comp: the terrain's channel of one cascade
  GodRayOcclusion,  // god_ray_occlusion.comp: what hides the sun, a quarter of the output
  GodRays,          // god_rays.comp: the god-ray mask (its radial blur)
  LightningBolts,   // lightning_bolts.comp: this frame's bolts into the radiance output
  HeroLight,        // hero_light_volume.comp: hero clouds' light volume, swept when due
  HeroNoise,        // hero_noise.comp: level 0 of the hero clouds' 128^3 detail noise
  HeroNoiseMip,     // hero_noise_mip.comp: one level of its mip chain
  Count
};

class Programs {
 public:
  // `composite`: whether the composite helper exists (CreateInfo::compositeColorFormat).
  Programs(const DeviceContext& device, bool composite);

  ComputeProgram& operator[](Program program) { return *programs_[index(program)]; }
  const ComputeProgram& operator[](Program program) const { return *programs_[index(program)]; }
  bool has(Program program) const { return programs_[index(program)] != nullptr; }

 private:
  static std::size_t index(Program program) { return static_cast<std::size_t>(program); }
  std::array<std::unique_ptr<ComputeProgram>, static_cast<std::size_t>(Program::Count)> programs_;
};

}  // namespace clouds::detail
