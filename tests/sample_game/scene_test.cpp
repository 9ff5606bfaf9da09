// Scenes as data: every shipped scene loads, and malformed scenes are rejected with the file,
// the JSON path and the reason, before anything is created.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "atmosphere/ecs/atmosphere_components.h"
#include "engine/core/error.h"
#include "engine/ecs/app.h"
#include "scene/scene_description.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

namespace {

namespace fs = std::filesystem;
using sample::loadSceneDescription;

fs::path writeScene(const std::string& name, const std::string& json) {
  const fs::path dir = fs::temp_directory_path() / "cloudscape_scene_tests";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << json;
  return path;
}

std::string errorOf(const fs::path& path) {
  try {
    loadSceneDescription(path);
  } catch (const engine::Error& e) {
    return e.what();
  }
  return "";
}

TEST(Scenes, EveryShippedSceneLoads) {
  int count = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(CLOUDSCAPE_ASSET_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const sample::SceneDescription scene = loadSceneDescription(entry.path());
    EXPECT_FALSE(scene.name.empty()) << entry.path();
    EXPECT_TRUE(scene.terrain.has_value()) << entry.path();
    EXPECT_TRUE(scene.clouds.has_value()) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(Scenes, ValuesArriveInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("values.json", R"({
    "name": "v", "camera": {"position": [1, 2, 3], "yawDegrees": 45},
    "sun": {"timeOfDayHours": 18.5},
    "clouds": {"coverage": 0.3, "cloudType": 0.1,
               "wind": {"directionDegrees": 90, "speedMetresPerSecond": 20}}
  })"));
  EXPECT_EQ(s.camera.position, glm::dvec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(s.camera.yawDegrees, 45.0);
  EXPECT_DOUBLE_EQ(s.sun.timeOfDayHours, 18.5);
  ASSERT_TRUE(s.clouds.has_value());
  EXPECT_FLOAT_EQ(s.clouds->settings.coverage, 0.3f);
  EXPECT_FLOAT_EQ(s.clouds->settings.windSpeedMetresPerSecond, 20.0f);
  EXPECT_NEAR(s.clouds->settings.windDirection.y, -1.0f, 1e-6f);  // 90 degrees: towards -Z
  EXPECT_TRUE(s.clouds->settings.skyLight) << "the clouds light the world's ambient by default";
  const sample::SceneDescription unlit = loadSceneDescription(writeScene("unlit.json", R"({
    "name": "u", "camera": {"position": [0, 10, 0]}, "clouds": {"skyLight": false}})"));
  EXPECT_FALSE(unlit.clouds->settings.skyLight);
  EXPECT_FALSE(s.terrain.has_value());
  const sample::SceneDescription plain = loadSceneDescription(writeScene("plain.json", R"({
    "name": "p", "camera": {"position": [0, 10, 0]},
    "terrain": {"gltf": "default", "closeDetail": false}})"));
  ASSERT_TRUE(plain.terrain.has_value());
  EXPECT_FALSE(plain.terrain->closeDetail);
  EXPECT_NE(sample::sceneJson(plain).find("\"closeDetail\": false"), std::string::npos)
      << "the writer keeps it";
  const sample::SceneDescription detailed = loadSceneDescription(writeScene("detailed.json", R"({
    "name": "d", "camera": {"position": [0, 10, 0]}, "terrain": {"gltf": "default"}})"));
  EXPECT_TRUE(detailed.terrain->closeDetail) << "the ground's close-up detail by default";
  EXPECT_EQ(s.camera.cloudQuality, clouds::Quality::Medium) << "the default preset";
  const sample::SceneDescription ultra = loadSceneDescription(writeScene("quality.json", R"({
    "name": "q", "camera": {"position": [0, 10, 0], "cloudQuality": "ultra"}})"));
  EXPECT_EQ(ultra.camera.cloudQuality, clouds::Quality::Ultra);
  EXPECT_FALSE(s.camera.frameTargetMilliseconds.has_value()) << "the sample's default";
  const sample::SceneDescription governed = loadSceneDescription(writeScene("target.json", R"({
    "name": "q", "camera": {"position": [0, 10, 0], "frameTargetMilliseconds": 16.7}})"));
  EXPECT_EQ(governed.camera.frameTargetMilliseconds, 16.7);
  EXPECT_FALSE(s.camera.cloudKnobs.any()) << "the preset as it is";
  const fs::path knobbed = writeScene("knobs.json", R"({
    "name": "k", "camera": {"position": [0, 10, 0], "cloudQuality": "high",
                            "cloudKnobs": {"lightSteps": 2, "viewStepMetres": 50}}})");
  const sample::SceneDescription k = loadSceneDescription(knobbed);
  EXPECT_EQ(k.camera.cloudKnobs.lightSteps, std::optional<std::uint32_t>(2u));
  EXPECT_EQ(k.camera.cloudKnobs.viewStepMetres, std::optional<float>(50.0f));
  EXPECT_FALSE(k.camera.cloudKnobs.maxViewSteps.has_value());
  const std::string written = sample::sceneJson(k);
  EXPECT_EQ(sample::sceneJson(loadSceneDescription(writeScene("knobs_again.json", written))),
            written);
  EXPECT_FALSE(s.atmosphere.has_value()) << "no atmosphere unless the scene asks";
  EXPECT_FALSE(s.fog.has_value());
}

// Every shipped scene written back (scene_writer.h, what the settings panel saves) loads to
// the same description: written again, the very same JSON, and the fields the writer derives
// (the wind's direction, an atmosphere preset's parameters, a storm's cells found in the
// weather) equal to the bit.
TEST(Scenes, EveryShippedSceneWrittenBackLoadsTheSame) {
  int count = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(CLOUDSCAPE_ASSET_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const sample::SceneDescription original = loadSceneDescription(entry.path());
    const std::string written = sample::sceneJson(original);
    const fs::path copy = writeScene("written_" + entry.path().filename().string(), written);
    const sample::SceneDescription loaded = loadSceneDescription(copy);
    EXPECT_EQ(sample::sceneJson(loaded), written);
    if (original.clouds) {
      ASSERT_TRUE(loaded.clouds);
      EXPECT_EQ(loaded.clouds->settings.windDirection, original.clouds->settings.windDirection);
      EXPECT_EQ(loaded.clouds->settings.shadowCascades, original.clouds->settings.shadowCascades);
      EXPECT_EQ(loaded.clouds->settings.godRaySamples, original.clouds->settings.godRaySamples);
      EXPECT_EQ(loaded.clouds->settings.skyLight, original.clouds->settings.skyLight);
      EXPECT_EQ(loaded.clouds->heroClouds.size(), original.clouds->heroClouds.size());
    }
    if (original.atmosphere) {
      ASSERT_TRUE(loaded.atmosphere);
      EXPECT_EQ(loaded.atmosphere->parameters.mieScatteringPerMetre,
                original.atmosphere->parameters.mieScatteringPerMetre);
      EXPECT_EQ(loaded.atmosphere->parameters.mieScaleHeightMetres,
                original.atmosphere->parameters.mieScaleHeightMetres);
    }
    if (original.weather) {
      ASSERT_TRUE(loaded.weather);
      ASSERT_EQ(loaded.weather->schedule.keys.size(), original.weather->schedule.keys.size());
      for (std::size_t i = 0; i < original.weather->schedule.keys.size(); ++i) {
        EXPECT_EQ(loaded.weather->schedule.keys[i].state, original.weather->schedule.keys[i].state);
      }
      ASSERT_EQ(loaded.weather->regions.size(), original.weather->regions.size());
      for (std::size_t i = 0; i < original.weather->regions.size(); ++i) {
        const sample::RegionDescription& a = original.weather->regions[i];
        const sample::RegionDescription& b = loaded.weather->regions[i];
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.place, a.place);
        EXPECT_EQ(b.schedule.states, a.schedule.states);
        EXPECT_EQ(b.schedule.repeat, a.schedule.repeat);
      }
    }
    if (original.lightning) {
      ASSERT_TRUE(loaded.lightning);
      ASSERT_EQ(loaded.lightning->storm.cells.size(), original.lightning->storm.cells.size());
      for (std::size_t i = 0; i < original.lightning->storm.cells.size(); ++i) {
        EXPECT_EQ(loaded.lightning->storm.cells[i].positionMetres,
                  original.lightning->storm.cells[i].positionMetres);
      }
    }
    ++count;
  }
  EXPECT_GE(count, 6);
}

// A scene that does not give its ground's albedo takes its terrain's (meanTerrainAlbedo()),
// for the sky and the clouds' bases alike; one that gives it keeps it.
TEST(Scenes, TheAirSeesTheTerrainsGroundUnlessTheSceneGivesOne) {
  auto mesh = std::make_shared<engine::assets::MeshData>();
  mesh->positions = {{0, 0, 0}, {100, 0, 0}, {0, 0, 100}};
  mesh->normals.assign(3, glm::vec3(0, 1, 0));
  mesh->colors.assign(3, glm::vec4(0.05f, 0.08f, 0.03f, 1.0f));
  mesh->uvs.assign(3, glm::vec2(0.0f));
  mesh->indices = {0, 2, 1};
  mesh->boundsMin = {0, 0, 0};
  mesh->boundsMax = {100, 0, 100};
  const sample::LoadedTerrain terrain{"flat.gltf", mesh};
  const auto groundOf = [&](const char* atmosphere) {
    // The snowline above the flat ground: the mesh's own default would lie on it.
    const std::string json = R"({"name": "g", "camera": {"position": [0, 10, 0]},
        "terrain": {"gltf": "default", "snowlineMetres": 3000}, "atmosphere": )";
    const sample::SceneDescription scene =
        loadSceneDescription(writeScene("ground.json", json + atmosphere + "}"));
    engine::ecs::App app;
    sample::populateScene(app, scene, terrain);
    glm::vec3 ground(-1.0f);
    app.world().view<const atmosphere::ecs::Atmosphere>().each(
        [&](const atmosphere::ecs::Atmosphere& a) { ground = a.parameters.groundAlbedo; });
    return ground;
  };
  EXPECT_EQ(groundOf("{}"), glm::vec3(0.05f, 0.08f, 0.03f)) << "the terrain's grass";
  EXPECT_EQ(groundOf(R"({"groundAlbedo": [0.2, 0.2, 0.2]})"), glm::vec3(0.2f));
}

