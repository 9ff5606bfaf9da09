#include "cpu_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "clamped_sampling.h"
#include "cloud_march.h"
#include "cloud_shadow_march.h"
#include "cloud_weather_maxima.h"
#include "fxcontracts/cloud_shadow.h"
#include "terrain_shadow_march.h"
#include "uniforms.h"

namespace clouds::shader {
namespace {
// Read-only while rendering; every worker thread samples the same texels.
const clouds::tools::CpuTextures* gTextures = nullptr;
// The hero clouds' light volume (cloud_hero_light.h) the reference swept for them, its extent.
std::vector<float>* gHeroLight = nullptr;
uint gHeroLightMode = kHeroLightCone;  // the render's Settings::heroLight
glm::uvec3 gHeroLightExtent{0u};
// The level weatherMaxima() reads (one thread).
const std::vector<std::uint8_t>* gMaximaSource = nullptr;
int gMaximaSourceSize = 0;

vec4 texel(const std::vector<std::uint8_t>& texels, std::size_t index) {
  const std::uint8_t* p = &texels[4 * index];
  return vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}
}  // namespace

vec4 fetchShapeNoise(ivec3 t) {
  const std::size_t n = kShapeNoiseSize;
  return texel(gTextures->shape, (std::size_t(t.z) * n + std::size_t(t.y)) * n + std::size_t(t.x));
}
vec4 fetchDetailNoise(ivec3 t) {
  const std::size_t n = kDetailNoiseSize;
  return texel(gTextures->detail, (std::size_t(t.z) * n + std::size_t(t.y)) * n + std::size_t(t.x));
}
vec4 fetchWeather(ivec2 t) {
  return texel(gTextures->weather, std::size_t(t.y) * kWeatherMapSize + std::size_t(t.x));
}
vec4 fetchCurl(ivec2 t) {
  return texel(gTextures->curl, std::size_t(t.y) * kCurlNoiseSize + std::size_t(t.x));
}
vec4 fetchWeatherMaxFine(ivec2 t) {
  return texel(gTextures->weatherMaxFine,
               std::size_t(t.y) * kWeatherMaxFineSize + std::size_t(t.x));
}
vec4 fetchMaximaSource(ivec2 t) {
  return texel(*gMaximaSource,
               std::size_t(t.y) * std::size_t(gMaximaSourceSize) + std::size_t(t.x));
}
vec4 fetchWeatherMaxCoarse(ivec2 t) {
  return texel(gTextures->weatherMaxCoarse,
               std::size_t(t.y) * kWeatherMaxCoarseSize + std::size_t(t.x));
}
uint heroCloudCount() {
  return gTextures != nullptr ? gTextures->heroes.uniforms.count.x : 0u;
}
bool heroLifeCompiledIn() {
  return true;  // the branch on each cloud's erosion gives the same result either way
}
HeroCloudInstance heroCloud(uint index) {
  return gTextures->heroes.uniforms.instance[index];
}
vec4 fetchHeroAtlas(ivec3 t) {
  const glm::uvec3 e = gTextures->heroes.extent;
  return texel(gTextures->heroes.atlas,
               (std::size_t(t.z) * e.y + std::size_t(t.y)) * e.x + std::size_t(t.x));
}
vec4 fetchHeroNoise(ivec3 t) {
  if (gTextures->heroes.noise.empty())
    throw std::logic_error("the CPU reference needs the hero clouds' detail noise (CpuHeroClouds)");
  const std::size_t n = kHeroNoiseSize;
  return texel(gTextures->heroes.noise,
               (std::size_t(t.z) * n + std::size_t(t.y)) * n + std::size_t(t.x));
}
vec4 heroNoiseMean() {
  return fetchHeroNoise(heroNoiseTexelAddress(kHeroNoiseLevels - 1, ivec3(0)));
}
uint heroLightMode() {
  return gHeroLightMode;
}
uvec4 heroCloudHeader() {
  return gTextures->heroes.uniforms.count;
}
float fetchHeroLight(ivec3 t) {
  const glm::uvec3 e = gHeroLightExtent;
  return (*gHeroLight)[(std::size_t(t.z) * e.y + std::size_t(t.y)) * e.x + std::size_t(t.x)];
}
void storeHeroLight(ivec3 t, float value) {
  const glm::uvec3 e = gHeroLightExtent;
  (*gHeroLight)[(std::size_t(t.z) * e.y + std::size_t(t.y)) * e.x + std::size_t(t.x)] = value;
}

// hero_light_volume.comp's sweep on the CPU: each instance's slot, slice by slice from the sun's
// side, with the shared function.
void sweepHeroLight(vec3 sunDirection) {
  const uvec4 header = heroCloudHeader();
  const glm::uvec3 slotExtent(header.z & 1023u, (header.z >> 10u) & 1023u, header.z >> 20u);
  gHeroLightExtent = 2u * slotExtent;
  gHeroLight->assign(std::size_t(gHeroLightExtent.x) * gHeroLightExtent.y * gHeroLightExtent.z,
                     0.0f);
  for (uint index = 0u; index < header.x; ++index) {
    const HeroCloudInstance h = heroCloud(index);
    const ivec3 size = heroLightSize(h);
    const ivec3 slotOrigin = heroLightSlotOrigin(index);
    const vec3 sun = heroSunIndexDirection(h, sunDirection);
    const int axis = heroLightAxis(sun);
    const int perSlice = size[(axis + 1) % 3] * size[(axis + 2) % 3];
    for (int s = 0; s < size[axis]; ++s) {
      for (int t = 0; t < perSlice; ++t) {
        const ivec3 j = heroLightSweepTexelAt(size, sun, axis, s, t);
        storeHeroLight(j + slotOrigin, heroLightSweepTexel(h, j, sun, axis, size, slotOrigin));
      }
    }
  }
}

// The reference marches without the host's terrain, and without a shadow map (its cone only).
float terrainSunLight(vec3, float) {
  return 1.0f;
}
float farCloudOpticalDepth(vec3, float) {
  return 0.0f;
}

// The heightfield cpuTerrainShadowTexel() walks over (one thread).
thread_local const clouds::tools::CpuHeightfield* tHeightfield = nullptr;
float fetchTerrainHeight(vec2 uv) {
  return tHeightfield->at(uv);
}

}  // namespace clouds::shader

