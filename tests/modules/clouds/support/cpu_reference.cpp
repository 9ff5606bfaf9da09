#include "cpu_reference.h"

#include <thread>

#include "cloud_march.h"
#include "uniforms.h"

namespace clouds::shader {
namespace {
// Read-only while rendering; every worker thread samples the same texels.
const test::CpuTextures* gTextures = nullptr;

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

}  // namespace clouds::shader

namespace test {

using namespace clouds::shader;

CpuTextures readTextures(CloudHarness& harness) {
  return CpuTextures{harness.readShapeNoise(), harness.readDetailNoise(), harness.readCurlNoise(),
                     harness.readWeatherMap()};
}

CloudFrame renderCpuReference(const CpuTextures& textures, const CloudUniforms& u,
                              const clouds::Settings& settings, const std::vector<float>& depth,
                              unsigned threads) {
  gTextures = &textures;
  const clouds::detail::MarchVariant variant = clouds::detail::marchVariant(settings);
  MarchOptions options{variant.detail, variant.cheapSampling, variant.multipleScattering,
                       variant.lightSteps};
  CloudFrame frame;
  frame.extent = {u.extent.x, u.extent.y};
  const std::size_t pixels = std::size_t{u.extent.x} * u.extent.y;
  frame.radiance.resize(pixels);
  frame.depth.resize(pixels);
  auto work = [&](unsigned first) {
    for (std::size_t i = first; i < pixels; i += threads) {
      const uvec2 pixel(static_cast<uint>(i % u.extent.x), static_cast<uint>(i / u.extent.x));
      const vec2 centre = vec2(pixel) + 0.5f;
      const vec2 extent = vec2(u.extent.x, u.extent.y);
      const vec3 direction = pixelRayDirection(centre, extent, u);
      const float sceneDistance =
          sceneDistanceFromDepth(depth.empty() ? 0.0f : depth[i], centre, extent, u);
      const float jitter = rayJitter(pixel, u.frame.x, variant.jitter);
      const MarchResult r = marchClouds(direction, sceneDistance, jitter, u, options);
      frame.radiance[i] = vec4(r.radiance, r.transmittance);
      frame.depth[i] = vec2(r.frontDepth, r.weightedDepth);
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) workers.emplace_back(work, t);
  for (auto& w : workers) w.join();
  gTextures = nullptr;
  return frame;
}

}  // namespace test
