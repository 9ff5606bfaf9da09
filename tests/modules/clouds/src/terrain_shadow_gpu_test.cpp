// The terrain's shadow in the cloud shadow map on lavapipe (FrameInputs::terrain): its texels
// against the CPU walk (the shared terrain_shadow_march.h), the receivers' lookup against a
// fine walk towards the sun from points on the ground, a ridge that takes the sun from the
// clouds behind it at a low sun and not at a high one, a terrain pass only with a terrain, and
// bad terrain inputs refused by name. Validation-clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "engine/gfx/upload.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudView;
using clouds::tools::CpuHeightfield;
using clouds::tools::ShadowMapImage;

using TerrainShadow = test::SharedHarnessTest<96, 64>;

constexpr std::uint32_t kHeightTexels = 256;
constexpr double kHeightfieldMetres = 40000.0;  // centred on the world origin
constexpr float kRidgeMetres = 3000.0f;
constexpr double kRidgeDistanceMetres = 6000.0;  // from the origin towards the sun

// A ridge kRidgeMetres high and a few kilometres wide, kRidgeDistanceMetres from the origin
// towards the sun's azimuth and across it, over a plain at 100 m.
CpuHeightfield ridgeTowards(const glm::vec3& sun) {
  const glm::dvec2 towardsSun = glm::normalize(glm::dvec2(sun.x, sun.z));
  CpuHeightfield field;
  field.width = kHeightTexels;
  field.height = kHeightTexels;
  field.metres.resize(std::size_t{kHeightTexels} * kHeightTexels);
  for (std::uint32_t j = 0; j < kHeightTexels; ++j) {
    for (std::uint32_t i = 0; i < kHeightTexels; ++i) {
      const glm::dvec2 p = (glm::dvec2(i, j) + 0.5) / double(kHeightTexels) * kHeightfieldMetres -
                           kHeightfieldMetres / 2.0;
      const double across = (glm::dot(p, towardsSun) - kRidgeDistanceMetres) / 1500.0;
      field.metres[std::size_t{j} * kHeightTexels + i] =
          100.0f + (kRidgeMetres - 100.0f) * static_cast<float>(std::exp(-across * across));
    }
  }
  return field;
}

// The heightfield as the module reads it: an R32F image, sampled.
class HeightfieldImage {
 public:
  explicit HeightfieldImage(const CpuHeightfield& field)
      : image_(test::GpuTest::device(),
               engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                      VK_FORMAT_R32_SFLOAT,
                                      {field.width, field.height, 1},
                                      1,
                                      1,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                      "test heightfield"}) {
    engine::gfx::uploadToImage(test::GpuTest::device(), image_,
                               std::as_bytes(std::span(field.metres)),
                               engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  }
  clouds::FrameInputs::Terrain terrain(const CpuHeightfield& field) const {
    clouds::FrameInputs::Terrain t;
    t.heightView = image_.view();
    t.originMetres = glm::dvec2(-kHeightfieldMetres / 2.0);
    t.sizeMetres = glm::dvec2(kHeightfieldMetres);
    t.minAltitudeMetres = *std::min_element(field.metres.begin(), field.metres.end());
    t.maxAltitudeMetres = *std::max_element(field.metres.begin(), field.metres.end());
    return t;
  }

 private:
  engine::gfx::Image image_;
};

// The camera on the plain near the origin, the sun low.
CloudView lowSunView(double elevation) {
  CloudView view;
  view.position = {0.0, 400.0, 0.0};
  view.sunElevationDegrees = elevation;
  view.sunAzimuthDegrees = 120.0;
  view.timeSeconds = 5.0;
  return view;
}

// Camera-relative position of a point on the ground at world (x, z).
glm::vec3 onTheGround(const CpuHeightfield& field, const CloudView& view, double x, double z) {
  const glm::vec2 uv =
      glm::vec2((glm::dvec2(x, z) + kHeightfieldMetres / 2.0) / kHeightfieldMetres);
  return {float(x - view.position.x), field.at(uv) - float(view.position.y),
          float(z - view.position.z)};
}

