#pragma once
// The CPU reference renderer: the module's shared cloud model (shaders/cloud_march.h and the
// headers it includes) compiled as C++, sampling CPU copies of the very texels the GPU used.
// Given the same uniforms it computes what the march shader should have written.
#include <cstdint>
#include <optional>
#include <vector>

#include "cloud_harness.h"
#include "cloud_types.h"

namespace clouds::tools {

// Hero clouds as the march saw them: the atlas's texels (detail::packHeroAtlas()) and the
// frame's block (Context internals: lastHeroClouds()). Count 0: none.
struct CpuHeroClouds {
  std::vector<std::uint8_t> atlas;  // RGBA8, x fastest
  glm::uvec3 extent{0u};
  // The detail noise's chain (CloudHarness::readHeroNoise()); needed when the block's header
  // asks for detail (count.w).
  std::vector<std::uint8_t> noise;
  clouds::shader::HeroCloudUniforms uniforms{};
};

struct CpuTextures {
  std::vector<std::uint8_t> shape;    // 128 x 128 x 192 RGBA8: 128^3 and its mip chain
  std::vector<std::uint8_t> detail;   // 32 x 32 x 48 RGBA8: 32^3 and its mip chain
  std::vector<std::uint8_t> curl;     // 128^2 RGBA8
  std::vector<std::uint8_t> weather;  // 512^2 RGBA8
  // Empty-space-skipping maxima computed on the CPU from `weather` (see weatherMaxima).
  std::vector<std::uint8_t> weatherMaxFine;    // 64^2 RGBA8
  std::vector<std::uint8_t> weatherMaxCoarse;  // 8^2 RGBA8
  CpuHeroClouds heroes;
};

CpuTextures readTextures(CloudHarness& harness);

// The module's weather maxima on the CPU, with the shaders' own function
// (cloud_weather_maxima.h): each of the `targetSize`^2 cells holds the maximum R and G of the
// source texels it covers plus a one-texel apron, wrapping (B = 0, A = 255).
std::vector<std::uint8_t> weatherMaxima(const std::vector<std::uint8_t>& source, int sourceSize,
                                        int targetSize);

// Renders with the uniforms and options of a GPU frame. `depth`, when non-empty, holds the
// host depth values the GPU sampled (reversed-Z), one per pixel.
CloudFrame renderCpuReference(const CpuTextures& textures,
                              const clouds::shader::CloudUniforms& uniforms,
                              const clouds::Settings& settings, const std::vector<float>& depth,
                              unsigned threads = 2);

// What the march's sky-light pass (Settings::skyLight) should store for each texel of the sky
// light's upper half (kSkyLightWidth x kSkyLightHeight / 2, row-major, v = 0 at the zenith): the
// clouds' radiance and transmittance along its ray, with the uniforms and settings of a GPU
// frame (its ambient as the GPU's sky ambient pass left it: give the uniforms those values).
std::vector<glm::vec4> cpuSkyLightClouds(const CpuTextures& textures,
                                         const clouds::shader::CloudUniforms& uniforms,
                                         const clouds::Settings& settings, unsigned threads = 2);

// What cloud_shadow_map.comp should store at `texel` of the cascade a dispatch made with
// `constants` (Context internals: lastShadowUniforms(), lastShadowJobs()), before the RGBA16F
// rounding: the shared column march on the CPU.
glm::vec4 cpuShadowTexel(const CpuTextures& textures, const clouds::shader::CloudUniforms& uniforms,
                         const clouds::shader::ShadowMapConstants& constants, glm::uvec2 texel,
                         bool emptySpaceSkipping);

// The ground truth a shadow lookup approximates: the clouds' optical depth between a
// camera-relative point and the sun along `light`, marched in steps of `stepMetres` with the
// low-frequency shape (the model the shadow map and the light samples use), no skipping; the
// layer's alone.
double cpuSunOpticalDepth(const CpuTextures& textures,
                          const clouds::shader::CloudUniforms& uniforms, const glm::vec3& relative,
                          const glm::vec3& light, float stepMetres);

// The shared model's hero-cloud functions (cloud_hero.h, cloud_hero_light.h) read `textures`
// while one of these lives, on the thread that made it: for tests of the voxel model itself.
// With `lightSun` (world, unit, towards the sun), the light volume of the clouds in
// textures.heroes (their slots as the block's header gives them) is swept for that sun first,
// as hero_light_volume.comp sweeps it. No other CPU reference call may run meanwhile.
class CpuHeroScope {
 public:
  explicit CpuHeroScope(const CpuTextures& textures,
                        std::optional<glm::vec3> lightSun = std::nullopt);
  ~CpuHeroScope();
  CpuHeroScope(const CpuHeroScope&) = delete;
  CpuHeroScope& operator=(const CpuHeroScope&) = delete;

 private:
  std::vector<float> light_;
};

// A terrain heightfield on the CPU: altitudes (m), row-major, row 0 at the image's v = 0
// (world z = origin.y), read as a linear sampler clamped to the edge reads it.
struct CpuHeightfield {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> metres;
  float at(glm::vec2 uv) const;
};

// What terrain_shadow_map.comp should store in the alpha of `texel` of the cascade a dispatch
// made with `constants` (Context internals: lastTerrainShadowJobs()): the shared walk on the CPU.
float cpuTerrainShadowTexel(const CpuHeightfield& heightfield,
                            const clouds::shader::TerrainShadowConstants& constants,
                            glm::uvec2 texel);

// The ground truth of the terrain's shadow: whether the terrain (`heightfield` placed at the
// camera-relative corner `origin` with extent `size`, m) rises above the ray from the
// camera-relative point `relative` towards the sun along `light`, walked in `stepMetres`
// steps. `cameraAltitude` is the camera's altitude (m).
bool cpuTerrainHidesSun(const CpuHeightfield& heightfield, glm::vec2 origin, glm::vec2 size,
                        float cameraAltitude, const glm::vec3& relative, const glm::vec3& light,
                        float stepMetres);

}  // namespace clouds::tools