namespace clouds::tools {

using namespace clouds::shader;

std::vector<std::uint8_t> weatherMaxima(const std::vector<std::uint8_t>& source, int sourceSize,
                                        int targetSize) {
  gMaximaSource = &source;
  gMaximaSourceSize = sourceSize;
  const int cell = sourceSize / targetSize;
  std::vector<std::uint8_t> maxima(std::size_t(4) * std::size_t(targetSize * targetSize), 0);
  for (int cy = 0; cy < targetSize; ++cy) {
    for (int cx = 0; cx < targetSize; ++cx) {
      const vec2 m = weatherCellMaxima(ivec2(cx, cy), sourceSize, cell);
      std::uint8_t* out = &maxima[4 * std::size_t(cy * targetSize + cx)];
      // As an RGBA8 storage image stores them: the maxima of UNORM texels are texels.
      out[0] = static_cast<std::uint8_t>(std::lround(m.x * 255.0f));
      out[1] = static_cast<std::uint8_t>(std::lround(m.y * 255.0f));
      out[3] = 255;
    }
  }
  return maxima;
}

CpuTextures readTextures(CloudHarness& harness) {
  CpuTextures textures{harness.readShapeNoise(),
                       harness.readDetailNoise(),
                       harness.readCurlNoise(),
                       harness.readWeatherMap(),
                       {},
                       {}};
  textures.heroes.noise = harness.readHeroNoise();
  textures.weatherMaxFine = weatherMaxima(textures.weather, kWeatherMapSize, kWeatherMaxFineSize);
  textures.weatherMaxCoarse =
      weatherMaxima(textures.weatherMaxFine, kWeatherMaxFineSize, kWeatherMaxCoarseSize);
  return textures;
}

CloudFrame renderCpuReference(const CpuTextures& textures, const CloudUniforms& u,
                              const clouds::Settings& settings, const std::vector<float>& depth,
                              unsigned threads) {
  gTextures = &textures;
  const clouds::detail::MarchVariant variant = clouds::detail::marchVariant(settings);
  MarchOptions options{variant.detail,     variant.cheapSampling, variant.multipleScattering,
                       variant.lightSteps, variant.emptySpace,    variant.lightReuse};
  gHeroLightMode = variant.heroLight;
  // The light volume the GPU swept for these clouds, swept again here (its slots: the block's).
  std::vector<float> heroLight;
  gHeroLight = &heroLight;
  if (variant.heroLight == kHeroLightVolume && heroCloudCount() > 0u)
    sweepHeroLight(u.sunDirection);
  CloudFrame frame;
  frame.extent = {u.traceExtent.x, u.traceExtent.y};
  const std::size_t pixels = std::size_t{u.traceExtent.x} * u.traceExtent.y;
  frame.radiance.resize(pixels);
  frame.depth.resize(pixels);
  auto work = [&](unsigned first) {
    for (std::size_t i = first; i < pixels; i += threads) {
      const uvec2 pixel(static_cast<uint>(i % u.traceExtent.x),
                        static_cast<uint>(i / u.traceExtent.x));
      const vec2 centre =
          vec2(pixel) + 0.5f + (variant.jitter == 2u ? u.subpixelOffset : vec2(0.0f));
      const vec2 extent = vec2(u.traceExtent.x, u.traceExtent.y);
      const vec3 direction = pixelRayDirection(centre, extent, u);
      const float sceneDistance =
          sceneDistanceFromDepth(depth.empty() ? 0.0f : depth[i], centre, extent, u);
      const float jitter = rayJitter(pixel, u.rayStartOffset, u.tileSize,
                                     (u.flags & kFlagRebuiltInsideCloud) != 0u, variant.jitter);
      const MarchResult r = marchClouds(direction, sceneDistance, jitter,
                                        lightJitter(u.lightRound, variant.jitter), u, options);
      frame.radiance[i] = vec4(r.radiance, r.transmittance);
      frame.depth[i] = vec2(r.frontDepth, r.weightedDepth);
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) workers.emplace_back(work, t);
  for (auto& w : workers) w.join();
  gTextures = nullptr;
  gHeroLight = nullptr;
  return frame;
}

std::vector<glm::vec4> cpuSkyLightClouds(const CpuTextures& textures, const CloudUniforms& frame,
                                         const clouds::Settings& settings, unsigned threads) {
  gTextures = &textures;
  CloudUniforms u = frame;
  u.cameraAltitudeMetres = skyLightAltitude(frame);
  const clouds::detail::MarchVariant variant = clouds::detail::marchVariant(settings);
  MarchOptions options{variant.detail,     variant.cheapSampling, variant.multipleScattering,
                       variant.lightSteps, variant.emptySpace,    variant.lightReuse,
                       kMarchWholeRay};
  gHeroLightMode = variant.heroLight;
  const uint width = kSkyLightWidth;
  const std::size_t texels = std::size_t{width} * (kSkyLightHeight / 2u);
  std::vector<glm::vec4> clouds(texels);
  auto work = [&](unsigned first) {
    for (std::size_t i = first; i < texels; i += threads) {
      const uvec2 texel(static_cast<uint>(i % width), static_cast<uint>(i / width));
      const MarchResult r = marchClouds(skyLightDirection(texel), kInfiniteDistance,
                                        skyLightJitter(texel, u.temporalIndex, variant.jitter),
                                        lightJitter(u.lightRound, variant.jitter), u, options);
      clouds[i] = vec4(r.radiance, r.transmittance);
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) workers.emplace_back(work, t);
  for (auto& w : workers) w.join();
  gTextures = nullptr;
  return clouds;
}

CpuHeroScope::CpuHeroScope(const CpuTextures& textures, std::optional<glm::vec3> lightSun) {
  gTextures = &textures;
  gHeroLight = &light_;
  if (lightSun && heroCloudCount() > 0u) sweepHeroLight(*lightSun);
}
CpuHeroScope::~CpuHeroScope() {
  gTextures = nullptr;
  gHeroLight = nullptr;
}

glm::vec4 cpuShadowTexel(const CpuTextures& textures, const CloudUniforms& u,
                         const ShadowMapConstants& c, glm::uvec2 texel, bool emptySpaceSkipping) {
  gTextures = &textures;
  const ShadowColumn column = marchShadowTexel(c, texel, emptySpaceSkipping ? 1u : 0u, u);
  gTextures = nullptr;
  return vec4(std::min(column.opticalDepth, fxcontracts::shader::kCloudShadowMaxDepth),
              column.frontAltitude, column.backAltitude, 1.0f);
}

float CpuHeightfield::at(glm::vec2 uv) const {
  return sampleLinearClamped(metres, width, height, uv);
}

float cpuTerrainShadowTexel(const CpuHeightfield& heightfield, const TerrainShadowConstants& t,
                            glm::uvec2 texel) {
  tHeightfield = &heightfield;
  const float top = terrainShadowTexel(t, texel);
  tHeightfield = nullptr;
  return top;
}

bool cpuTerrainHidesSun(const CpuHeightfield& heightfield, glm::vec2 origin, glm::vec2 size,
                        float cameraAltitude, const glm::vec3& relative, const glm::vec3& light,
                        float stepMetres) {
  float highest = -1e30f;
  for (float h : heightfield.metres) highest = std::max(highest, h);
  const float altitude = cameraAltitude + relative.y;
  // Walk until the ray clears the highest terrain or leaves the heightfield.
  for (float s = stepMetres; altitude + light.y * s <= highest; s += stepMetres) {
    const glm::vec2 p = glm::vec2(relative.x, relative.z) + glm::vec2(light.x, light.z) * s;
    const glm::vec2 uv = (p - origin) / size;
    if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) break;
    if (heightfield.at(uv) > altitude + light.y * s) return true;
  }
  return false;
}

double cpuSunOpticalDepth(const CpuTextures& textures, const CloudUniforms& u,
                          const glm::vec3& relative, const glm::vec3& light, float stepMetres) {
  gTextures = &textures;
  const double altitude = double(u.cameraAltitudeMetres) + double(relative.y);
  const double start = std::max(0.0, (double(u.layerBottomMetres) - altitude) / light.y);
  const double end = (double(u.layerTopMetres) - altitude) / light.y;
  double tau = 0.0;
  for (double t = start + 0.5 * stepMetres; t < end; t += stepMetres) {
    const vec3 p = relative + light * float(t);
    const FieldSample s =
        layerField(vec3(p.x, 0.0f, p.z), float(altitude + t * light.y), 0.0f, 0.0f, 0u, u);
    tau += double(s.sigmaT) * std::min(double(stepMetres), end - (t - 0.5 * stepMetres));
  }
  gTextures = nullptr;
  return tau;
}

}  // namespace clouds::tools
