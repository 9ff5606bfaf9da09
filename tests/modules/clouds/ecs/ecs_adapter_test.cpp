// The clouds' ECS adapter without a GPU: the frame inputs come from the world's camera, sun,
// sky and time in one function, each camera's CloudQuality preset decides the settings it
// renders with, and the module installs only where it can run.
#include <gtest/gtest.h>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_frame.h"
#include "clouds/ecs/clouds_module.h"
#include "engine/ecs/app.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "engine/render/render_feature.h"
#include "engine/render/scene_components.h"

namespace {

struct AdapterWorld {
  engine::ecs::World world;
  engine::ecs::Entity camera;
  clouds::Settings look;
  AdapterWorld() {
    world.ctx().emplace<engine::ecs::FrameTime>();
    look.coverage = 0.81f;
    look.cloudType = 0.3f;
    world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{look, 1, {}});
    camera = world.create();
    engine::render::Camera c;
    c.position = {10.0, 2000.0, -30.0};
    world.emplace<engine::render::Camera>(camera, c);
  }
};

clouds::ecs::HostFrame hostFrame() {
  clouds::ecs::HostFrame host;
  host.extent = {320, 180};
  host.frameIndex = 7;
  return host;
}

// Each frame draws the hero clouds nearest the camera, as many as the module takes.
TEST(CloudsEcsAdapter, TheNearestHeroCloudsAreDrawn) {
  AdapterWorld w;
  for (int i = 0; i < 12; ++i) {
    clouds::HeroCloud cloud;
    cloud.asset = static_cast<std::uint32_t>(i);
    // Alternately far and near, so the order of creation is not the order of distance.
    cloud.positionMetres = {(i % 2 == 0 ? 1000.0 : -100.0) * (i + 1), 2000.0, 0.0};
    w.world.emplace<clouds::HeroCloud>(w.world.create(), cloud);
  }
  const glm::dvec3 camera(0.0, 2000.0, 0.0);
  const std::vector<clouds::HeroCloud> drawn =
      clouds::ecs::heroClouds(w.world, camera, clouds::kMaxHeroClouds);
  ASSERT_EQ(drawn.size(), clouds::kMaxHeroClouds);
  for (std::size_t i = 1; i < drawn.size(); ++i) {
    EXPECT_LE(glm::length(drawn[i - 1].positionMetres - camera),
              glm::length(drawn[i].positionMetres - camera));
  }
  // The six near ones (odd, 100-1200 m) and the two nearest far ones (1 and 3 km).
  EXPECT_EQ(drawn.front().asset, 1u);
  EXPECT_EQ(drawn.back().positionMetres.x, 3000.0);
  EXPECT_TRUE(clouds::ecs::heroClouds(w.world, camera, 0).empty());
}

// A hero cloud with a lifecycle lives it on the frame's clock; while it is not there (before
// it grows, after it dissipates) it takes no place among the nearest.
TEST(CloudsEcsAdapter, HeroCloudsLiveTheirLifecycles) {
  AdapterWorld w;
  clouds::HeroCloud near;
  near.asset = 1;
  near.positionMetres = {0.0, 2000.0, -500.0};
  const engine::ecs::Entity living = w.world.create();
  w.world.emplace<clouds::HeroCloud>(living, near);
  clouds::HeroCloudLifecycle life;
  life.startSeconds = 10.0;
  life.growSeconds = 20.0f;
  life.matureSeconds = 30.0f;
  life.dissipateSeconds = 40.0f;
  life.repeat = false;
  w.world.emplace<clouds::HeroCloudLifecycle>(living, life);
  clouds::HeroCloud far = near;
  far.asset = 2;
  far.positionMetres.z = -9000.0;
  w.world.emplace<clouds::HeroCloud>(w.world.create(), far);

  const glm::dvec3 camera(0.0, 2000.0, 0.0);
  auto& time = w.world.ctx().get<engine::ecs::FrameTime>();
  const auto drawnAt = [&](double seconds) {
    time.elapsedSeconds = seconds;
    return clouds::ecs::heroClouds(w.world, camera, 1);
  };
  EXPECT_EQ(drawnAt(5.0).front().asset, 2u);  // not yet there: the far one is the nearest
  std::vector<clouds::HeroCloud> drawn = drawnAt(15.0);
  EXPECT_EQ(drawn.front().asset, 1u);
  EXPECT_FLOAT_EQ(drawn.front().growth, 0.25f);
  drawn = drawnAt(80.0);
  EXPECT_EQ(drawn.front().growth, 1.0f);
  EXPECT_FLOAT_EQ(drawn.front().dissipation, 0.5f);
  EXPECT_EQ(drawnAt(200.0).front().asset, 2u);  // dissipated
  // One without a lifecycle is as authored.
  EXPECT_EQ(drawnAt(200.0).front().growth, 1.0f);
  EXPECT_EQ(drawnAt(200.0).front().dissipation, 0.0f);

  // A lifecycle out of range: not drawn, and the problem named.
  w.world.get<clouds::HeroCloudLifecycle>(living).growSeconds = 0.0f;
  time.elapsedSeconds = 15.0;
  std::string problem;
  drawn = clouds::ecs::heroClouds(w.world, camera, 1, &problem);
  EXPECT_EQ(drawn.front().asset, 2u);
  EXPECT_NE(problem.find("HeroCloudLifecycle.growSeconds"), std::string::npos) << problem;
}

