// The clouds' shadows on themselves over kilometres (Settings::cloudShadowsOnClouds): beyond a
// sample's light cone the march takes the sun's optical depth from the cloud shadow map. A cloud
// with a bank of cloud towards the sun, beyond its cone's reach, is darker than the same cloud
// alone, and only with the term; through a uniform slab the cone and the map together give the
// sun of a cone long enough to cross it (no seam where the one hands over to the other); without
// a map made this frame nothing changes. Validation-clean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "engine/gfx/upload.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;

using CloudOnCloudShadow = test::SharedHarnessTest<64, 64>;

constexpr VkExtent2D kExtent{64, 64};
constexpr std::uint32_t kMapSize = 64;
constexpr double kTileMetres = 16000.0;  // 250 m a texel

// A painted weather map (R coverage, G type, B density) of cumulonimbus where `cloud` says.
std::vector<std::uint8_t> paint(const auto& cloud) {
  std::vector<std::uint8_t> texels(kMapSize * kMapSize * 4, 0);
  for (std::uint32_t y = 0; y < kMapSize; ++y) {
    for (std::uint32_t x = 0; x < kMapSize; ++x) {
      // The world (x, z) metres of the texel's centre (the map tiles from the origin).
      const glm::dvec2 world((x + 0.5) / kMapSize * kTileMetres,
                             (y + 0.5) / kMapSize * kTileMetres);
      std::uint8_t* t = &texels[4 * (std::size_t{y} * kMapSize + x)];
      t[0] = cloud(world) ? 255 : 0;
      t[1] = 255;
      t[2] = 255;
      t[3] = 255;
    }
  }
  return texels;
}

class PaintedMap {
 public:
  PaintedMap(engine::gfx::Device& device, std::span<const std::uint8_t> texels)
      : image_(device,
               engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                      VK_FORMAT_R8G8B8A8_UNORM,
                                      {kMapSize, kMapSize, 1},
                                      1,
                                      1,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                      "painted clouds"}) {
    engine::gfx::uploadToImage(device, image_, std::as_bytes(texels),
                               engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  }
  VkImageView view() const { return image_.view(); }

 private:
  engine::gfx::Image image_;
};

// The sun 15 degrees up towards +x; the camera level with the middle of the layer, 6 km south
// of a lone cumulonimbus (500 m across, at x 4 km, z 8 km), looking north at it. A bank towards
// the sun (x 7 to 13 km, z 3 to 13 km) lies beyond the cone's 1.8 km from every sample of the
// cloud and out of the middle of the view: it changes the cloud only by the shade it casts.
CloudView sideView(VkImageView weather) {
  CloudView view;
  view.position = {4000.0, 2500.0, 14000.0};
  view.yawDegrees = 0.0;  // along -z
  view.pitchDegrees = 0.0;
  view.sunElevationDegrees = 15.0;
  view.sunAzimuthDegrees = 270.0;  // towards +x
  view.windDisplacementMetres = glm::dvec2(0.0);
  // The shadow map is made before each frame; a black ground lights no base either way.
  view.groundAlbedo = glm::vec3(0.0f);
  view.weatherView = weather;
  return view;
}

// Every pixel marched in the one frame (no reconstruction from a few rays).
clouds::Settings painted() {
  clouds::Settings s = clouds::tools::singleFrame({});
  s.weatherTileMetres = static_cast<float>(kTileMetres);
  s.coverage = 0.5f;  // the map as painted
  s.densityVariation = 0.0f;
  return s;
}

// The cloud's light in the middle columns of the view: the summed luminance of the pixels the
// lone cloud covers (transmittance below 0.9 in `alone`), in `frame`.
double cloudLight(const CloudFrame& frame, const CloudFrame& alone) {
  double sum = 0.0;
  for (std::uint32_t y = 0; y < frame.extent.height; ++y) {
    for (std::uint32_t x = 26; x < 38; ++x) {
      const std::size_t i = std::size_t{y} * frame.extent.width + x;
      if (alone.radiance[i].a > 0.9f) continue;
      const glm::vec4 p = frame.radiance[i];
      sum += 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
    }
  }
  return sum;
}