TEST(Scenes, AtmosphereFogAndExposureArriveInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("air.json", R"({
    "name": "a", "camera": {"position": [0, 10, 0], "atmosphereQuality": "high"},
    "atmosphere": {"preset": "hazy", "miePhaseG": 0.7, "groundAlbedo": [0.1, 0.2, 0.3]},
    "exposure": {"mode": "manual", "ev100": 12.5, "adaptationSeconds": 2}
  })"));
  ASSERT_TRUE(s.atmosphere.has_value());
  const atmosphere::Parameters earth;
  EXPECT_FLOAT_EQ(s.atmosphere->parameters.mieScatteringPerMetre.g,
                  4.0f * earth.mieScatteringPerMetre.g)
      << "the hazy preset";
  EXPECT_FLOAT_EQ(s.atmosphere->parameters.miePhaseG, 0.7f) << "an override over the preset";
  EXPECT_EQ(s.atmosphere->parameters.groundAlbedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_TRUE(s.atmosphere->groundAlbedoGiven);
  EXPECT_EQ(s.camera.atmosphereQuality, atmosphere::Quality::High);
  EXPECT_FALSE(s.exposure.automatic);
  EXPECT_DOUBLE_EQ(s.exposure.ev100, 12.5);
  EXPECT_DOUBLE_EQ(s.exposure.adaptationSeconds, 2.0);

  const sample::SceneDescription fogged = loadSceneDescription(writeScene("fog.json", R"({
    "name": "f", "camera": {"position": [0, 10, 0]}, "fog": {"densityPerMetre": 1e-4}})"));
  ASSERT_TRUE(fogged.fog.has_value());
  EXPECT_DOUBLE_EQ(fogged.fog->densityPerMetre, 1e-4);
  EXPECT_FALSE(fogged.atmosphere.has_value());
}

