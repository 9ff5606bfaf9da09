// The sample's systems in a world without a GPU: flying with the keyboard, staying above the
// terrain, teleports, the sun's daily arc, terrain chunking and frustum culling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/ecs/app.h"
#include "engine/ecs/frame_time.h"
#include "engine/platform/input.h"
#include "engine/render/camera_math.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"
#include "game/cloud_quality_controls.h"
#include "game/exposure_control.h"
#include "game/flight.h"
#include "game/game_components.h"
#include "game/terrain_height.h"
#include "game/terrain_placement.h"
#include "game/time_of_day.h"
#include "game/water.h"
#include "render/terrain_materials.h"
#include "render/terrain_renderer.h"

namespace {

using engine::platform::Key;
using engine::render::Camera;

// A 2 x 2 km ramp rising from 0 m at x = -1000 to 1000 m at x = +1000.
engine::assets::MeshData ramp() {
  engine::assets::MeshData mesh;
  const int n = 11;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float x = -1000.0f + 200.0f * float(i);
      const float z = -1000.0f + 200.0f * float(j);
      mesh.positions.emplace_back(x, (x + 1000.0f) * 0.5f, z);
      mesh.normals.emplace_back(0, 1, 0);
      mesh.colors.emplace_back(1.0f);
      mesh.uvs.emplace_back(0.0f);
    }
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const auto a = std::uint32_t(j * n + i);
      for (std::uint32_t v : {a, a + std::uint32_t(n), a + 1, a + 1, a + std::uint32_t(n),
                              a + std::uint32_t(n) + 1}) {
        mesh.indices.push_back(v);
      }
    }
  }
  mesh.boundsMin = {-1000, 0, -1000};
  mesh.boundsMax = {1000, 1000, 1000};
  return mesh;
}

struct FlightWorld {
  engine::ecs::App app;
  engine::ecs::Entity player;
  explicit FlightWorld(const glm::dvec3& position) {
    auto& world = app.world();
    world.ctx().emplace<engine::ecs::FrameTime>();
    world.ctx().emplace<engine::platform::InputState>();
    player = world.create();
    Camera camera;
    camera.position = position;
    world.emplace<Camera>(player, camera);
    sample::Aircraft aircraft;
    aircraft.speedMetresPerSecond = 50.0;
    world.emplace<sample::Aircraft>(player, aircraft);
    sample::installFlight(app.scheduler());
  }
  void step(double dt, int frames) {
    auto& time = app.world().ctx().get<engine::ecs::FrameTime>();
    for (int i = 0; i < frames; ++i) {
      time = time.next(dt);
      app.runFrame();
    }
  }
  Camera& camera() { return app.world().get<Camera>(player); }
  sample::Aircraft& aircraft() { return app.world().get<sample::Aircraft>(player); }
  engine::platform::InputState& input() {
    return app.world().ctx().get<engine::platform::InputState>();
  }
};

TEST(Flight, FliesForwardAndThrottles) {
  FlightWorld w({0, 500, 0});
  w.step(0.1, 10);  // 1 s at 50 m/s along -Z
  EXPECT_NEAR(w.camera().position.z, -50.0, 1e-6);
  EXPECT_NEAR(w.camera().position.y, 500.0, 1e-6);
  w.input().press(Key::W);
  w.step(0.1, 10);
  EXPECT_GT(w.aircraft().speedMetresPerSecond, 100.0);
  w.input().release(Key::W);
  w.input().press(Key::S);
  w.step(0.1, 100);
  EXPECT_EQ(w.aircraft().speedMetresPerSecond, 0.0) << "slows down to a standstill (a camera)";
}

TEST(Flight, PitchRollAndYawTurnTheAircraft) {
  FlightWorld w({0, 500, 0});
  w.input().press(Key::Down);  // pull up
  w.step(0.1, 5);
  EXPECT_GT(engine::render::forwardOf(w.camera()).y, 0.3);
  w.input().release(Key::Down);
  const glm::dvec3 before = engine::render::forwardOf(w.camera());
  w.input().press(Key::A);
  w.step(0.1, 5);
  EXPECT_LT(glm::dot(before, engine::render::forwardOf(w.camera())), 0.99);
}

