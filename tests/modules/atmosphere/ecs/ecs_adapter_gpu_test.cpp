// The atmosphere's engine module on a real device: with a renderer's RenderDevice it installs,
// registers its render feature (which draws the sky), publishes the sun's transmittance through
// its air and an AtmosphereStatus; where it cannot run (a scene colour format it cannot write)
// it skips itself with a warning and publishes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere/ecs/atmosphere_module.h"
#include "engine/ecs/app.h"
#include "engine/render/render_feature.h"
#include "engine/render/scene_components.h"
#include "gpu_test.h"
#include "log_capture.h"

namespace {

using AtmosphereModuleOnDevice = test::GpuTest;

engine::render::RenderDevice renderDevice(engine::gfx::Device& device, VkFormat hdr) {
  return engine::render::RenderDevice{&device, hdr, VK_FORMAT_D32_SFLOAT, 2, {640, 360}};
}

TEST_F(AtmosphereModuleOnDevice, InstallsDrawsTheSkyAndPublishesTheSunThroughItsAir) {
  engine::ecs::App app;
  auto& world = app.world();
  world.ctx().emplace<engine::render::RenderDevice>(
      renderDevice(device(), VK_FORMAT_R16G16B16A16_SFLOAT));
  world.emplace<atmosphere::ecs::Atmosphere>(world.create(), atmosphere::ecs::Atmosphere{});
  ASSERT_TRUE(app.addModule<atmosphere::ecs::AtmosphereModule>());
  const auto& features = world.ctx().get<engine::render::RenderFeatures>().features;
  ASSERT_EQ(features.size(), 1u);
  EXPECT_STREQ(features[0]->name(), "atmosphere");
  EXPECT_TRUE(features[0]->drawsSky());
  EXPECT_TRUE(world.ctx().has<atmosphere::ecs::AtmosphereStatus>());

  // The published transmittance is the module's model: what the CPU reference integral gives.
  const auto* transmittance = world.ctx().tryGet<engine::render::SunTransmittance>();
  ASSERT_NE(transmittance, nullptr);
  const glm::dvec3 low = glm::normalize(glm::dvec3(1.0, 0.05, 0.0));
  const glm::vec3 expected = atmosphere::sunTransmittance(atmosphere::Parameters{}, 1000.0, low);
  const glm::vec3 published = transmittance->at(1000.0, low);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(published[c], expected[c], 1e-6f);
  EXPECT_GT(published.r, published.b) << "a low sun is reddened";
  EXPECT_EQ(transmittance->at(0.0, {0.0, -0.5, 0.0}), glm::vec3(0.0f)) << "set: no sun";
  // And the ground its sky is made with, for light bounced off it.
  const auto* ground = world.ctx().tryGet<engine::render::GroundAlbedo>();
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(ground->rgb, atmosphere::Parameters{}.groundAlbedo);
}

TEST_F(AtmosphereModuleOnDevice, ADeviceItCannotUseMakesItSkipItselfWithAWarning) {
  test::LogCapture log;
  const std::vector<std::string>& warnings = log.warnings;
  engine::ecs::App app;
  app.world().ctx().emplace<engine::render::RenderDevice>(
      renderDevice(device(), VK_FORMAT_R8G8B8A8_UNORM));
  app.world().emplace<atmosphere::ecs::Atmosphere>(app.world().create(),
                                                   atmosphere::ecs::Atmosphere{});
  EXPECT_FALSE(app.addModule<atmosphere::ecs::AtmosphereModule>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::RenderFeatures>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::SunTransmittance>());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("atmosphere"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("RGBA16F"), std::string::npos) << warnings[0];
  app.runFrame();  // the rest of the app runs on
}

}  // namespace
