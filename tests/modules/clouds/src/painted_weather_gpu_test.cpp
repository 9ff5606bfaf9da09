// A painted weather map blended into another (FrameInputs::weatherBlendView, weatherBlend): the
// module's map is the mix of the two paintings, a blend eased over frames keeps the history
// (the frame report says the history was used) where a swap at once drops it, and bad blends are
// refused naming the field.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cloud_gpu_fixture.h"
#include "clouds/clouds.h"
#include "engine/gfx/upload.h"

namespace {

using clouds::tools::CloudView;
using PaintedWeatherBlend = test::SharedHarnessTest<64, 36>;
constexpr VkExtent2D kExtent{64, 36};
constexpr std::uint32_t kSide = 64;  // texels per side of the paintings

// A painting whose coverage is `coverage(x, y)`, cumulus at full density.
engine::gfx::Image paint(engine::gfx::Device& device,
                         std::uint8_t (*coverage)(std::uint32_t, std::uint32_t)) {
  engine::gfx::Image image(
      device, engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                     VK_FORMAT_R8G8B8A8_UNORM,
                                     {kSide, kSide, 1},
                                     1,
                                     1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     "painted weather"});
  std::vector<std::uint8_t> texels;
  for (std::uint32_t y = 0; y < kSide; ++y) {
    for (std::uint32_t x = 0; x < kSide; ++x) {
      texels.insert(texels.end(), {coverage(x, y), 200, 255, 255});
    }
  }
  engine::gfx::uploadToImage(device, image, std::as_bytes(std::span(texels)),
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  return image;
}

std::uint8_t stripes(std::uint32_t x, std::uint32_t) {
  return (x / 8) % 2 ? 230 : 40;
}
std::uint8_t rings(std::uint32_t x, std::uint32_t y) {
  const int dx = int(x) - 32, dy = int(y) - 32;
  return (dx * dx + dy * dy) / 64 % 2 ? 240 : 20;
}

TEST_F(PaintedWeatherBlend, TheMapIsTheMixOfThePaintings) {
  const engine::gfx::Image a = paint(device(), stripes);
  const engine::gfx::Image b = paint(device(), rings);
  CloudView view;
  view.weatherView = a.view();
  view.weatherBlendView = b.view();
  const clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  // The module's 512^2 map samples each painting at its texel centres: compare the mix of the
  // two maps made from each painting alone with the map made from the blend.
  const auto mapAt = [&](VkImageView only, VkImageView blendTo, float blend) {
    CloudView v = view;
    v.weatherView = only;
    v.weatherBlendView = blendTo;
    v.weatherBlend = blend;
    harness().render(v, settings, kExtent);
    return harness().readWeatherMap();
  };
  const std::vector<std::uint8_t> mapA = mapAt(a.view(), VK_NULL_HANDLE, 0.0f);
  const std::vector<std::uint8_t> mapB = mapAt(b.view(), VK_NULL_HANDLE, 0.0f);
  const std::vector<std::uint8_t> blended = mapAt(a.view(), b.view(), 0.25f);
  ASSERT_EQ(blended.size(), mapA.size());
  int worst = 0;
  for (std::size_t i = 0; i < blended.size(); ++i) {
    const double expected = 0.75 * mapA[i] + 0.25 * mapB[i];
    worst = std::max(worst, int(std::lround(std::abs(blended[i] - expected) + 0.49)));
  }
  EXPECT_LE(worst, 1) << "the map is not the paintings' mix";
  EXPECT_NE(blended, mapA);
}

TEST_F(PaintedWeatherBlend, AnEasedBlendKeepsTheHistoryAndASwapDropsIt) {
  const engine::gfx::Image a = paint(device(), stripes);
  const engine::gfx::Image b = paint(device(), rings);
  const clouds::Settings medium = clouds::settingsFor(clouds::Quality::Medium);
  CloudView view;
  view.pitchDegrees = 20.0;
  view.weatherView = a.view();
  harness().render(view, medium, kExtent, 4);
  view.weatherBlendView = b.view();
  for (int frame = 1; frame <= 200; ++frame) {
    view.weatherBlend = float(frame) / 200.0f;  // 0.5% a frame: 6.7 s at 30 fps
    harness().render(view, medium, kExtent);
    const clouds::FrameReport report = harness().context().lastFrameReport();
    ASSERT_TRUE(report.historyUsed) << "frame " << frame << ": " << report.resetReason;
  }
  view.weatherView = b.view();  // the blend ends: the second painting alone
  view.weatherBlendView = VK_NULL_HANDLE;
  view.weatherBlend = 0.0f;
  harness().render(view, medium, kExtent);
  EXPECT_TRUE(harness().context().lastFrameReport().historyUsed)
      << harness().context().lastFrameReport().resetReason;
  view.weatherView = a.view();  // back at once
  harness().render(view, medium, kExtent);
  EXPECT_FALSE(harness().context().lastFrameReport().historyUsed);
  EXPECT_EQ(std::string(harness().context().lastFrameReport().resetReason), "weather map changed");
}

TEST_F(PaintedWeatherBlend, BadBlendsAreRefusedNamingTheField) {
  const engine::gfx::Image a = paint(device(), stripes);
  const struct {
    VkImageView view;
    VkImageView blendView;
    float blend;
    const char* field;
  } cases[] = {{a.view(), a.view(), 1.5f, "FrameInputs.weatherBlend"},
               {a.view(), a.view(), std::nanf(""), "FrameInputs.weatherBlend"},
               {VK_NULL_HANDLE, a.view(), 0.5f, "FrameInputs.weatherBlendView"}};
  for (const auto& c : cases) {
    CloudView view;
    view.weatherView = c.view;
    view.weatherBlendView = c.blendView;
    view.weatherBlend = c.blend;
    const std::string error = harness().tryRender(view, clouds::Settings{}, kExtent);
    EXPECT_NE(error.find(c.field), std::string::npos) << "'" << error << "'";
  }
}

}  // namespace