// A lake: its level, colour and clarity, the defaults where the scene gives none, and all of it
// written back as read.
TEST(Scenes, WaterArrivesInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("water.json", R"({
    "name": "w", "camera": {"position": [0, 300, 0]},
    "water": {"levelMetres": 215, "colour": [0.02, 0.04, 0.05], "clarity": 0.6}})"));
  ASSERT_TRUE(s.water.has_value());
  EXPECT_DOUBLE_EQ(s.water->levelMetres, 215.0);
  EXPECT_EQ(s.water->colour, glm::dvec3(0.02, 0.04, 0.05));
  EXPECT_DOUBLE_EQ(s.water->clarity, 0.6);
  const std::string written = sample::sceneJson(s);
  EXPECT_EQ(sample::sceneJson(loadSceneDescription(writeScene("water_back.json", written))),
            written);
  const sample::SceneDescription plain = loadSceneDescription(writeScene("water_plain.json", R"({
    "name": "w", "camera": {"position": [0, 300, 0]}, "water": {"levelMetres": -20}})"));
  ASSERT_TRUE(plain.water.has_value());
  EXPECT_DOUBLE_EQ(plain.water->clarity, sample::WaterDescription{}.clarity);
  EXPECT_FALSE(loadSceneDescription(writeScene("dry.json", R"({
    "name": "d", "camera": {"position": [0, 300, 0]}})"))
                   .water.has_value());
}

