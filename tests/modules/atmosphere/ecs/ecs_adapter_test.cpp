// The atmosphere's ECS adapter without a GPU: the frame inputs come from the world's camera and
// sun, the camera's AtmosphereQuality decides the settings, the measured sky becomes the
// engine's SkyLight, and the module installs only where there is an atmosphere and a renderer.
#include <gtest/gtest.h>

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere/ecs/atmosphere_frame.h"
#include "atmosphere/ecs/atmosphere_module.h"
#include "engine/ecs/app.h"
#include "engine/ecs/world.h"
#include "engine/render/camera_math.h"
#include "engine/render/render_feature.h"
#include "engine/render/scene_components.h"

namespace {

struct AdapterWorld {
  engine::ecs::World world;
  engine::ecs::Entity camera;
  AdapterWorld() {
    camera = world.create();
    engine::render::Camera c;
    c.position = {10.0, 2000.0, -30.0};
    world.emplace<engine::render::Camera>(camera, c);
  }
};

TEST(AtmosphereEcsAdapter, TheSceneGivesTheParametersAndTheCameraTheQuality) {
  AdapterWorld w;
  const atmosphere::Parameters earth;
  EXPECT_EQ(atmosphere::ecs::atmosphereParameters(w.world).mieScaleHeightMetres,
            earth.mieScaleHeightMetres)
      << "Earth without an Atmosphere";
  atmosphere::Parameters hazy;
  hazy.mieScaleHeightMetres = 1800.0f;
  w.world.emplace<atmosphere::ecs::Atmosphere>(w.world.create(), atmosphere::ecs::Atmosphere{hazy});
  EXPECT_EQ(atmosphere::ecs::atmosphereParameters(w.world).mieScaleHeightMetres, 1800.0f);

  const atmosphere::Settings medium = atmosphere::settingsFor(atmosphere::Quality::Medium);
  EXPECT_EQ(atmosphere::ecs::atmosphereSettings(w.world).skyViewWidth, medium.skyViewWidth);
  w.world.emplace<atmosphere::ecs::AtmosphereQuality>(
      w.camera, atmosphere::ecs::AtmosphereQuality{atmosphere::Quality::High});
  const atmosphere::Settings high = atmosphere::settingsFor(atmosphere::Quality::High);
  EXPECT_EQ(atmosphere::ecs::atmosphereSettings(w.world).skyViewWidth, high.skyViewWidth);
  EXPECT_EQ(atmosphere::ecs::atmosphereSettings(w.world).aerialPerspectiveSlices,
            high.aerialPerspectiveSlices);
}

TEST(AtmosphereEcsAdapter, TheInputsComeFromTheWorldAndTheHostFrame) {
  AdapterWorld w;
  engine::render::Sun sun;
  sun.direction = glm::normalize(glm::dvec3(0.2, 0.7, -0.4));
  sun.illuminance = glm::vec3(120.0f);
  w.world.emplace<engine::render::Sun>(w.world.create(), sun);
  const atmosphere::FrameInputs in =
      atmosphere::ecs::atmosphereFrameInputs(w.world, VK_NULL_HANDLE, {320, 180}, 9);
  const auto& camera = w.world.get<engine::render::Camera>(w.camera);
  EXPECT_EQ(in.cameraPosition, camera.position);
  EXPECT_EQ(in.view, engine::render::viewRotation(camera));
  EXPECT_EQ(in.projection, engine::render::projectionOf(camera, 320.0f / 180.0f))
      << "the projection the renderer draws the scene with";
  EXPECT_EQ(in.sunDirection, glm::vec3(sun.direction));
  EXPECT_EQ(in.sunIlluminance, sun.illuminance) << "above the air: the module applies its own";
  EXPECT_EQ(in.renderExtent.width, 320u);
  EXPECT_EQ(in.frameIndex, 9u);
}

TEST(AtmosphereEcsAdapter, TheMeasuredSkyBecomesTheScenesSkyLight) {
  atmosphere::SkyLighting measured;
  measured.zenith = {1.0f, 2.0f, 3.0f};
  measured.horizon = {4.0f, 5.0f, 6.0f};
  measured.lower = {0.1f, 0.2f, 0.3f};
  const engine::render::SkyLight sky = atmosphere::ecs::skyLightFrom(measured);
  EXPECT_EQ(sky.zenith, measured.zenith);
  EXPECT_EQ(sky.horizon, measured.horizon);
  EXPECT_EQ(sky.ground, measured.lower);
}

TEST(AtmosphereEcsAdapter, TheModuleNeedsAnAtmosphereAndARenderer) {
  atmosphere::ecs::AtmosphereModule module;
  engine::ecs::World world;
  std::string reason;
  EXPECT_FALSE(module.supported(world, reason));
  EXPECT_NE(reason.find("no atmosphere"), std::string::npos) << reason;
  world.emplace<atmosphere::ecs::Atmosphere>(world.create(), atmosphere::ecs::Atmosphere{});
  EXPECT_FALSE(module.supported(world, reason));
  EXPECT_NE(reason.find("RenderDevice"), std::string::npos) << reason;
  engine::ecs::App app;
  EXPECT_FALSE(app.addModule<atmosphere::ecs::AtmosphereModule>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::RenderFeatures>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::SunTransmittance>());
}

}  // namespace
