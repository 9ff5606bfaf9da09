// The clouds seen through the host's aerial perspective (FrameInputs::aerialPerspective): the
// output is the unhazed clouds attenuated by the air's transmittance and lit by its
// in-scattering at their transmittance-weighted depth, rgb * T_air + L_air * (1 - T_clouds),
// with the layout of fxcontracts/aerial_perspective.glsl; their transmittance is their own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/packing.hpp>

#include "cloud_gpu_fixture.h"
#include "engine/gfx/upload.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::cumulusView;
using test::kExtent;
using test::meanOpacity;
using CloudHaze = test::CloudGpuTest;

constexpr std::uint32_t kSlices = 16;
constexpr float kRangeMetres = 40000.0f;

// The synthetic air of slice s: transmittance falling and in-scattering rising with distance,
// the same across the screen (so only the distance decides what a pixel reads).
glm::vec4 airAtSlice(std::uint32_t s) {
  const float w = (float(s) + 0.5f) / float(kSlices);
  return glm::vec4(0.3f * w, 0.4f * w, 0.6f * w, 1.0f - 0.8f * w);
}

// The air at `distance` m as fxcontracts/aerial_perspective.glsl reads it: the slices interpolated
// linearly at w = sqrt(d / range), faded in before the first slice's centre.
glm::vec4 airAt(float distance) {
  const float w = std::sqrt(distance / kRangeMetres);
  const float position = std::clamp(w * kSlices - 0.5f, 0.0f, float(kSlices - 1));
  const auto below = static_cast<std::uint32_t>(position);
  const std::uint32_t above = std::min(below + 1, kSlices - 1);
  glm::vec4 air = glm::mix(airAtSlice(below), airAtSlice(above), position - float(below));
  const float weight = std::clamp(w * kSlices * 2.0f, 0.0f, 1.0f);
  return glm::vec4(glm::vec3(air) * weight, glm::mix(1.0f, air.a, weight));
}

engine::gfx::Image makeAir(engine::gfx::Device& device) {
  const VkExtent3D extent{4, 4, kSlices};
  engine::gfx::Image image(
      device, engine::gfx::ImageDesc{VK_IMAGE_TYPE_3D, VK_FORMAT_R16G16B16A16_SFLOAT, extent, 1, 1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     "synthetic air"});
  std::vector<std::uint16_t> texels;
  for (std::uint32_t s = 0; s < kSlices; ++s) {
    for (std::uint32_t i = 0; i < extent.width * extent.height; ++i) {
      const glm::vec4 air = airAtSlice(s);
      for (int c = 0; c < 4; ++c) texels.push_back(glm::packHalf1x16(air[c]));
    }
  }
  engine::gfx::uploadToImage(
      device, image, std::as_bytes(std::span(texels)),
      {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  return image;
}

TEST_F(CloudHaze, CloudsAreHazedAtTheirWeightedDepth) {
  const engine::gfx::Image volume = makeAir(device());
  const clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  const glm::vec3 scale(2.0f, 1.5f, 1.0f);
  CloudView view = cumulusView();
  auto clear = renderer();
  const CloudFrame clean = clear->render(view, settings, kExtent);
  view.aerialPerspective = {volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kSlices,
                            kRangeMetres, scale};
  auto hazy = renderer();
  const CloudFrame hazed = hazy->render(view, settings, kExtent);

  std::size_t cloudy = 0;
  float worst = 0.0f;
  for (std::size_t i = 0; i < clean.radiance.size(); ++i) {
    const glm::vec4 c = clean.radiance[i];
    const glm::vec4 air = airAt(clean.depth[i].y);
    const glm::vec3 expected = glm::vec3(c) * air.a + glm::vec3(air) * scale * (1.0f - c.a);
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst,
                       std::abs(hazed.radiance[i][k] - expected[k]) / std::max(expected[k], 0.05f));
    }
    EXPECT_EQ(hazed.radiance[i].a, c.a) << "the transmittance is the clouds' own";
    EXPECT_EQ(hazed.depth[i], clean.depth[i]);
    if (c.a < 0.5f) ++cloudy;
  }
  EXPECT_GT(cloudy, clean.radiance.size() / 20) << "the view must hold cloud";
  // Half-float outputs and the GPU's filtering weights: a few parts in a thousand.
  EXPECT_LT(worst, 0.01f);
}