TEST(Flight, NeverGoesThroughTheGroundAndCanClimbAboveTheClouds) {
  FlightWorld w({500, 900, 0});  // over the ramp where the ground is at 750 m
  auto mesh = ramp();
  w.app.world().ctx().emplace<sample::TerrainHeightField>(mesh, 64u);
  w.input().press(Key::Up);  // dive
  w.aircraft().speedMetresPerSecond = 300.0;
  for (int i = 0; i < 50; ++i) {
    w.step(0.05, 1);
    const glm::dvec3 p = w.camera().position;
    const double ground = (std::clamp(p.x, -1000.0, 1000.0) + 1000.0) * 0.5;
    if (std::abs(p.x) <= 1000.0 && std::abs(p.z) <= 1000.0) {
      ASSERT_GE(p.y, ground + 4.9) << "below the terrain at frame " << i;
    }
    ASSERT_GE(p.y, 4.9);
  }
  w.app.world().events<sample::SetCameraPose>().send(
      sample::SetCameraPose{{0, 100, 0}, 0.0, 80.0, 0.0, 400.0});
  w.input().release(Key::Up);
  w.step(0.1, 150);
  EXPECT_GT(w.camera().position.y, 5000.0) << "climbs above a 1.5-4 km cloud layer";
}

// Over a lake the floor is its surface: a diving pilot skims the water, never goes under it.
TEST(Flight, SkimsTheWaterAndNeverDivesUnderIt) {
  FlightWorld w({500, 900, 0});  // over the ramp where the ground is at 750 m
  auto mesh = ramp();
  w.app.world().ctx().emplace<sample::TerrainHeightField>(mesh, 64u);
  w.app.world().ctx().emplace<sample::WaterSurface>(sample::WaterSurface{820.0});
  w.input().press(Key::Up);  // dive
  w.aircraft().speedMetresPerSecond = 300.0;
  double lowest = 1e9;
  for (int i = 0; i < 50; ++i) {
    w.step(0.05, 1);
    lowest = std::min(lowest, w.camera().position.y);
    ASSERT_GE(w.camera().position.y, 820.0 + 4.9) << "under the water at frame " << i;
  }
  EXPECT_LT(lowest, 820.0 + 5.1) << "the dive reached the water";
}

TEST(Flight, TeleportsSetThePoseAndMarkACameraCut) {
  FlightWorld w({0, 500, 0});
  w.app.world().events<sample::SetCameraPose>().send(
      sample::SetCameraPose{{100, 2000, -300}, 90.0, 10.0, 0.0, 0.0});
  w.step(0.1, 1);
  EXPECT_EQ(w.camera().position, glm::dvec3(100, 2000, -300));
  EXPECT_TRUE(w.camera().cut);
  const glm::dvec3 f = engine::render::forwardOf(w.camera());
  EXPECT_NEAR(f.x, -std::cos(glm::radians(10.0)), 1e-9);  // yaw 90: looking along -X
  w.step(0.1, 1);
  EXPECT_FALSE(w.camera().cut);
}