TEST(CloudsEcsAdapter, TheCamerasPresetDecidesTheSettings) {
  AdapterWorld w;
  clouds::Settings settings = clouds::ecs::cloudSettings(w.world);
  EXPECT_EQ(settings.maxViewSteps, w.look.maxViewSteps) << "no preset: the layer as it is";
  EXPECT_EQ(settings.coverage, w.look.coverage);

  w.world.emplace<clouds::ecs::CloudQuality>(w.camera,
                                             clouds::ecs::CloudQuality{clouds::Quality::Ultra});
  settings = clouds::ecs::cloudSettings(w.world);
  const clouds::Settings ultra = clouds::settingsFor(clouds::Quality::Ultra, w.look);
  EXPECT_EQ(settings.maxViewSteps, ultra.maxViewSteps);
  EXPECT_EQ(settings.traceScale, ultra.traceScale);
  EXPECT_EQ(settings.coverage, w.look.coverage) << "the preset keeps the layer's look";
  EXPECT_EQ(settings.cloudType, w.look.cloudType);

  w.world.get<clouds::ecs::CloudQuality>(w.camera).preset = clouds::Quality::Low;
  settings = clouds::ecs::cloudSettings(w.world);
  EXPECT_EQ(settings.traceScale, clouds::settingsFor(clouds::Quality::Low).traceScale);
}

TEST(CloudsEcsAdapter, TheInputsComeFromTheWorldAndTheHostFrame) {
  AdapterWorld w;
  const engine::ecs::Entity sun = w.world.create();
  engine::render::Sun s;
  s.direction = glm::normalize(glm::dvec3(0.2, 0.7, -0.4));
  s.illuminance = glm::vec3(9.0f, 8.0f, 7.0f);
  w.world.emplace<engine::render::Sun>(sun, s);
  engine::render::SkyLight sky;
  sky.zenith = glm::vec3(0.1f, 0.2f, 0.6f);
  w.world.ctx().emplace<engine::render::SkyLight>(sky);
  auto& time = w.world.ctx().get<engine::ecs::FrameTime>();
  time = time.next(0.5);

  const clouds::FrameInputs in = clouds::ecs::cloudFrameInputs(w.world, hostFrame());
  const auto& camera = w.world.get<engine::render::Camera>(w.camera);
  EXPECT_EQ(in.cameraPosition, glm::dvec3(10.0, 2000.0, -30.0));
  EXPECT_EQ(in.view, engine::render::viewRotation(camera));
  EXPECT_EQ(in.projection, engine::render::projectionOf(camera, 320.0f / 180.0f))
      << "the projection the renderer draws the scene with";
  EXPECT_EQ(in.renderExtent.width, 320u);
  EXPECT_EQ(in.frameIndex, 7u);
  EXPECT_EQ(in.sunDirection, glm::vec3(s.direction));
  EXPECT_EQ(in.sunIlluminance, s.illuminance);
  EXPECT_EQ(in.ambientTop, sky.zenith);
  EXPECT_DOUBLE_EQ(in.timeSeconds, 0.5);
  EXPECT_FALSE(in.reset);
  w.world.get<engine::render::Camera>(w.camera).cut = true;
  EXPECT_TRUE(clouds::ecs::cloudFrameInputs(w.world, hostFrame()).reset)
      << "a teleport is a camera cut";
}