TEST_F(TerrainShadow, TexelsMatchTheCpuWalk) {
  const CloudView base = lowSunView(6.0);
  const CpuHeightfield field = ridgeTowards(clouds::tools::sunDirection(base));
  const HeightfieldImage image(field);
  CloudView view = base;
  view.terrain = image.terrain(field);
  clouds::Settings s;
  harness().cut();
  const ShadowMapImage map = harness().renderShadowMap(view, s);
  const auto& jobs = impl().lastTerrainShadowJobs();
  ASSERT_EQ(jobs.size(), s.shadowCascades) << "a cut makes every cascade";
  double worst = 0.0;
  int shadowing = 0;
  for (const auto& job : jobs) {
    for (std::uint32_t y = 2; y < s.shadowMapResolution; y += 7) {
      for (std::uint32_t x = 3; x < s.shadowMapResolution; x += 9) {
        const float cpu = clouds::tools::cpuTerrainShadowTexel(field, job, {x, y});
        const float gpu =
            map.texels[std::size_t{y} * map.width + job.cascade.cascade * s.shadowMapResolution + x]
                .w;
        // RGBA16F keeps 11 significant bits (2 m at 3 km); the sampler's filter weights are
        // fixed-point on lavapipe, which moves a crossing by a little more.
        worst = std::max(worst, std::abs(double(gpu - cpu)) / (4.0 + 0.002 * std::abs(cpu)));
        shadowing += cpu > 500.0f ? 1 : 0;
      }
    }
  }
  std::printf("terrain texels vs CPU: worst error %.2f of the bound, %d texels shadowing\n", worst,
              shadowing);
  EXPECT_GT(shadowing, 20) << "the ridge must shadow some rays for the comparison to mean much";
  EXPECT_LT(worst, 1.0);
}

// Points on the ground facing the sun, lit or not by the lookup, against a 10 m walk towards the
// sun over the same heightfield.
TEST_F(TerrainShadow, LookupAgreesWithAWalkTowardsTheSun) {
  for (double elevation : {4.0, 10.0}) {
    const CloudView base = lowSunView(elevation);
    const glm::vec3 sun = clouds::tools::sunDirection(base);
    const CpuHeightfield field = ridgeTowards(sun);
    const HeightfieldImage image(field);
    CloudView view = base;
    view.terrain = image.terrain(field);
    harness().cut();
    const ShadowMapImage map = harness().renderShadowMap(view, clouds::Settings{});
    const glm::vec3 light = glm::vec3(map.parameters.cascade[2]);
    int points = 0;
    int hidden = 0;
    int disagree = 0;
    for (double x = -12000.0; x <= 12000.0; x += 800.0) {
      for (double z = -12000.0; z <= 12000.0; z += 800.0) {
        const glm::vec3 p = onTheGround(field, view, x, z);
        // Ground facing away from the sun is dark by its own slope (the receiver's Lambert
        // term), whatever the map says: only ground facing the sun is compared.
        const glm::vec3 east = onTheGround(field, view, x + 20.0, z) - p;
        const glm::vec3 south = onTheGround(field, view, x, z + 20.0) - p;
        if (glm::dot(glm::cross(south, east), sun) <= 0.0f) continue;
        const bool truth = clouds::tools::cpuTerrainHidesSun(
            field, glm::vec2(-kHeightfieldMetres / 2.0), glm::vec2(kHeightfieldMetres),
            float(view.position.y), p, light, 10.0f);
        const float lit = map.terrainLight(p);
        ++points;
        hidden += truth ? 1 : 0;
        disagree += (lit < 0.5f) != truth ? 1 : 0;
      }
    }
    const double rate = double(disagree) / points;
    std::printf("sun %.0f degrees: %d ground points, %d hidden by the ridge, %.1f%% disagree\n",
                elevation, points, hidden, 100.0 * rate);
    EXPECT_GT(hidden, points / 10) << "the ridge must hide part of the ground";
    // Points within a texel's footprint of a shadow's edge can go either way (measured: 0.1 % at
    // 4 degrees, 0.6 % at 10).
    EXPECT_LT(rate, 0.02) << "sun " << elevation << " degrees up";
  }
}