TEST(CloudQuality, NumberKeysFixTheCameraPresetAndGTogglesTheGovernor) {
  FlightWorld w({0, 500, 0});
  auto& world = w.app.world();
  world.emplace<clouds::ecs::CloudQuality>(w.player, clouds::ecs::CloudQuality{});
  world.emplace<clouds::ecs::CloudFrameBudget>(w.player, clouds::ecs::CloudFrameBudget{16.7});
  sample::installCloudQualityControls(w.app.scheduler(), 25.0);
  const auto press = [&](Key key) {
    w.input().beginFrame();
    w.input().press(key);
    w.step(0.016, 1);
    w.input().release(key);
  };
  const std::pair<Key, clouds::Quality> presses[] = {{Key::Num4, clouds::Quality::Ultra},
                                                     {Key::Num1, clouds::Quality::Low},
                                                     {Key::Num5, clouds::Quality::Reference}};
  for (const auto& [key, preset] : presses) {
    press(key);
    EXPECT_EQ(world.get<clouds::ecs::CloudQuality>(w.player).preset, preset);
    EXPECT_FALSE(world.has<clouds::ecs::CloudFrameBudget>(w.player)) << "a fixed preset";
  }
  press(Key::G);
  ASSERT_TRUE(world.has<clouds::ecs::CloudFrameBudget>(w.player));
  EXPECT_EQ(world.get<clouds::ecs::CloudFrameBudget>(w.player).targetMilliseconds, 25.0);
  press(Key::G);
  EXPECT_FALSE(world.has<clouds::ecs::CloudFrameBudget>(w.player));
}

TEST(TimeOfDay, TheSunFollowsADailyArc) {
  sample::TimeOfDay t;
  t.maxElevationDegrees = 60.0;
  t.hours = 12.0;
  EXPECT_NEAR(std::asin(sample::sunDirectionAt(t).y), glm::radians(60.0), 1e-9);
  t.hours = 6.0;
  EXPECT_NEAR(sample::sunDirectionAt(t).y, 0.0, 1e-9);
  EXPECT_GT(sample::sunDirectionAt(t).x, 0.99);  // rises in the east (+X)
  t.hours = 18.0;
  EXPECT_LT(sample::sunDirectionAt(t).x, -0.99);
  t.hours = 0.0;
  EXPECT_LT(sample::sunDirectionAt(t).y, -0.5);
  const engine::render::Sun midnight = sample::sunLightFor(t);
  EXPECT_LT(glm::length(sample::analyticSunTransmittance(0.0, midnight.direction)), 1e-3f)
      << "no sun at night";
  t.hours = 12.0;
  const engine::render::Sun noon = sample::sunLightFor(t);
  EXPECT_EQ(noon.illuminance, midnight.illuminance) << "above the air the sun is the same";
  EXPECT_EQ(noon.illuminance.r, noon.illuminance.b) << "and white";
  const glm::vec3 atNoon = sample::analyticSunTransmittance(0.0, noon.direction);
  t.hours = 18.2;
  const glm::vec3 atDusk = sample::analyticSunTransmittance(0.0, sample::sunLightFor(t).direction);
  EXPECT_GT(atNoon.b, atDusk.b * 3.0f);
  EXPECT_GT(atDusk.r / atDusk.b, atNoon.r / atNoon.b) << "redder near the horizon";
  EXPECT_GT(sample::analyticSunTransmittance(4000.0, sample::sunLightFor(t).direction).b, atDusk.b)
      << "less air above a mountain";
}

// A world lit by the analytic sky at a time of day, with the sample's auto-exposure.
struct LitWorld {
  engine::ecs::App app;
  explicit LitWorld(double hours) {
    auto& world = app.world();
    world.ctx().emplace<engine::ecs::FrameTime>();
    world.ctx().emplace<engine::render::Exposure>();
    Camera camera;
    camera.position = {0.0, 500.0, 0.0};
    world.emplace<Camera>(world.create(), camera);
    sample::TimeOfDay time;
    time.hours = hours;
    world.emplace<engine::render::Sun>(world.create(), sample::sunLightFor(time));
    sample::installAnalyticSky(world, app.scheduler());
    sample::installExposureControl(app.scheduler());
  }
  float ev100() {
    app.runFrame();
    return app.world().ctx().get<engine::render::Exposure>().ev100;
  }
};