// Changing weather (CloudWeather) decides the layer's look at the clock, over the layer's other
// settings, and the clouds drift as far as its wind has carried them.
TEST(CloudsEcsAdapter, TheWeatherAtTheClockDecidesTheLook) {
  AdapterWorld w;
  const clouds::WeatherKey keys[] = {
      {clouds::weatherPreset(clouds::WeatherPreset::Sparse), 10.0, 20.0},
      {clouds::weatherPreset(clouds::WeatherPreset::Overcast), 60.0, 0.0}};
  const clouds::WeatherTimeline weather = *clouds::WeatherTimeline::schedule(keys, false, nullptr);
  w.world.view<clouds::ecs::CloudLayer>().each(
      [&](engine::ecs::Entity layer, clouds::ecs::CloudLayer&) {
        w.world.emplace<clouds::ecs::CloudWeather>(layer, clouds::ecs::CloudWeather{weather});
      });
  auto& time = w.world.ctx().get<engine::ecs::FrameTime>();
  time.elapsedSeconds = 20.0;
  const clouds::Settings settings = clouds::ecs::cloudSettings(w.world);
  EXPECT_EQ(settings.coverage, weather.stateAt(20.0).coverage);
  EXPECT_EQ(settings.skewMetres, weather.stateAt(20.0).skewMetres);
  EXPECT_NE(settings.coverage, w.look.coverage);
  EXPECT_EQ(settings.typeVariation, w.look.typeVariation) << "not a weather field: the layer's";
  ASSERT_TRUE(clouds::ecs::currentWeather(w.world));
  const clouds::FrameInputs in = clouds::ecs::cloudFrameInputs(w.world, hostFrame());
  ASSERT_TRUE(in.windDisplacementMetres);
  EXPECT_EQ(*in.windDisplacementMetres, weather.windDisplacementAt(20.0));
}

// The weather's regions at the clock: each place with its own timeline's look now.
TEST(CloudsEcsAdapter, TheRegionsAtTheClockCarryTheirOwnWeather) {
  AdapterWorld w;
  EXPECT_TRUE(clouds::ecs::currentWeatherRegions(w.world).empty()) << "no weather, no regions";
  const clouds::WeatherKey keys[] = {
      {clouds::weatherPreset(clouds::WeatherPreset::Cloudy), 10.0, 20.0},
      {clouds::weatherPreset(clouds::WeatherPreset::Stormy), 60.0, 0.0}};
  clouds::WeatherRegion place;
  place.centreMetres = {-3000.0, 12000.0};
  place.halfSidesMetres = {9000.0f, 1000.0f};
  clouds::ecs::CloudWeather weather{clouds::WeatherTimeline{}};
  weather.regions.push_back(
      {"front", place, *clouds::WeatherTimeline::schedule(keys, false, nullptr)});
  w.world.view<clouds::ecs::CloudLayer>().each(
      [&](engine::ecs::Entity layer, clouds::ecs::CloudLayer&) {
        w.world.emplace<clouds::ecs::CloudWeather>(layer, weather);
      });
  w.world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds = 20.0;
  const std::vector<clouds::WeatherRegion> regions = clouds::ecs::currentWeatherRegions(w.world);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0], clouds::withWeather(place, weather.regions[0].timeline.stateAt(20.0)));
  EXPECT_NE(regions[0].coverage, clouds::weatherPreset(clouds::WeatherPreset::Cloudy).coverage)
      << "halfway into the storm";
}