double meanLuminance(const clouds::tools::CloudFrame& frame) {
  double sum = 0.0;
  for (const glm::vec4& p : frame.radiance) sum += (p.r + p.g + p.b) / 3.0;
  return sum / double(frame.radiance.size());
}

// Overcast low enough for the ridge to rise into its shadow: looking up towards the ridge at a
// low sun, the clouds in its shadow lose their direct sun; at a high sun the ridge's shadow
// falls short of them and the clouds are exactly as without the terrain.
TEST_F(TerrainShadow, ARidgeAtALowSunDarkensTheCloudsBehindIt) {
  clouds::Settings s = clouds::tools::singleFrame(clouds::Settings{});
  s.layerBottomMetres = 1200.0f;
  s.layerTopMetres = 2400.0f;
  s.coverage = 0.8f;
  s.maxDistanceMetres = 8000.0f;
  // The render with terrain has a shadow map and the one without none: the clouds' own shadow
  // from the map would darken the first alone.
  s.cloudShadowsOnClouds = false;
  const VkExtent2D extent{96, 64};
  for (double elevation : {5.0, 60.0}) {
    const CloudView base = lowSunView(elevation);
    const CpuHeightfield field = ridgeTowards(clouds::tools::sunDirection(base));
    const HeightfieldImage image(field);
    CloudView view = base;
    view.pitchDegrees = 50.0;
    view.yawDegrees = base.sunAzimuthDegrees;  // towards the sun and the ridge
    harness().cut();
    const auto bare = harness().render(view, s, extent);
    view.terrain = image.terrain(field);
    harness().cut();
    const auto shaded = harness().render(view, s, extent);
    ASSERT_TRUE(test::allValid(shaded));
    const double without = meanLuminance(bare);
    const double with = meanLuminance(shaded);
    std::printf("sun %.0f degrees: clouds %.4f without the terrain, %.4f with it\n", elevation,
                without, with);
    ASSERT_GT(test::meanOpacity(bare), 0.3) << "the view must hold clouds";
    if (elevation < 10.0) {
      EXPECT_LT(with, 0.8 * without) << "the ridge's shadow must take the clouds' sun";
    } else {
      EXPECT_NEAR(with, without, 1e-6 * without) << "a high sun: no shadow reaches the clouds";
    }
  }
}

// The terrain pass runs only with a terrain; without one the map's terrain channel lets the
// sun through everywhere.
TEST_F(TerrainShadow, NoTerrainNoTerrainPass) {
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  clouds::tools::CloudHarness h(device(), {64, 64}, options);
  const CloudView base = lowSunView(6.0);
  const ShadowMapImage bare = h.renderShadowMap(base, clouds::Settings{}, 2);
  for (const clouds::PassTiming& t : h.lastPassTimings()) EXPECT_STRNE(t.name, "terrain shadow");
  for (const glm::vec4& t : bare.texels) ASSERT_LT(t.w, -1000.0f);
  EXPECT_EQ(bare.terrainLight({0.0f, -400.0f, 0.0f}), 1.0f);

  const CpuHeightfield field = ridgeTowards(clouds::tools::sunDirection(base));
  const HeightfieldImage image(field);
  CloudView view = base;
  view.terrain = image.terrain(field);
  h.renderShadowMap(view, clouds::Settings{}, 1);
  bool timed = false;
  for (const clouds::PassTiming& t : h.lastPassTimings()) {
    timed = timed || std::string(t.name) == "terrain shadow";
  }
  EXPECT_TRUE(timed) << "with a terrain the pass runs (and is timed)";
}