TEST(Exposure, AutoExposureMetersDaylightAndClampsTheNight) {
  LitWorld noon(12.0);
  const float noonEv = noon.ev100();
  EXPECT_GT(noonEv, 14.0f) << "sunny 16: about EV 15 under a high sun";
  EXPECT_LT(noonEv, 16.5f);
  LitWorld dusk(18.2);
  const float duskEv = dusk.ev100();
  EXPECT_LT(duskEv, noonEv - 3.0f) << "a low sun through much air is many stops darker";
  const float duskMetered = sample::meteredEv100(dusk.app.world());
  ASSERT_LT(duskMetered, 10.0f);
  EXPECT_FLOAT_EQ(duskEv, duskMetered - engine::render::dimLightCompensationEv(duskMetered))
      << "dusk is exposed darker than the meter reads";
  LitWorld night(0.0);
  const float nightEv = night.ev100();
  EXPECT_FLOAT_EQ(nightEv, engine::render::Exposure{}.minEv100) << "night stays dark";
  EXPECT_TRUE(std::isfinite(sample::meteredEv100(night.app.world())));
}

TEST(Exposure, ManualExposureIsLeftAlone) {
  LitWorld noon(12.0);
  auto& exposure = noon.app.world().ctx().get<engine::render::Exposure>();
  exposure.mode = engine::render::Exposure::Mode::Manual;
  exposure.ev100 = 9.0f;
  EXPECT_FLOAT_EQ(noon.ev100(), 9.0f);
}

TEST(Terrain, PlacementCentresSmallMeshesAndScalesThemUp) {
  engine::assets::MeshData mesh = ramp();
  for (auto& p : mesh.positions) p = p * 0.001f + glm::vec3(5, 7, 9);  // a 2 m model off-centre
  mesh.boundsMin = mesh.boundsMin * 0.001f + glm::vec3(5, 7, 9);
  mesh.boundsMax = mesh.boundsMax * 0.001f + glm::vec3(5, 7, 9);
  const double scale = sample::placeTerrain(mesh);
  EXPECT_NEAR(scale, 10000.0, 1e-6);
  EXPECT_NEAR(mesh.boundsMin.y, 0.0f, 1e-3f);
  EXPECT_NEAR(mesh.boundsMin.x, -10000.0f, 1e-1f);
  EXPECT_NEAR(mesh.boundsMax.z, 10000.0f, 1e-1f);
  engine::assets::MeshData big = ramp();
  for (auto& p : big.positions) p *= 20.0f;
  big.boundsMin *= 20.0f;
  big.boundsMax *= 20.0f;
  EXPECT_EQ(sample::placeTerrain(big), 1.0) << "terrain-sized meshes keep their metres";
}

TEST(Terrain, HeightFieldIsConservative) {
  const engine::assets::MeshData mesh = ramp();
  const sample::TerrainHeightField field(mesh, 64);
  // Never below the surface; above it by at most the rise across one triangle plus two cells
  // (200 m + 2 x 31.25 m at slope 0.5), the price of being conservative.
  for (double x = -990.0; x < 990.0; x += 37.0) {
    EXPECT_GE(field.heightAt(x, 0.0), (x + 1000.0) * 0.5 - 1e-3);
    EXPECT_LE(field.heightAt(x, 0.0), (x + 1000.0) * 0.5 + 0.5 * (200.0 + 2.0 * 31.25) + 1e-3);
  }
  EXPECT_EQ(field.heightAt(5000.0, 0.0), 0.0);
}

// The terrain's materials (terrain_material.h, as its fragment shader runs them): the mesh's
// colour on flat low ground, rock on steep ground, snow high up unless it is steep.
TEST(TerrainMaterial, RockOnSteepGroundSnowHighUp) {
  using namespace engine::shaders;
  const engine::assets::MeshData mesh = ramp();  // 0 to 1000 m: snow from 700 m
  const TerrainMaterials m = sample::terrainMaterialsFor(mesh, std::nullopt);
  EXPECT_NEAR(m.snow.w, 700.0f, 1e-3f);
  const glm::vec3 grass(0.05f, 0.08f, 0.03f);
  const glm::vec4 calm(0.0f, 0.0f, 0.5f, 0.5f);  // no detail gradient, mid waver
  const auto normalAt = [](float degrees) {
    return glm::vec3(std::sin(glm::radians(degrees)), std::cos(glm::radians(degrees)), 0.0f);
  };
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-3f; };
  EXPECT_TRUE(near(terrainAlbedo(grass, normalAt(5.0f), 100.0f, calm, m), grass));
  EXPECT_TRUE(near(terrainAlbedo(grass, normalAt(55.0f), 100.0f, calm, m), glm::vec3(m.rock)));
  EXPECT_TRUE(near(terrainAlbedo(grass, normalAt(5.0f), 950.0f, calm, m), glm::vec3(m.snow)));
  EXPECT_TRUE(near(terrainAlbedo(grass, normalAt(60.0f), 950.0f, calm, m), glm::vec3(m.rock)))
      << "no snow on a cliff";
  EXPECT_NEAR(sample::terrainMaterialsFor(mesh, 1234.0).snow.w, 1234.0f, 1e-3f);
}