TEST_F(CloudOnCloudShadow, ABankTowardsTheSunBeyondTheConeDarkensACloud) {
  const auto cloud = [](glm::dvec2 w) {
    return glm::length(w - glm::dvec2(4000.0, 8000.0)) < 500.0;
  };
  // (Not north or south of the cloud: the view's rays past it never reach the bank.)
  const auto bank = [](glm::dvec2 w) {
    return w.x > 7000.0 && w.x < 13000.0 && std::abs(w.y - 8000.0) < 5000.0;
  };
  const PaintedMap alone(device(), paint(cloud));
  const PaintedMap withBank(device(), paint([&](glm::dvec2 w) { return cloud(w) || bank(w); }));
  const glm::vec3 sun = clouds::tools::sunDirection(sideView(VK_NULL_HANDLE));
  ASSERT_GT(sun.x, 0.95f) << "the sun towards +x";
  bool withMap = true;
  const auto render = [&](const PaintedMap& map, bool term) {
    clouds::Settings s = painted();
    s.cloudShadowsOnClouds = term;
    harness().cut();
    CloudView view = sideView(map.view());
    if (!withMap) view.groundAlbedo.reset();  // then render() makes no shadow map
    return harness().render(view, s, kExtent);
  };
  // The cloud's light with the bank over its light alone.
  const auto bankedOverAlone = [&](bool term) {
    const CloudFrame lone = render(alone, term);
    const CloudFrame banked = render(withBank, term);
    std::size_t covered = 0;
    for (std::uint32_t y = 0; y < kExtent.height; ++y) {
      for (std::uint32_t x = 26; x < 38; ++x) {
        covered += lone.radiance[std::size_t{y} * kExtent.width + x].a < 0.9f ? 1u : 0u;
      }
    }
    EXPECT_GT(covered, 20u) << "the lone cloud is in the middle of the view";
    return cloudLight(banked, lone) / cloudLight(lone, lone);
  };
  const double withTerm = bankedOverAlone(true);
  const double withoutTerm = bankedOverAlone(false);
  withMap = false;
  const double withoutMap = bankedOverAlone(true);
  std::printf(
      "cloud-on-cloud shadow: the cloud's light with the bank over without, %.3f with "
      "the term, %.3f without, %.3f without a shadow map\n",
      withTerm, withoutTerm, withoutMap);
  EXPECT_LT(withTerm, 0.85) << "the bank towards the sun shades the cloud";
  EXPECT_NEAR(withoutTerm, 1.0, 0.01) << "without the term the bank is beyond the cone's reach";
  EXPECT_NEAR(withoutMap, 1.0, 0.01) << "without a map this frame, the cone alone";
}

// A uniform slab, the sun 30 degrees up, seen from below: with a 1.8 km cone and the map beyond
// it, each sample's sun is that of a cone 20 km long (which crosses the slab: its quadrature of
// a constant density is exact); the short cone alone lets more through, and the two differ from
// the long cone by less than a tenth of that.
TEST_F(CloudOnCloudShadow, TheConeAndTheMapMeetWithoutASeam) {
  const DebugFlags homogeneous(clouds::shader::kFlagHomogeneous);
  clouds::Settings s;
  s.emptySpaceSkipping = false;  // the test slab ignores the weather map
  s.lightSteps = 32;             // the long cone's steps across the slab's top are short
  s.extinctionPerMetre = 1.0f / (s.layerTopMetres - s.layerBottomMetres);  // tau 1 straight up
  CloudView view;
  view.position = {0.0, 300.0, 0.0};
  view.pitchDegrees = 60.0;
  view.sunElevationDegrees = 30.0;
  view.groundAlbedo = glm::vec3(0.0f);
  const auto render = [&](float coneMetres, bool term) {
    clouds::Settings r = s;
    r.lightConeMetres = coneMetres;
    r.cloudShadowsOnClouds = term;
    harness().cut();
    const CloudFrame frame = harness().render(view, r, kExtent);
    double sum = 0.0;
    for (const glm::vec4& p : frame.radiance) sum += p.g;
    return sum;
  };
  const double longCone = render(20000.0f, false);
  const double coneAndMap = render(1800.0f, true);
  const double coneAlone = render(1800.0f, false);
  std::printf(
      "slab: sunlit radiance, 20 km cone %.4g, 1.8 km cone and the map %.4g, the cone "
      "alone %.4g\n",
      longCone, coneAndMap, coneAlone);
  EXPECT_GT(coneAlone / longCone, 1.03) << "the map's part of the shade is worth testing";
  EXPECT_LT(std::abs(coneAndMap - longCone), 0.1 * (coneAlone - longCone))
      << "the map gives what the long cone gives beyond the short one's end";
}

}  // namespace