// A storm whose cells the weather places: found where it holds cumulonimbus, the ones given
// otherwise.
TEST(Scenes, AStormsCellsComeFromTheWeatherOrTheScene) {
  const sample::SceneDescription found = loadSceneDescription(writeScene("storm.json", R"({
    "name": "s", "camera": {"position": [5000, 1100, -10000]},
    "clouds": {"coverage": 0.55, "cloudType": 1.0, "noiseSeed": 12},
    "lightning": {"cellsFromWeather": {"count": 2, "withinMetres": 14000, "radiusMetres": 3000},
                  "groundAltitudeMetres": 150}})"));
  ASSERT_TRUE(found.lightning.has_value());
  ASSERT_EQ(found.lightning->storm.cells.size(), 2u);
  EXPECT_EQ(found.lightning->storm.cells[0].radiusMetres, 3000.0f);
  EXPECT_EQ(found.lightning->storm.groundAltitudeMetres, 150.0);
  const glm::dvec3 cell = found.lightning->storm.cells[0].positionMetres;
  EXPECT_GE(clouds::proceduralWeatherAt(found.clouds->settings, 12, {cell.x, cell.z}, 0.0).type,
            0.75f);
  const sample::SceneDescription given = loadSceneDescription(writeScene("storm_given.json", R"({
    "name": "s", "camera": {"position": [0, 1, 0]}, "clouds": {},
    "lightning": {"cells": [{"position": [1, 2000, 3], "radiusMetres": 700}]}})"));
  ASSERT_EQ(given.lightning->storm.cells.size(), 1u);
  EXPECT_EQ(given.lightning->storm.cells[0].positionMetres, glm::dvec3(1, 2000, 3));
}

// A weather schedule: built-in states blow the layer's way, the scene's own start from the
// layer's look (or a built-in state's) with the fields they give; a storm's cells are found
// under the state that strikes most, though the layer itself is fair.
TEST(Scenes, AWeatherScheduleArrivesInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("weather.json", R"({
    "name": "w", "camera": {"position": [5000, 1100, -10000]},
    "clouds": {"coverage": 0.3, "cloudType": 0.5, "noiseSeed": 12, "wind": {"directionDegrees": 90}},
    "weather": {
      "states": {"grey": {"coverage": 0.8}, "squall": {"like": "stormy", "wind": {"speedMetresPerSecond": 30}}},
      "schedule": [{"state": "sparse", "holdSeconds": 5, "transitionSeconds": 7},
                   {"state": "grey"}, {"state": "squall", "transitionSeconds": 3}],
      "repeat": false},
    "lightning": {"cellsFromWeather": {"count": 1, "withinMetres": 14000}}})"));
  ASSERT_TRUE(s.weather.has_value());
  const sample::WeatherDescription& w = *s.weather;
  ASSERT_EQ(w.schedule.keys.size(), 3u);
  EXPECT_FALSE(w.schedule.repeat);
  EXPECT_EQ(w.schedule.keys[0].holdSeconds, 5.0);
  EXPECT_EQ(w.schedule.keys[0].transitionSeconds, 7.0);
  EXPECT_EQ(w.schedule.keys[1].holdSeconds, clouds::WeatherKey{}.holdSeconds);
  const clouds::WeatherState sparse = clouds::weatherPreset(clouds::WeatherPreset::Sparse);
  EXPECT_EQ(w.schedule.keys[0].state.coverage, sparse.coverage);
  EXPECT_NEAR(w.schedule.keys[0].state.windDirection.y, -1.0f, 1e-6f) << "the layer's 90 degrees";
  EXPECT_EQ(w.schedule.keys[1].state.coverage, 0.8f);
  EXPECT_EQ(w.schedule.keys[1].state.cloudType, 0.5f) << "the layer's own look otherwise";
  EXPECT_EQ(w.schedule.keys[2].state.anvilBias, 1.0f) << "like stormy";
  EXPECT_EQ(w.schedule.keys[2].state.windSpeedMetresPerSecond, 30.0f);
  EXPECT_TRUE(w.strikes());
  ASSERT_EQ(s.lightning->storm.cells.size(), 1u) << "found under the squall, not the fair layer";
  EXPECT_EQ(w.schedule.timeline().stateAt(1e6), w.schedule.keys[2].state);
}

// Painted weather on the schedule: each key's map, its own or the layer's; written back, the
// same maps.
TEST(Scenes, PaintedMapsOnTheWeatherScheduleArriveInTheDescription) {
  // Any existing files stand for the maps: only the game reads them.
  const fs::path first = writeScene("front_a.png", "");
  const fs::path second = writeScene("front_b.png", "");
  const fs::path layer = writeScene("fair.png", "");
  const sample::SceneDescription s = loadSceneDescription(writeScene("painted.json", R"({
    "name": "p", "camera": {"position": [0, 1100, 0]},
    "clouds": {"weatherMap": "fair.png"},
    "weather": {"schedule": [{"state": "sparse", "weatherMap": "front_a.png"},
                             {"state": "cloudy"},
                             {"state": "overcast", "weatherMap": "front_b.png"}]}})"));
  ASSERT_TRUE(s.weather.has_value());
  const std::vector<fs::path> maps =
      sample::scheduledWeatherMaps(s.weather->schedule, s.clouds->weatherMap);
  ASSERT_EQ(maps.size(), 3u);
  EXPECT_EQ(fs::canonical(maps[0]), fs::canonical(first));
  EXPECT_EQ(fs::canonical(maps[1]), fs::canonical(layer)) << "the layer's map for a key without";
  EXPECT_EQ(fs::canonical(maps[2]), fs::canonical(second));
  // A schedule that paints nothing keeps the layer's map (or the procedural weather).
  sample::ScheduleDescription plain = s.weather->schedule;
  plain.weatherMaps.assign(plain.keys.size(), std::nullopt);
  EXPECT_TRUE(sample::scheduledWeatherMaps(plain, s.clouds->weatherMap).empty());
  // Written back (absolute paths) and read again: the same maps.
  const fs::path back = writeScene("painted_back.json", sample::sceneJson(s));
  const sample::SceneDescription again = loadSceneDescription(back);
  EXPECT_EQ(sample::scheduledWeatherMaps(again.weather->schedule, again.clouds->weatherMap), maps);
}