// The ground's albedo at large (meanTerrainAlbedo()): what the materials paint, by area.
TEST(TerrainMaterial, TheGroundsMeanAlbedoIsWhatItsMaterialsPaintByArea) {
  const glm::vec3 grass(0.05f, 0.08f, 0.03f);
  engine::assets::MeshData mesh = ramp();  // flat normals, 0 to 1000 m along x
  for (glm::vec4& colour : mesh.colors) colour = glm::vec4(grass, 1.0f);
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
  EXPECT_TRUE(
      near(sample::meanTerrainAlbedo(mesh, sample::terrainMaterialsFor(mesh, 5000.0)), grass))
      << "all grass below a snowline above it";
  // Snow from 700 m (half at 700, whole from 760): 30% of the ramp's area by its triangles.
  const engine::shaders::TerrainMaterials m = sample::terrainMaterialsFor(mesh, 700.0);
  EXPECT_TRUE(near(sample::meanTerrainAlbedo(mesh, m), glm::mix(grass, glm::vec3(m.snow), 0.3f)));
  // Steep everywhere: rock.
  for (glm::vec3& normal : mesh.normals) normal = glm::normalize(glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_TRUE(near(sample::meanTerrainAlbedo(mesh, sample::terrainMaterialsFor(mesh, 5000.0)),
                   glm::vec3(m.rock)));
  // Two triangles of areas 1 and 3: weighted by area, not counted.
  engine::assets::MeshData two;
  two.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 2}, {10, 0, 0}, {13, 0, 0}, {10, 0, 2}};
  two.normals.assign(6, glm::vec3(0, 1, 0));
  two.colors = {glm::vec4(1, 0, 0, 1), glm::vec4(1, 0, 0, 1), glm::vec4(1, 0, 0, 1),
                glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, 1, 1)};
  two.indices = {0, 2, 1, 3, 5, 4};
  EXPECT_TRUE(near(sample::meanTerrainAlbedo(two, sample::terrainMaterialsFor(two, 5000.0)),
                   glm::vec3(0.25f, 0.0f, 0.75f)));
}

// The angle between two unit vectors (degrees).
double degreesBetween(const glm::vec3& a, const glm::vec3& b) {
  return glm::degrees(std::acos(std::clamp(double(glm::dot(a, b)), -1.0, 1.0)));
}

// The detail normal: finer than the mesh's 150 m (points 5 m apart differ), a few degrees to a
// few tens of degrees off the mesh's normal, and unbiased (the mesh's slope stays its slope).
TEST(TerrainMaterial, DetailNormalsAreFinerThanTheMesh) {
  using namespace engine::shaders;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  double sumAngle = 0.0;
  double maxAngle = 0.0;
  double sumNeighbour = 0.0;
  glm::dvec3 mean(0.0);
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const glm::vec2 xz(float(i) * 5.0f + 1234.5f, float(i % 37) * 13.0f - 800.0f);
    const glm::vec3 a = terrainDetailNormal(up, terrainDetail(xz));
    const glm::vec3 b = terrainDetailNormal(up, terrainDetail(xz + glm::vec2(5.0f, 0.0f)));
    const double angle = glm::degrees(std::acos(std::clamp(double(a.y), -1.0, 1.0)));
    sumAngle += angle;
    maxAngle = std::max(maxAngle, angle);
    sumNeighbour += degreesBetween(a, b);
    mean += glm::dvec3(a);
  }
  mean /= double(n);
  std::printf("detail normals: mean %.1f deg off the mesh's, max %.1f, 5 m apart %.1f deg\n",
              sumAngle / n, maxAngle, sumNeighbour / n);
  EXPECT_GT(sumAngle / n, 3.0);
  EXPECT_LT(maxAngle, 35.0);
  EXPECT_GT(sumNeighbour / n, 1.0) << "no variation at the metre scale";
  EXPECT_LT(std::abs(mean.x), 0.03);
  EXPECT_LT(std::abs(mean.z), 0.03);
}

