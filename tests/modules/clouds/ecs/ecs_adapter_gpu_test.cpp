// The clouds' engine module on a real device: with a renderer's RenderDevice it installs,
// registers its render feature and publishes a CloudStatus; where the module cannot run (here:
// a scene colour format its composite cannot write) it skips itself with a warning and the
// app runs on without clouds.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/clouds_module.h"
#include "engine/ecs/app.h"
#include "engine/render/render_feature.h"
#include "gpu_test.h"
#include "log_capture.h"

namespace {

using CloudsModuleOnDevice = test::GpuTest;

// An app on `device` whose renderer's scene colour is `hdr`, with a cloud layer in its world:
// what the clouds' module needs to install itself.
void addRendererAndCloudLayer(engine::ecs::App& app, engine::gfx::Device& device, VkFormat hdr) {
  app.world().ctx().emplace<engine::render::RenderDevice>(
      engine::render::RenderDevice{&device, hdr, VK_FORMAT_D32_SFLOAT, 2, {640, 360}});
  app.world().emplace<clouds::ecs::CloudLayer>(app.world().create(), clouds::ecs::CloudLayer{});
}

TEST_F(CloudsModuleOnDevice, InstallsAndRegistersItsRenderFeature) {
  engine::ecs::App app;
  addRendererAndCloudLayer(app, device(), VK_FORMAT_R16G16B16A16_SFLOAT);
  ASSERT_TRUE(app.addModule<clouds::ecs::CloudsModule>());
  const auto& features = app.world().ctx().get<engine::render::RenderFeatures>().features;
  ASSERT_EQ(features.size(), 1u);
  EXPECT_STREQ(features[0]->name(), "clouds");
  EXPECT_TRUE(app.world().ctx().has<clouds::ecs::CloudStatus>());
}

// The engine reads the clouds' radiance only, so the feature asks for no depth output: its
// outputs are the RGBA16F radiance alone (the status reports the memory of the prepare before).
TEST_F(CloudsModuleOnDevice, AsksForNoDepthOutputItWouldNotRead) {
  engine::ecs::App app;
  addRendererAndCloudLayer(app, device(), VK_FORMAT_R16G16B16A16_SFLOAT);
  ASSERT_TRUE(app.addModule<clouds::ecs::CloudsModule>());
  engine::render::RenderFeature& clouds =
      *app.world().ctx().get<engine::render::RenderFeatures>().features.at(0);
  const VkExtent2D extent{320, 180};
  clouds.prepare(extent, 0);
  clouds.prepare(extent, 1);
  const std::uint64_t pixels = std::uint64_t{extent.width} * extent.height;
  const std::uint64_t outputs =
      app.world().ctx().get<clouds::ecs::CloudStatus>().memory.outputBytes;
  EXPECT_GE(outputs, pixels * 8) << "the radiance";
  EXPECT_LT(outputs, pixels * 16) << "and no RG32F depth beside it";
  device().waitIdle();
}

TEST_F(CloudsModuleOnDevice, ADeviceItCannotUseMakesItSkipItselfWithAWarning) {
  test::LogCapture log;
  const std::vector<std::string>& warnings = log.warnings;
  engine::ecs::App app;
  addRendererAndCloudLayer(app, device(), VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_FALSE(app.addModule<clouds::ecs::CloudsModule>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::RenderFeatures>());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("clouds"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("RGBA16F"), std::string::npos) << warnings[0];
  app.runFrame();  // the rest of the app runs on
}

}  // namespace