// Weather regions: a place with one state or a schedule of its own, over the layer's own look
// when the scene has no schedule; a storm's cells are found under a storm region's stormiest
// state, where the fair layer has none.
TEST(Scenes, WeatherRegionsArriveInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("regions.json", R"({
    "name": "w", "camera": {"position": [5000, 1100, -10000]},
    "clouds": {"coverage": 0.3, "cloudType": 0.5, "noiseSeed": 12},
    "weather": {
      "regions": [
        {"name": "front", "centre": [5000, -10000], "halfSides": [20000, 4000],
         "headingDegrees": 30, "radiusMetres": 1000, "blendMetres": 6000,
         "schedule": [{"state": "cloudy", "holdSeconds": 30, "transitionSeconds": 10},
                      {"state": "stormy"}], "repeat": false},
        {"name": "hole", "centre": [-20000, 3000], "state": "sparse"}]},
    "lightning": {"cellsFromWeather": {"count": 1, "withinMetres": 14000}}})"));
  ASSERT_TRUE(s.weather.has_value());
  const sample::WeatherDescription& w = *s.weather;
  EXPECT_FALSE(w.ownSchedule);
  ASSERT_EQ(w.schedule.keys.size(), 1u);
  EXPECT_EQ(w.schedule.keys[0].state, clouds::weatherOf(s.clouds->settings));
  ASSERT_EQ(w.regions.size(), 2u);
  const sample::RegionDescription& front = w.regions[0];
  EXPECT_EQ(front.name, "front");
  EXPECT_EQ(front.place.centreMetres, glm::dvec2(5000, -10000));
  EXPECT_EQ(front.place.halfSidesMetres, glm::vec2(20000, 4000));
  EXPECT_EQ(front.place.headingDegrees, 30.0f);
  EXPECT_EQ(front.place.radiusMetres, 1000.0f);
  EXPECT_EQ(front.place.blendMetres, 6000.0f);
  EXPECT_FALSE(front.steady);
  EXPECT_FALSE(front.schedule.repeat);
  EXPECT_EQ(front.schedule.timeline().stateAt(1e6).anvilBias,
            clouds::weatherPreset(clouds::WeatherPreset::Stormy).anvilBias);
  EXPECT_TRUE(w.regions[1].steady);
  EXPECT_EQ(w.regions[1].place.blendMetres, clouds::WeatherRegion{}.blendMetres);
  EXPECT_TRUE(w.strikes()) << "the front's storm strikes";
  ASSERT_EQ(s.lightning->storm.cells.size(), 1u) << "found under the front's storm";
  const glm::dvec3 cell = s.lightning->storm.cells[0].positionMetres;
  EXPECT_GT(clouds::weatherRegionStrength(w.stormiestRegions()[0], {cell.x, cell.z}), 0.0f);
}

// A superstorm: a region with a vortex, read, written back the same, and its cells found in it.
TEST(Scenes, ASuperstormArrivesInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("superstorm.json", R"({
    "name": "w", "camera": {"position": [0, 1100, 20000]},
    "clouds": {"coverage": 0.3, "cloudType": 0.4},
    "weather": {"regions": [
      {"name": "eye", "centre": [1000, -2000], "radiusMetres": 20000, "blendMetres": 6000,
       "vortex": {"eyeRadiusMetres": 3500, "eyeWallMetres": 4000,
                  "wallSpeedMetresPerSecond": -50, "spiralArms": 2},
       "state": "stormy"}]},
    "lightning": {"cellsFromWeather": {"count": 2, "withinMetres": 20000, "radiusMetres": 3000}}})"));
  ASSERT_TRUE(s.weather.has_value());
  const clouds::WeatherRegion::Vortex& v = s.weather->regions[0].place.vortex;
  EXPECT_EQ(v.eyeRadiusMetres, 3500.0f);
  EXPECT_EQ(v.eyeWallMetres, 4000.0f);
  EXPECT_EQ(v.wallSpeedMetresPerSecond, -50.0f);
  EXPECT_EQ(v.spiralArms, 2.0f);
  const nlohmann::json back = sample::weatherJson(*s.weather);
  EXPECT_EQ(back["regions"][0]["vortex"]["wallSpeedMetresPerSecond"], -50.0);
  ASSERT_EQ(s.lightning->storm.cells.size(), 2u) << "found in the storm's wall and bands";
  for (const auto& cell : s.lightning->storm.cells) {
    const double fromEye =
        std::hypot(cell.positionMetres.x - 1000.0, cell.positionMetres.z + 2000.0);
    EXPECT_GT(fromEye, 0.7 * 3500.0);
    EXPECT_LT(fromEye, 26000.0);
  }
}

