#include "bench_cases.h"

#include <algorithm>
#include <cmath>

#include "engine/assets/image_metrics.h"
#include "engine/render/scene_components.h"

namespace atmosphere::bench {
namespace {

tools::SkyView sky(double altitude, double pitch, double sunElevation, double sunAzimuth,
                   bool ground) {
  tools::SkyView v;
  v.position = {0.0, altitude, 0.0};
  v.pitchDegrees = pitch;
  v.sunElevationDegrees = sunElevation;
  v.sunAzimuthDegrees = sunAzimuth;
  v.sunIlluminance = glm::vec3(127.0f);  // klx above the air, the sample's units
  v.groundDepth = ground;
  // A sunlit field of albedo 0.15 under a high sun (kcd/m^2); the haze in front is the test.
  v.groundColour = glm::vec3(4.0f, 4.5f, 3.0f);
  return v;
}

}  // namespace

std::vector<View> benchmarkViews() {
  return {
      {"noon, over the plain", sky(300.0, 4.0, 60.0, 160.0, true)},
      {"afternoon, looking down from 3 km", sky(3000.0, -12.0, 30.0, 120.0, true)},
      {"sunset, towards the sun", sky(500.0, 3.0, 2.0, 15.0, true)},
      {"twilight, sun 4 degrees down", sky(300.0, 12.0, -4.0, 20.0, false)},
      {"from 12 km", sky(12000.0, -8.0, 20.0, 200.0, true)},
  };
}

std::vector<Config> benchmarkConfigs() {
  std::vector<Config> configs;
  for (Quality q : {Quality::Low, Quality::Medium, Quality::High}) {
    configs.push_back({qualityName(q), "", true, settingsFor(q)});
  }
  const Settings medium = settingsFor(Quality::Medium);
  // One knob (one or two Settings fields set to the same value) at each value, around Medium.
  using Field = std::uint32_t Settings::*;
  const auto sweep = [&](const std::string& name, std::initializer_list<Field> fields,
                         std::initializer_list<std::uint32_t> values) {
    for (std::uint32_t value : values) {
      Settings s = medium;
      for (Field field : fields) s.*field = value;
      configs.push_back({name + " " + std::to_string(value), name, false, s});
    }
  };
  // A width and a height, named "WxH".
  const auto sweepSize = [&](const std::string& name, Field width, Field height,
                             std::initializer_list<std::pair<std::uint32_t, std::uint32_t>> sizes) {
    for (auto [w, h] : sizes) {
      Settings s = medium;
      s.*width = w;
      s.*height = h;
      configs.push_back({name + " " + std::to_string(w) + "x" + std::to_string(h), name, false, s});
    }
  };
  sweepSize("sky-view size", &Settings::skyViewWidth, &Settings::skyViewHeight,
            {{64u, 36u}, {128u, 72u}, {192u, 108u}, {256u, 144u}});
  sweep("sky-view samples", {&Settings::skyViewSamples}, {8u, 12u, 24u, 32u});
  sweep("froxels across", {&Settings::aerialPerspectiveWidth, &Settings::aerialPerspectiveHeight},
        {16u, 32u, 48u});
  sweep("froxel slices", {&Settings::aerialPerspectiveSlices}, {16u, 24u, 48u});
  sweep("samples per slice", {&Settings::aerialPerspectiveSamplesPerSlice}, {2u, 4u});
  sweep("transmittance samples", {&Settings::transmittanceSamples}, {10u, 20u, 80u});
  sweepSize("transmittance size", &Settings::transmittanceWidth, &Settings::transmittanceHeight,
            {{128u, 32u}, {512u, 128u}});
  sweep("multiple-scattering directions", {&Settings::multiScatteringDirections}, {4u, 16u});
  sweep("multiple-scattering samples", {&Settings::multiScatteringSamples}, {10u, 40u, 80u});
  sweep("multiple-scattering size", {&Settings::multiScatteringSize}, {16u, 64u});
  return configs;
}

double displayPsnr(const tools::FloatImage& image, const tools::FloatImage& reference) {
  double luminanceSum = 0.0;
  for (const glm::vec4& t : reference.texels) {
    luminanceSum += engine::render::luminance(glm::dvec3(t));
  }
  const double mean = luminanceSum / double(std::max<std::size_t>(reference.texels.size(), 1));
  const double exposure = 0.18 / std::max(mean, 1e-9);
  const auto display = [&](const tools::FloatImage& source) {
    std::vector<float> rgb;
    rgb.reserve(source.texels.size() * 3);
    for (const glm::vec4& t : source.texels) {
      for (int c = 0; c < 3; ++c) {
        const double x = std::max(double(t[c]), 0.0) * exposure;
        rgb.push_back(float(x / (1.0 + x)));
      }
    }
    return rgb;
  };
  return engine::assets::compareImages(display(image), display(reference), 3, 3).psnr(1.0);
}

}  // namespace atmosphere::bench