// The octaves' values at their middle: no colour from the 60 m and 11 m octaves.
const glm::vec4 kCalmDetail(0.0f, 0.0f, 0.5f, 0.5f);

// Close up (terrainCloseDetail): where a pixel covers 0.75 m of ground or more the close-up
// octave is exactly nothing; closer, the ground gains relief and colour at the metre scale, half
// of it where a pixel covers 0.5625 m.
TEST(TerrainMaterial, CloseUpDetailFadesOutWithThePixelsFootprint) {
  using namespace engine::shaders;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec2 grass(0.0f, 0.0f);
  // The detail's variation between points 0.75 m apart (degrees of normal, colour factor), and
  // whether any point had any detail at all.
  struct Variation {
    double degrees = 0.0;
    double tint = 0.0;
    bool any = false;
  };
  const auto variation = [&](float footprint) {
    Variation v;
    const int n = 2000;
    const glm::vec3 step(0.75f, 0.0f, 0.0f);
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p(float(i) * 0.75f + 512.3f, 100.0f, float(i % 41) * 2.9f - 300.0f);
      const glm::vec4 a = terrainCloseDetail(p, up, grass, footprint);
      const glm::vec4 b = terrainCloseDetail(p + step, up, grass, footprint);
      const glm::vec3 na = glm::normalize(up + glm::vec3(a));
      const glm::vec3 nb = glm::normalize(up + glm::vec3(b));
      v.degrees += degreesBetween(na, nb) / n;
      v.tint += std::abs(terrainDetailTint(kCalmDetail, a.w, grass, footprint).g -
                         terrainDetailTint(kCalmDetail, b.w, grass, footprint).g) /
                n;
      v.any = v.any || a != glm::vec4(0.0f);
    }
    return v;
  };
  const Variation sharp = variation(0.05f);
  const Variation half = variation(0.5625f);
  const Variation faded = variation(0.75f);
  std::printf(
      "close-up detail 0.75 m apart: %.2f deg and tint %.3f (0.05 m pixels), %.2f deg "
      "and %.3f (0.5625 m), %s at 0.75 m\n",
      sharp.degrees, sharp.tint, half.degrees, half.tint, faded.any ? "some" : "none");
  EXPECT_GT(sharp.degrees, 3.0) << "relief at the metre scale";
  EXPECT_GT(sharp.tint, 0.03) << "colour at the metre scale";
  EXPECT_NEAR(half.degrees / sharp.degrees, 0.5, 0.1) << "half of it kept";
  EXPECT_NEAR(half.tint / sharp.tint, 0.5, 0.1) << "half of it kept";
  EXPECT_FALSE(faded.any) << "nothing once a pixel covers a quarter of the octave";
}