TEST(Scenes, HeroCloudsArriveInTheDescription) {
  const sample::SceneDescription s = loadSceneDescription(writeScene("hero.json", R"({
    "name": "x", "camera": {"position": [0, 1, 0]},
    "clouds": {"heroClouds": [
      {"asset": "towering_cumulus", "positionMetres": [10, 20, 30], "scale": 2, "yawDegrees": 45,
       "lifecycle": {"startSeconds": -5, "growSeconds": 90, "matureSeconds": 0,
                     "dissipateSeconds": 45, "restSeconds": 12, "repeat": false}},
      {"asset": "arch", "positionMetres": [0, 0, 0]}], "heroDetail": "off"}
  })"));
  ASSERT_TRUE(s.clouds);
  EXPECT_EQ(s.clouds->settings.heroDetail, clouds::HeroDetail::Off);
  ASSERT_EQ(s.clouds->heroClouds.size(), 2u);
  const sample::HeroCloudDescription& h = s.clouds->heroClouds[0];
  EXPECT_EQ(h.shipped, "towering_cumulus");
  EXPECT_EQ(h.positionMetres, glm::dvec3(10, 20, 30));
  EXPECT_EQ(h.scale, 2.0);
  EXPECT_EQ(h.yawDegrees, 45.0);
  ASSERT_TRUE(h.lifecycle);
  EXPECT_EQ(h.lifecycle->startSeconds, -5.0);
  EXPECT_EQ(h.lifecycle->growSeconds, 90.0f);
  EXPECT_EQ(h.lifecycle->matureSeconds, 0.0f);
  EXPECT_EQ(h.lifecycle->dissipateSeconds, 45.0f);
  EXPECT_EQ(h.lifecycle->restSeconds, 12.0f);
  EXPECT_FALSE(h.lifecycle->repeat);
  EXPECT_FALSE(s.clouds->heroClouds[1].lifecycle);  // always as authored
  const sample::SceneDescription byDefault = loadSceneDescription(writeScene("detail.json", R"({
    "name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {"coverage": 0.5}})"));
  EXPECT_EQ(byDefault.clouds->settings.heroDetail, clouds::HeroDetail::Uprezzed);
}