// A host that does not read the cloud depth (Settings::depthOutput false) gets no depth
// image and the same radiance to the bit: the depths are still used inside (the haze reads the
// weighted one, the histories reproject through them); only their store is left out. Medium's
// upsample and High's temporal one each store the depth in their own place; the turning frames
// take High's reprojected history.
TEST_F(CloudHaze, WithoutTheDepthOutputTheHazedRadianceIsTheSame) {
  const engine::gfx::Image volume = makeAir(device());
  for (clouds::Quality quality : {clouds::Quality::Medium, clouds::Quality::High}) {
    SCOPED_TRACE(clouds::qualityName(quality));
    const clouds::Settings with = clouds::settingsFor(quality);
    clouds::Settings without = with;
    without.depthOutput = false;
    auto stored = renderer();
    auto left = renderer();
    CloudView view = cumulusView();
    view.aerialPerspective = {volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kSlices,
                              kRangeMetres, glm::vec3(1.0f)};
    CloudFrame a, b;
    for (int frame = 0; frame < 6; ++frame) {
      view.yawDegrees += frame < 3 ? 0.0 : 0.5;
      a = stored->render(view, with, kExtent);
      b = left->render(view, without, kExtent);
    }
    EXPECT_FALSE(a.depth.empty());
    EXPECT_TRUE(b.depth.empty()) << "no depth output to read back";
    EXPECT_EQ(left->context().outputs().depth.image, VkImage{VK_NULL_HANDLE});
    const std::uint64_t depthBytes =
        stored->memoryUsage().outputBytes - left->memoryUsage().outputBytes;
    EXPECT_GE(depthBytes, std::uint64_t{kExtent.width} * kExtent.height * 8) << "RG32F";
    EXPECT_LT(depthBytes, std::uint64_t{kExtent.width} * kExtent.height * 16);
    ASSERT_GT(meanOpacity(a), 0.002) << "the view must show clouds";
    ASSERT_EQ(a.radiance.size(), b.radiance.size());
    for (std::size_t i = 0; i < a.radiance.size(); ++i) {
      ASSERT_EQ(a.radiance[i], b.radiance[i]) << "pixel " << i;
    }
  }
}

TEST_F(CloudHaze, HazeAtTheFrontDepthWouldBeWrong) {
  // Negative control: the weighted depth is what the haze reads. Reading it at the first
  // cloud's distance instead changes thick, deep clouds measurably.
  const engine::gfx::Image volume = makeAir(device());
  const clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  CloudView view = cumulusView();
  view.aerialPerspective = {volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kSlices,
                            kRangeMetres, glm::vec3(1.0f)};
  auto hazy = renderer();
  const CloudFrame hazed = hazy->render(view, settings, kExtent);
  auto clear = renderer();
  view.aerialPerspective = {};
  const CloudFrame clean = clear->render(view, settings, kExtent);
  std::size_t differs = 0;
  for (std::size_t i = 0; i < clean.radiance.size(); ++i) {
    const glm::vec4 c = clean.radiance[i];
    if (c.a > 0.5f || clean.depth[i].y - clean.depth[i].x < 500.0f) continue;
    const glm::vec4 atFront = airAt(clean.depth[i].x);
    const float wrong = c.g * atFront.a + atFront.g * (1.0f - c.a);
    if (std::abs(wrong - hazed.radiance[i].g) > 0.02f * std::max(wrong, 0.05f)) ++differs;
  }
  EXPECT_GT(differs, 20u);
}

TEST_F(CloudHaze, BadHazeInputsAreRejected) {
  const engine::gfx::Image volume = makeAir(device());
  CloudView view = cumulusView();
  view.aerialPerspective = {volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kSlices, 0.0f,
                            glm::vec3(1.0f)};
  auto r = renderer();
  EXPECT_NE(r->tryRender(view, clouds::Settings{}, kExtent).find("aerialPerspective.rangeMetres"),
            std::string::npos);
  view.aerialPerspective.rangeMetres = kRangeMetres;
  view.aerialPerspective.slices = 0;
  EXPECT_NE(r->tryRender(view, clouds::Settings{}, kExtent).find("aerialPerspective.slices"),
            std::string::npos);
}

// A lightning bolt is hazed like the clouds, at its own distance: a bolt thinner than a pixel,
// 3 km ahead below the cloud, adds its energy times the air's transmittance there to the row
// that looks at it square on.
TEST_F(CloudHaze, BoltsAreHazedAtTheirDistance) {
  const engine::gfx::Image volume = makeAir(device());
  clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  settings.lightningBoltSegments = 1;
  CloudView view;
  view.pitchDegrees = 0.0;
  view.aerialPerspective = {volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kSlices,
                            kRangeMetres, glm::vec3(1.0f)};
  auto r = renderer();
  const CloudFrame without = r->render(view, settings, kExtent);
  clouds::LightningBoltSegment bolt;
  bolt.fromMetres = view.position + glm::dvec3(0.0, 200.0, -3000.0);
  bolt.toMetres = view.position + glm::dvec3(0.0, -200.0, -3000.0);
  bolt.radiance = glm::vec3(1e4f);
  bolt.widthMetres = 3.0f;
  view.lightningBolts = {bolt};
  const CloudFrame with = r->render(view, settings, kExtent);
  const std::uint32_t row = kExtent.height / 2;
  double gained = 0.0;
  for (std::uint32_t x = 0; x < kExtent.width; ++x) {
    const std::size_t i = std::size_t{row} * kExtent.width + x;
    gained += (double(with.radiance[i].r) - double(without.radiance[i].r));
  }
  const double pixelMetres =
      3000.0 * 2.0 * std::tan(glm::radians(double(view.verticalFovDegrees) / 2.0)) / kExtent.height;
  const double expected = 1e4 * 3.0 / pixelMetres * double(airAt(3000.0f).a);
  std::printf("hazed bolt: the row gains %.2f (expected %.2f, air transmittance %.3f)\n", gained,
              expected, double(airAt(3000.0f).a));
  EXPECT_NEAR(gained, expected, 0.02 * expected);
}

}  // namespace