// The terrain does not move: a cascade remade over the same rays keeps its terrain channel and
// the terrain pass does not run; a camera that moved a cascade's rays gets them walked again.
TEST_F(TerrainShadow, UnmovedCascadesKeepTheirTerrainChannel) {
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  clouds::tools::CloudHarness h(device(), {64, 64}, options);
  CloudView view = lowSunView(6.0);
  const CpuHeightfield field = ridgeTowards(clouds::tools::sunDirection(view));
  const HeightfieldImage image(field);
  view.terrain = image.terrain(field);
  const clouds::Settings s;
  const auto ranTerrainPass = [&] {
    for (const clouds::PassTiming& t : h.lastPassTimings()) {
      if (std::string(t.name) == "terrain shadow") return true;
    }
    return false;
  };
  const ShadowMapImage first = h.renderShadowMap(view, s, 1);
  EXPECT_TRUE(ranTerrainPass());
  view.timeSeconds += 0.1;
  const ShadowMapImage kept = h.renderShadowMap(view, s, 3);
  EXPECT_FALSE(ranTerrainPass()) << "still camera: nothing to walk again";
  ASSERT_EQ(first.texels.size(), kept.texels.size());
  for (std::size_t i = 0; i < first.texels.size(); ++i) {
    ASSERT_EQ(first.texels[i].w, kept.texels[i].w) << "texel " << i;
  }
  view.position.x += 1000.0;  // 13 finest texels: the finest cascade's rays move
  h.renderShadowMap(view, s, 2);
  EXPECT_TRUE(ranTerrainPass());
  const auto& jobs = clouds::detail::ContextAccess::impl(h.context()).lastTerrainShadowJobs();
  ASSERT_FALSE(jobs.empty());
  const ShadowMapImage moved = h.readShadowMap();
  for (const auto& job : jobs) {
    for (std::uint32_t y = 5; y < s.shadowMapResolution; y += 17) {
      for (std::uint32_t x = 7; x < s.shadowMapResolution; x += 19) {
        const float cpu = clouds::tools::cpuTerrainShadowTexel(field, job, {x, y});
        const float gpu = moved
                              .texels[std::size_t{y} * moved.width +
                                      job.cascade.cascade * s.shadowMapResolution + x]
                              .w;
        EXPECT_NEAR(gpu, cpu, 4.0 + 0.002 * std::abs(cpu));
      }
    }
  }
}

TEST_F(TerrainShadow, BadTerrainInputsAreRefusedByName) {
  const CloudView base = lowSunView(6.0);
  const CpuHeightfield field = ridgeTowards(clouds::tools::sunDirection(base));
  const HeightfieldImage image(field);
  struct Case {
    const char* field;
    void (*spoil)(clouds::FrameInputs::Terrain&);
  };
  const Case cases[] = {
      {"FrameInputs.terrain.sizeMetres", [](auto& t) { t.sizeMetres.x = 0.0; }},
      {"FrameInputs.terrain.sizeMetres", [](auto& t) { t.sizeMetres.y = -5.0; }},
      {"FrameInputs.terrain.originMetres", [](auto& t) { t.originMetres.x = NAN; }},
      {"FrameInputs.terrain.minAltitudeMetres", [](auto& t) { t.maxAltitudeMetres = -1.0f; }},
      {"FrameInputs.terrain.minAltitudeMetres", [](auto& t) { t.minAltitudeMetres = INFINITY; }},
  };
  for (const Case& c : cases) {
    CloudView view = base;
    view.terrain = image.terrain(field);
    c.spoil(view.terrain);
    const std::string error = harness().tryRender(view, clouds::Settings{}, {32, 32});
    EXPECT_NE(error.find(c.field), std::string::npos) << error;
  }
}

}  // namespace