// The ground's colour varies at the scales a pixel resolves (terrainDetailTint): where a pixel
// covers 1 m, with both the 60 m and the 11 m octaves (points 5 m apart differ); at 6 m, with the
// 60 m one alone (the 11 m one would alias); from 15 m, not at all (the far view as it was).
TEST(TerrainMaterial, TheGroundsColourVariesAtTheScalesAPixelResolves) {
  using namespace engine::shaders;
  const glm::vec2 grass(0.0f, 0.0f);
  const auto tintAt = [&](glm::vec2 xz, float footprint) {
    return terrainDetailTint(terrainDetail(xz), 0.0f, grass, footprint).g;
  };
  // Mean colour difference between points `apart` metres apart.
  const auto variation = [&](float footprint, float apart) {
    double sum = 0.0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      const glm::vec2 xz(float(i) * 7.3f - 4000.0f, float(i % 53) * 31.0f);
      sum += std::abs(tintAt(xz, footprint) - tintAt(xz + glm::vec2(apart, 0.0f), footprint)) / n;
    }
    return sum;
  };
  const double near5 = variation(1.0f, 5.0f);
  const double mid5 = variation(6.0f, 5.0f);
  const double mid40 = variation(6.0f, 40.0f);
  std::printf("detail colour: 5 m apart %.4f (1 m pixels), %.4f (6 m); 40 m apart %.4f (6 m)\n",
              near5, mid5, mid40);
  EXPECT_GT(near5, 0.02) << "the 11 m octave's colour where a pixel resolves it";
  EXPECT_LT(mid5, 0.5 * near5) << "the 11 m octave gone at 6 m pixels";
  EXPECT_GT(mid40, 0.03) << "the 60 m octave's colour still there";
  for (int i = 0; i < 100; ++i) {
    const glm::vec2 xz(float(i) * 17.1f, float(i) * -3.7f);
    ASSERT_EQ(tintAt(xz, 15.0f), 1.0f) << "the far view as it was, to the bit";
  }
}

// Close up the colour factor is 1 on average for every material (the ground's mean albedo is
// what the materials paint, near as far), rock mottled, snow nearly even.
TEST(TerrainMaterial, CloseUpColourIsUnbiasedAndFollowsTheMaterial) {
  using namespace engine::shaders;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const struct {
    const char* name;
    glm::vec2 weights;
  } materials[] = {{"grass", {0.0f, 0.0f}}, {"rock", {1.0f, 0.0f}}, {"snow", {0.0f, 1.0f}}};
  double spread[3] = {};
  for (int m = 0; m < 3; ++m) {
    glm::dvec3 mean(0.0);
    double squares = 0.0;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p(float(i % 200) * 0.97f, 50.0f, float(i / 200) * 1.03f);
      const glm::vec4 d = terrainCloseDetail(p, up, materials[m].weights, 0.01f);
      const glm::dvec3 tint(
          terrainDetailTint(terrainDetail(glm::vec2(p.x, p.z)), d.w, materials[m].weights, 0.01f));
      mean += tint / double(n);
      squares += (tint.r - 1.0) * (tint.r - 1.0) / n;
    }
    spread[m] = std::sqrt(squares);
    std::printf("%s: mean tint %.3f %.3f %.3f, spread %.3f\n", materials[m].name, mean.r, mean.g,
                mean.b, spread[m]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0, 0.03) << materials[m].name;
  }
  EXPECT_GT(spread[1], spread[0]) << "rock more mottled than grass";
  EXPECT_LT(spread[2], 0.2 * spread[1]) << "snow nearly even";
}

// On a cliff, rock's detail is projected on the face (triplanar): the normal varies up the
// face as along it. A plan-view projection (what grass gets) is constant up a vertical face.
TEST(TerrainMaterial, RockDetailIsProjectedOnTheFace) {
  using namespace engine::shaders;
  const glm::vec3 face(1.0f, 0.0f, 0.0f);  // a vertical face looking along +x
  const auto upTheFace = [&](glm::vec2 weights) {
    double degrees = 0.0;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p(40.0f, float(i) * 0.75f + 20.0f, float(i % 29) * 1.7f);
      const glm::vec3 a =
          glm::normalize(face + glm::vec3(terrainCloseDetail(p, face, weights, 0.05f)));
      const glm::vec3 b =
          glm::normalize(face + glm::vec3(terrainCloseDetail(p + glm::vec3(0.0f, 0.75f, 0.0f), face,
                                                             weights, 0.05f)));
      degrees += degreesBetween(a, b) / n;
    }
    return degrees;
  };
  const double rock = upTheFace({1.0f, 0.0f});
  const double planView = upTheFace({0.0f, 0.0f});
  std::printf("up a cliff, 0.75 m apart: rock %.2f deg, plan view %.2f deg\n", rock, planView);
  EXPECT_GT(rock, 3.0);
  EXPECT_LT(planView, 0.05) << "constant but for float rounding";
}