TEST(Scenes, MalformedScenesNameFilePathAndReason) {
  struct Case {
    const char* file;
    const char* json;
    const char* expected;  // substring after "<file>: "
  };
  const Case cases[] = {
      {"unknown.json", R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clods": {}})",
       "clods: unknown key"},
      {"nested_unknown.json", R"({"name": "x", "camera": {"position": [0, 1, 0], "fov": 60}})",
       "camera.fov: unknown key"},
      {"type.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {"coverage": "lots"}})",
       "clouds.coverage: must be a number, got a string"},
      {"range.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {"coverage": 1.5}})",
       "clouds.coverage: must be in [0, 1], got 1.5"},
      {"layer.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"layerBottomMetres": 3000, "layerTopMetres": 2000}})",
       "clouds: Settings.layerTopMetres"},
      {"missing.json", R"({"name": "x"})", "camera: is required"},
      {"vector.json", R"({"name": "x", "camera": {"position": [0, 1]}})",
       "camera.position: must be an array of 3 numbers"},
      {"terrain.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "terrain": {"gltf": "nowhere.glb"}})",
       "terrain.gltf: file not found"},
      {"syntax.json", R"({"name": "x", )", "not valid JSON"},
      {"water_level.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "water": {"levelMetres": 2e4}})",
       "water.levelMetres: must be in [-1000, 10000], got 20000"},
      {"water_level_missing.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "water": {"clarity": 0.5}})",
       "water.levelMetres: is required"},
      {"water_clarity.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "water": {"levelMetres": 0, "clarity": 1.5}})",
       "water.clarity: must be in [0, 1], got 1.5"},
      {"water_colour.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "water": {"levelMetres": 0, "colour": [0.1, 0.1]}})",
       "water.colour: must be an array of 3 numbers"},
      {"close_detail.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "terrain": {"gltf": "default", "closeDetail": "yes"}})",
       "terrain.closeDetail: must be"},
      {"root.json", R"([1, 2, 3])", "(root): must be an object"},
      {"altitude.json", R"({"name": "x", "camera": {"position": [0, -5, 0]}})",
       "camera.position: altitude (y) must be in [0, 50000] m"},
      {"detail.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {"heroDetail": "max"}})",
       "clouds.heroDetail: must be one of uprezzed, off"},
      {"quality.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0], "cloudQuality": "extreme"}})",
       "camera.cloudQuality: must be one of low, medium, high, ultra, reference"},
      {"knob.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0], "cloudKnobs": {"lightSteps": 99}}})",
       "camera.cloudKnobs.lightSteps: must be in"},
      {"knob_name.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0], "cloudKnobs": {"coverage": 1}}})",
       "camera.cloudKnobs.coverage: unknown key"},
      {"target.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0], "frameTargetMilliseconds": -5}})",
       "camera.frameTargetMilliseconds"},
      {"both.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "atmosphere": {},
           "fog": {"densityPerMetre": 1e-5}})",
       "fog: a scene has an atmosphere or fog, not both"},
      {"preset.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "atmosphere": {"preset": "mars"}})",
       "atmosphere.preset: must be one of earth, hazy"},
      {"extinction.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "atmosphere": {"mieScatteringPerMetre": [1e-4, 1e-4, 1e-4],
                          "mieExtinctionPerMetre": [1e-5, 1e-5, 1e-5]}})",
       "atmosphere: Parameters.mieExtinctionPerMetre"},
      {"albedo.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "atmosphere": {"groundAlbedo": [0.1, 2, 0.1]}})",
       "atmosphere.groundAlbedo"},
      {"exposure.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "exposure": {"mode": "magic"}})",
       "exposure.mode: must be one of auto, manual"},
      {"ev.json", R"({"name": "x", "camera": {"position": [0, 1, 0]}, "exposure": {"ev100": 99}})",
       "exposure.ev100: must be in [-10, 25], got 99"},
      {"fogrange.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "fog": {"densityPerMetre": -1}})",
       "fog.densityPerMetre: must be in [0, 0.01], got -1"},
      {"lightning_no_clouds.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "lightning": {"cells": [{"position": [0, 2000, 0]}]}})",
       "lightning: lightning glows in clouds: the scene has none"},
      {"lightning_no_cells.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {}, "lightning": {}})",
       "lightning.cells: a storm needs either cells or cellsFromWeather"},
      {"lightning_both.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "lightning": {"cells": [{"position": [0, 2000, 0]}], "cellsFromWeather": {}}})",
       "lightning.cells: a storm needs either cells or cellsFromWeather"},
      {"lightning_count.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "lightning": {"cellsFromWeather": {"count": 99}}})",
       "lightning.cellsFromWeather.count: must be in [1, 16], got 99"},
      {"lightning_no_cumulonimbus.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {"cloudType": 0.3},
           "lightning": {"cellsFromWeather": {}}})",
       "lightning.cellsFromWeather: no cumulonimbus within"},
      {"weather_unknown.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "drizzle"}]}})",
       "weather.schedule[0].state: unknown state \"drizzle\""},
      {"weather_shadow.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"states": {"Stormy": {}}, "schedule": [{"state": "Stormy"}]}})",
       "weather.states.Stormy: a built-in state's name"},
      {"weather_like.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"states": {"grey": {"like": "foggy"}}, "schedule": [{"state": "grey"}]}})",
       "weather.states.grey.like: a built-in state"},
      {"weather_field.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"states": {"grey": {"coverage": 2}}, "schedule": [{"state": "grey"}]}})",
       "weather.states.grey.coverage: must be in [0, 1], got 2"},
      {"weather_hold.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "sparse", "holdSeconds": -1}]}})",
       "weather.schedule[0].holdSeconds: must be in [0, 1e+07], got -1"},
      {"weather_empty.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": []}})",
       "weather.schedule: at least one state"},
      {"weather_instant.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "sparse", "holdSeconds": 0, "transitionSeconds": 0}]}})",
       "weather.schedule: a repeating weather schedule must last some time"},
      {"weather_no_clouds.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "weather": {"schedule": [{"state": "sparse"}]}})",
       "weather: weather is the clouds'"},
      {"weather_no_storm.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "stormy"}]}})",
       "weather: a state strikes lightning: the scene needs a \"lightning\" storm"},
      {"weather_rate.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "stormy"}]},
           "lightning": {"cells": [{"position": [0, 2000, 0]}], "strikesPerMinute": 3}})",
       "lightning.strikesPerMinute: the weather's states set the rate"},
      {"region_centre.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0], "state": "cloudy"}]}})",
       "weather.regions[0].centre: must be an array of 2 numbers"},
      {"region_blend.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "blendMetres": 5,
                                    "state": "cloudy"}]}})",
       "weather.regions[0].blendMetres: must be in [100, 1e+07], got 5"},
      {"region_sides.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "halfSides": [1, -1],
                                    "state": "cloudy"}]}})",
       "weather.regions[0].halfSides: element 1 must be in [0, 1e+07], got -1"},
      {"vortex_sides.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "halfSides": [10, 10],
                                    "vortex": {"eyeRadiusMetres": 3000}, "state": "stormy"}]}})",
       "weather.regions[0].halfSides: a superstorm's region is a disc"},
      {"vortex_speed.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "state": "stormy",
                                    "vortex": {"eyeRadiusMetres": 3000,
                                               "wallSpeedMetresPerSecond": 900}}]}})",
       "weather.regions[0].vortex.wallSpeedMetresPerSecond: must be in [-200, 200], got 900"},
      {"vortex_two.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [
             {"name": "a", "centre": [0, 0], "state": "stormy", "vortex": {"eyeRadiusMetres": 3000}},
             {"name": "b", "centre": [9, 0], "state": "stormy", "vortex": {"eyeRadiusMetres": 3000}}
           ]}})",
       "weather.regions: at most one superstorm"},
      {"region_neither.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0]}]}})",
       "weather.regions[0].state: a region needs either a state or a schedule"},
      {"region_state.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "state": "drizzle"}]}})",
       "weather.regions[0].state: unknown state \"drizzle\""},
      {"region_schedule.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0],
                                    "schedule": [{"state": "sparse", "holdSeconds": -2}]}]}})",
       "weather.regions[0].schedule[0].holdSeconds: must be in [0, 1e+07], got -2"},
      {"region_none.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": []}})",
       "weather.regions: at least one region"},
      {"region_storm.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "state": "stormy"}]}})",
       "weather: a state strikes lightning: the scene needs a \"lightning\" storm"},
      {"region_repeat.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"repeat": true,
                       "regions": [{"name": "r", "centre": [0, 0], "state": "cloudy"}]}})",
       "weather.repeat: a schedule's: there is none"},
      {"weather_map_missing.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "sparse", "weatherMap": "nowhere.png"}]}})",
       "weather.schedule[0].weatherMap: file not found"},
      // (A file that exists stands for a painted map: the scene is refused before any is read.)
      {"weather_map_partial.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "sparse", "weatherMap": "weather_map_partial.json"},
                                    {"state": "cloudy"}]}})",
       "weather.schedule: key 1 (\"cloudy\") has no weatherMap and the layer none"},
      {"weather_map_region.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"regions": [{"name": "r", "centre": [0, 0], "schedule": [
             {"state": "cloudy", "weatherMap": "weather_map_region.json"}]}]}})",
       "weather.regions[0].schedule[0].weatherMap: a region sets a look over the layer's map"},
      {"weather_map_cells.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "weather": {"schedule": [{"state": "stormy", "weatherMap": "weather_map_cells.json"}]},
           "lightning": {"cellsFromWeather": {}}})",
       "lightning.cellsFromWeather: found in the procedural weather only, not a painted map"},
      {"lightning_ground.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]}, "clouds": {},
           "lightning": {"cells": [{"position": [0, 2000, 0]}], "groundAltitudeMetres": 1e6}})",
       "lightning.groundAltitudeMetres: must be in [-1000, 10000], got 1e+06"},
      {"hero_unknown.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "nowhere.vdb", "positionMetres": [0, 0, 0]}]}})",
       "clouds.heroClouds[0].asset: file not found"},
      {"hero_extension.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "hero_extension.json", "positionMetres": [0, 0, 0]}]}})",
       "clouds.heroClouds[0].asset: a shipped cloud (towering_cumulus, cumulonimbus, arch) or an "
       ".nvdf or .vdb file"},
      {"hero_scale.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "arch", "positionMetres": [0, 0, 0], "scale": 0}]}})",
       "clouds.heroClouds[0].scale: must be in [0.01, 100], got 0"},
      {"hero_position.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "arch"}]}})",
       "clouds.heroClouds[0].positionMetres: is required"},
      {"hero_life.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "arch", "positionMetres": [0, 0, 0],
                                      "lifecycle": {"growSeconds": 0}}]}})",
       "clouds.heroClouds[0].lifecycle.growSeconds: must be in [0.1, 1e+06], got 0"},
      {"hero_life_key.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0]},
           "clouds": {"heroClouds": [{"asset": "arch", "positionMetres": [0, 0, 0],
                                      "lifecycle": {"growthSeconds": 60}}]}})",
       "clouds.heroClouds[0].lifecycle.growthSeconds"},
      {"atmospherequality.json",
       R"({"name": "x", "camera": {"position": [0, 1, 0], "atmosphereQuality": "ultra"}})",
       "camera.atmosphereQuality: must be one of low, medium, high, reference"},
  };
  for (const Case& c : cases) {
    const fs::path path = writeScene(c.file, c.json);
    const std::string error = errorOf(path);
    EXPECT_NE(error.find(path.string() + ": "), std::string::npos) << c.file << ": " << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.file << ": " << error;
  }
  EXPECT_NE(errorOf("/no/such/scene.json").find("/no/such/scene.json"), std::string::npos);
}

}  // namespace