TEST(CloudsEcsAdapter, TheSunReachesTheLayerThroughTheAirAndTheHostsHazeIsPassedOn) {
  AdapterWorld w;
  engine::render::Sun s;
  s.direction = glm::normalize(glm::dvec3(0.0, 0.2, 1.0));
  s.illuminance = glm::vec3(100.0f);
  w.world.emplace<engine::render::Sun>(w.world.create(), s);
  double askedAltitude = -1.0;
  w.world.ctx().emplace<engine::render::SunTransmittance>(
      engine::render::SunTransmittance{[&](double altitude, const glm::dvec3&) {
        askedAltitude = altitude;
        return glm::vec3(0.9f, 0.6f, 0.3f);
      }});
  clouds::ecs::HostFrame host = hostFrame();
  host.aerialPerspectiveView = reinterpret_cast<VkImageView>(std::uintptr_t{0x1234});
  host.aerialPerspectiveSlices = 32;
  host.aerialPerspectiveRangeMetres = 80000.0f;
  const clouds::FrameInputs in = clouds::ecs::cloudFrameInputs(w.world, host);
  const clouds::Settings layer = clouds::ecs::cloudSettings(w.world);
  EXPECT_DOUBLE_EQ(askedAltitude, 0.5 * (double(layer.layerBottomMetres) + layer.layerTopMetres))
      << "the sun as it reaches the middle of the layer";
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(in.sunIlluminance[c], glm::vec3(90.0f, 60.0f, 30.0f)[c]);
  }
  EXPECT_EQ(in.aerialPerspective.view, host.aerialPerspectiveView);
  EXPECT_EQ(in.aerialPerspective.slices, 32u);
  EXPECT_EQ(in.aerialPerspective.rangeMetres, 80000.0f);
  EXPECT_EQ(in.aerialPerspective.radianceScale, s.illuminance)
      << "the haze is in units of the sun above the air";
  EXPECT_EQ(clouds::ecs::cloudFrameInputs(w.world, hostFrame()).aerialPerspective.view,
            VK_NULL_HANDLE)
      << "no haze without the host's";
}

TEST(CloudsEcsAdapter, TheScenesGroundAlbedoLightsTheBasesFromBelow) {
  AdapterWorld w;
  engine::render::SkyLight sky;
  sky.horizon = glm::vec3(8.0f);
  sky.ground = glm::vec3(2.0f);
  w.world.ctx().emplaceOrReplace<engine::render::SkyLight>(sky);
  const clouds::FrameInputs without = clouds::ecs::cloudFrameInputs(w.world, hostFrame());
  EXPECT_FALSE(without.groundAlbedo) << "no ground known, no ground light";
  EXPECT_EQ(without.ambientBottom, glm::vec3(5.0f)) << "the horizon's and the ground's radiance";
  w.world.ctx().emplace<engine::render::GroundAlbedo>(
      engine::render::GroundAlbedo{glm::vec3(0.1f, 0.2f, 0.3f)});
  const clouds::FrameInputs in = clouds::ecs::cloudFrameInputs(w.world, hostFrame());
  ASSERT_TRUE(in.groundAlbedo);
  EXPECT_EQ(*in.groundAlbedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(in.ambientBottom, glm::vec3(8.0f)) << "the horizon's: the module adds the ground";
}

TEST(CloudsEcsAdapter, TheModuleNeedsACloudLayerAndARenderer) {
  clouds::ecs::CloudsModule module;
  engine::ecs::World world;
  std::string reason;
  EXPECT_FALSE(module.supported(world, reason));
  EXPECT_NE(reason.find("cloud layer"), std::string::npos) << reason;
  world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{});
  EXPECT_FALSE(module.supported(world, reason));
  EXPECT_NE(reason.find("RenderDevice"), std::string::npos) << reason;
  // An App skips it with a warning instead of failing: the scene runs without clouds.
  engine::ecs::App app;
  app.world().emplace<clouds::ecs::CloudLayer>(app.world().create(), clouds::ecs::CloudLayer{});
  EXPECT_FALSE(app.addModule<clouds::ecs::CloudsModule>());
  EXPECT_FALSE(app.world().ctx().has<engine::render::RenderFeatures>());
}

}  // namespace