// What long shadows are cast from: the surface itself, exact on a planar ramp (linear
// interpolation on its triangles), without the conservative field's lift.
TEST(Terrain, SurfaceSamplesLieOnTheMesh) {
  const engine::assets::MeshData mesh = ramp();
  const sample::SurfaceHeights s = sample::sampleSurface(mesh, 50);
  ASSERT_EQ(s.metres.size(), 2500u);
  const glm::dvec2 cell = s.sizeMetres / 50.0;
  for (std::uint32_t j = 0; j < 50; ++j) {
    for (std::uint32_t i = 0; i < 50; ++i) {
      const double x = s.originMetres.x + (i + 0.5) * cell.x;
      EXPECT_NEAR(s.metres[j * 50 + i], (x + 1000.0) * 0.5, 1e-3) << i << ", " << j;
    }
  }
  EXPECT_NEAR(s.minMetres, (0.5 * cell.x) * 0.5, 1e-3);
  EXPECT_NEAR(s.maxMetres, (2000.0 - 0.5 * cell.x) * 0.5, 1e-3);
}

TEST(Terrain, ChunksPartitionEveryTriangleOnceAndCoarserLevelsHaveFewer) {
  const engine::assets::MeshData mesh = ramp();
  std::vector<std::uint32_t> indices;
  const auto chunks = sample::buildChunks(mesh, indices, 4, {0.0f, 450.0f, 1100.0f});
  EXPECT_EQ(chunks.size(), 16u);
  std::array<std::uint64_t, sample::kTerrainLods> totals{};
  for (const auto& c : chunks) {
    EXPECT_LE(c.boundsMax.x - c.boundsMin.x, 700.0f);
    for (std::size_t l = 0; l < sample::kTerrainLods; ++l) {
      totals[l] += c.lods[l].indexCount;
      ASSERT_LE(c.lods[l].firstIndex + c.lods[l].indexCount, indices.size());
      for (std::uint32_t i = 0; i < c.lods[l].indexCount; ++i) {
        ASSERT_LT(indices[c.lods[l].firstIndex + i], mesh.positions.size());
      }
    }
  }
  EXPECT_EQ(totals[0], mesh.indices.size()) << "level 0 is the whole mesh";
  EXPECT_LT(totals[1], totals[0] / 2);
  EXPECT_LT(totals[2], totals[1]);
  EXPECT_GT(totals[2], 0u);
  EXPECT_EQ(sample::lodForDistance(100.0f), 0u);
  EXPECT_EQ(sample::lodForDistance(20000.0f), 2u);
}

TEST(Terrain, FrustumCullingKeepsWhatIsInFrontOnly) {
  const glm::mat4 viewProjection =
      engine::render::perspectiveReversedZ(glm::radians(60.0f), 16.0f / 9.0f, 0.5f) *
      engine::render::lookTo(glm::vec3(0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
  EXPECT_TRUE(sample::boxInFrustum(viewProjection, {-10, -10, -110}, {10, 10, -90}));
  EXPECT_FALSE(sample::boxInFrustum(viewProjection, {-10, -10, 90}, {10, 10, 110})) << "behind";
  EXPECT_FALSE(sample::boxInFrustum(viewProjection, {500, -10, -110}, {520, 10, -90})) << "right";
  EXPECT_TRUE(sample::boxInFrustum(viewProjection, {-1, -1, -1}, {1, 1, 1})) << "around the eye";
  EXPECT_TRUE(sample::boxInFrustum(viewProjection, {-10, -10, -1e6}, {10, 10, -9e5})) << "far";
}

}  // namespace
