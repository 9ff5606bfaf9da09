// The cloud shadow map on lavapipe: its texels against the CPU reference (the shared column
// march), the receivers' lookup against Beer-Lambert through a uniform slab and against a fine
// march towards the sun at sampled ground points, a cloud bank 80 km away, no swimming when the
// camera moves, cascades remade in turn without a pop, shadows that travel with the wind,
// hard cases that stay finite, and no pass or memory without a map. Validation-clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "engine/gfx/upload.h"
#include "gpu_test.h"
#include "shadow_cascades.h"

namespace {

using clouds::tools::CloudView;
using clouds::tools::ShadowMapImage;

using CloudShadow = test::SharedHarnessTest<64, 64>;

// Broken cumulus seen from near the ground, the sun 35 degrees up.
CloudView groundView() {
  CloudView view;
  view.position = {1200.0, 300.0, -800.0};
  view.sunElevationDegrees = 35.0;
  view.sunAzimuthDegrees = 200.0;
  view.timeSeconds = 5.0;
  return view;
}

clouds::Settings cumulus() {
  clouds::Settings s;
  s.coverage = 0.55f;
  s.cloudType = 0.9f;
  return s;
}

bool finiteMap(const ShadowMapImage& map) {
  for (const glm::vec4& t : map.texels) {
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(t[c])) return false;
    }
    if (t.x < 0.0f) return false;
  }
  return true;
}

TEST_F(CloudShadow, TexelsMatchTheCpuReference) {
  const clouds::Settings s = cumulus();
  harness().cut();
  const ShadowMapImage map = harness().renderShadowMap(groundView(), s);
  ASSERT_EQ(map.width, s.shadowMapResolution * s.shadowCascades);
  ASSERT_TRUE(finiteMap(map));
  const auto textures = clouds::tools::readTextures(harness());
  const auto& u = impl().lastShadowUniforms();
  const auto& jobs = impl().lastShadowJobs();
  ASSERT_EQ(jobs.size(), s.shadowCascades) << "a cut makes every cascade";
  double worstDepth = 0.0;
  double worstAltitude = 0.0;
  int cloudy = 0;
  for (const auto& job : jobs) {
    for (std::uint32_t y = 3; y < s.shadowMapResolution; y += 11) {
      for (std::uint32_t x = 5; x < s.shadowMapResolution; x += 13) {
        const glm::vec4 cpu = clouds::tools::cpuShadowTexel(textures, u, job, {x, y}, true);
        const glm::vec4 gpu =
            map.texels[std::size_t{y} * map.width + job.cascade * s.shadowMapResolution + x];
        // RGBA16F keeps 11 significant bits.
        worstDepth = std::max(worstDepth, std::abs(double(gpu.x - cpu.x)) / (1.0 + cpu.x));
        worstAltitude = std::max(
            {worstAltitude, std::abs(double(gpu.y - cpu.y)), std::abs(double(gpu.z - cpu.z))});
        cloudy += cpu.x > 0.1f ? 1 : 0;
      }
    }
  }
  std::printf(
      "shadow texels vs CPU: worst depth error %.2e (relative), altitude %.2f m, %d cloudy\n",
      worstDepth, worstAltitude, cloudy);
  EXPECT_GT(cloudy, 20) << "the view must hold clouds for the comparison to mean anything";
  EXPECT_LT(worstDepth, 2e-3);
  EXPECT_LT(worstAltitude, 4.0);
}

// A uniform slab of optical depth tau overhead lets through exp(-tau / sin(elevation)) of the
// sun at the ground, and the linear share of it inside the slab: within 2 % everywhere the
// cascades reach.
TEST_F(CloudShadow, AUniformSlabShadowsAsBeerLambert) {
  const DebugFlags homogeneous(clouds::shader::kFlagHomogeneous);
  clouds::Settings s;
  s.emptySpaceSkipping = false;  // the test slab ignores the weather map
  const double thickness = double(s.layerTopMetres - s.layerBottomMetres);
  s.extinctionPerMetre = static_cast<float>(1.0 / thickness);  // tau 1 straight up
  for (double elevation : {12.0, 35.0, 70.0, 90.0}) {
    CloudView view = groundView();
    view.sunElevationDegrees = elevation;
    harness().cut();
    const ShadowMapImage map = harness().renderShadowMap(view, s);
    double worst = 0.0;
    for (double distance : {0.0, 2500.0, 9000.0, 30000.0, 100000.0}) {
      for (double angle = 0.0; angle < 360.0; angle += 45.0) {
        for (double altitude : {0.0, 1000.0, 2750.0}) {
          const glm::vec3 p(float(distance * std::cos(glm::radians(angle))),
                            float(altitude - view.position.y),
                            float(distance * std::sin(glm::radians(angle))));
          const double above =
              std::clamp((double(s.layerTopMetres) - altitude) / thickness, 0.0, 1.0);
          const double expected = std::exp(-above / std::sin(glm::radians(elevation)));
          const double got = map.transmittance(p);
          worst = std::max(worst, std::abs(got - expected) / expected);
        }
      }
    }
    EXPECT_LT(worst, 0.02) << "sun " << elevation << " degrees up";
  }
}

// The lookup against a fine march towards the sun from sampled ground points (the same model,
// marched in 10 m steps): the error each cascade adds by its texel size and its steps.
TEST_F(CloudShadow, LookupAgreesWithAMarchTowardsTheSun) {
  const clouds::Settings s = cumulus();
  harness().cut();
  const CloudView view = groundView();
  const ShadowMapImage map = harness().renderShadowMap(view, s);
  const auto textures = clouds::tools::readTextures(harness());
  const auto& u = impl().lastShadowUniforms();
  const glm::vec3 light = glm::vec3(map.parameters.cascade[2]);
  // Rings of ground points in the middle of each cascade's reach.
  const double rings[][2] = {
      {200.0, 2500.0}, {5000.0, 9000.0}, {15000.0, 30000.0}, {45000.0, 100000.0}};
  const double meanBound[] = {0.05, 0.08, 0.15, 0.25};
  for (int c = 0; c < 4; ++c) {
    double sum = 0.0;
    double worst = 0.0;
    int n = 0;
    for (int i = 0; i < 160; ++i) {
      const double t = (i + 0.5) / 160.0;
      const double r = rings[c][0] + (rings[c][1] - rings[c][0]) * std::fmod(t * 7.3, 1.0);
      const double a = glm::radians(360.0 * t);
      const glm::vec3 p(float(r * std::cos(a)), -float(view.position.y), float(r * std::sin(a)));
      const double truth =
          std::exp(-clouds::tools::cpuSunOpticalDepth(textures, u, p, light, 10.0f));
      const double error = std::abs(double(map.transmittance(p)) - truth);
      sum += error;
      worst = std::max(worst, error);
      ++n;
    }
    std::printf("cascade %d (ground %.0f to %.0f km): mean |dT| %.3f, max %.3f\n", c,
                rings[c][0] / 1000.0, rings[c][1] / 1000.0, sum / n, worst);
    EXPECT_LT(sum / n, meanBound[c]) << "cascade " << c;
  }
}

// One cloud bank painted 80 km east of the camera darkens the ground beneath it; the ground near
// the camera, under a clear sky, stays lit.
TEST_F(CloudShadow, ACloudBank80KilometresAwayDarkensTheGroundBeneathIt) {
  constexpr std::uint32_t kSize = 64;
  clouds::Settings s;
  s.weatherTileMetres = 400000.0f;  // 6.25 km a texel; the bank is 3 texels across
  s.coverage = 0.5f;                // the map as painted
  s.densityVariation = 0.0f;
  std::vector<std::uint8_t> texels(kSize * kSize * 4, 0);
  const glm::dvec2 bankUv(80000.0 / 400000.0, 0.5);
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const glm::dvec2 uv((x + 0.5) / kSize, (y + 0.5) / kSize);
      const bool inBank = glm::length(uv - bankUv) * kSize < 1.6;
      std::uint8_t* t = &texels[4 * (std::size_t{y} * kSize + x)];
      t[0] = inBank ? 255 : 0;
      t[1] = 255;
      t[2] = 255;
      t[3] = 255;
    }
  }
  engine::gfx::Image painted(
      device(), engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                       VK_FORMAT_R8G8B8A8_UNORM,
                                       {kSize, kSize, 1},
                                       1,
                                       1,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                       "painted bank"});
  engine::gfx::uploadToImage(device(), painted, std::as_bytes(std::span(texels)),
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  CloudView view;
  view.position = {0.0, 300.0, 200000.0};  // weather v = 0.5
  view.sunElevationDegrees = 60.0;
  view.weatherView = painted.view();
  harness().cut();
  const ShadowMapImage map = harness().renderShadowMap(view, s);
  // The ground whose sun ray crosses the bank's middle (2.75 km up).
  const glm::vec3 light = glm::vec3(map.parameters.cascade[2]);
  const float rise = (2750.0f + 0.0f) / light.y;
  const glm::vec3 bank(80000.0f, -300.0f, 0.0f);
  const glm::vec3 underBank = bank - light * rise + glm::vec3(0.0f, light.y * rise, 0.0f);
  const float shadowed = map.transmittance(underBank);
  const float nearCamera = map.transmittance({-3000.0f, -300.0f, 2000.0f});
  const float beside = map.transmittance(underBank + glm::vec3(0.0f, 0.0f, 30000.0f));
  std::printf("bank at 80 km: ground beneath %.3f, 30 km beside it %.3f, near the camera %.3f\n",
              shadowed, beside, nearCamera);
  EXPECT_LT(shadowed, 0.2f);
  EXPECT_GT(beside, 0.99f);
  EXPECT_GT(nearCamera, 0.99f);
}

// Moving the camera 10 m (still sun, still clouds) moves the cascades by whole texels: the
// ground keeps its shadow.
TEST_F(CloudShadow, SnappedCascadesDoNotSwim) {
  const clouds::Settings s = cumulus();
  CloudView a = groundView();
  CloudView b = a;
  b.position += glm::dvec3(7.0, 2.0, 7.0);
  harness().cut();
  const ShadowMapImage first = harness().renderShadowMap(a, s);
  harness().cut();
  const ShadowMapImage second = harness().renderShadowMap(b, s);
  double worst = 0.0;
  double sum = 0.0;
  int n = 0;
  for (int y = -40; y <= 40; ++y) {
    for (int x = -40; x <= 40; ++x) {
      const glm::dvec3 world = a.position + glm::dvec3(x * 97.0, -a.position.y, y * 89.0);
      const double ta = first.transmittance(glm::vec3(world - a.position));
      const double tb = second.transmittance(glm::vec3(world - b.position));
      worst = std::max(worst, std::abs(ta - tb));
      sum += std::abs(ta - tb);
      ++n;
    }
  }
  std::printf("camera moved 10 m: ground |dT| mean %.2e, max %.2e\n", sum / n, worst);
  EXPECT_LT(worst, 0.01);
}

// After a cut every cascade is made; then one per frame, the finest every other frame. With
// time and wind running, consecutive frames differ little at the ground (no pop when a cascade
// is remade), and a cascade not remade moves with the wind.
TEST_F(CloudShadow, CascadesAreRemadeInTurnWithoutAPop) {
  const clouds::Settings s = cumulus();
  CloudView view = groundView();
  harness().cut();
  ShadowMapImage previous = harness().renderShadowMap(view, s);
  EXPECT_EQ(harness().context().lastFrameReport().shadowCascadesMade, 0xFu);
  const std::uint32_t expected[] = {1u, 2u, 1u, 4u, 1u, 8u, 1u, 2u};
  double worstMean = 0.0;
  for (std::uint32_t frame = 0; frame < 8; ++frame) {
    view.timeSeconds += 1.0 / 30.0;
    const ShadowMapImage map = harness().renderShadowMap(view, s);
    EXPECT_EQ(harness().context().lastFrameReport().shadowCascadesMade, expected[frame])
        << "frame " << frame;
    double sum = 0.0;
    int n = 0;
    for (int y = -30; y <= 30; ++y) {
      for (int x = -30; x <= 30; ++x) {
        const glm::vec3 p(float(x) * 1500.0f, -300.0f, float(y) * 1300.0f);
        sum += std::abs(double(map.transmittance(p)) - double(previous.transmittance(p)));
        ++n;
      }
    }
    worstMean = std::max(worstMean, sum / n);
    previous = map;
  }
  std::printf("frame to frame, ground |dT| mean over 90 km: worst %.2e\n", worstMean);
  EXPECT_LT(worstMean, 0.01);
}

// A cascade made over two frames in slices of rows: while half made, the atlas still holds
// the old cascade (no half-made pop); once done, it is the cascade one frame would have made
// when its first slice was made, to the bit, though the camera and the clouds moved since (the
// procedural weather map is not regenerated meanwhile: slices see it as it is).
TEST_F(CloudShadow, ACascadeMadeInSlicesEqualsOneMadeWhole) {
  clouds::Settings s = cumulus();
  s.shadowFramesPerCascade = 2;
  s.windSpeedMetresPerSecond = 30.0f;
  s.weatherUpdateSeconds = 3600.0f;
  CloudView view = groundView();
  harness().cut();
  const ShadowMapImage old = harness().renderShadowMap(view, s);
  ASSERT_EQ(harness().context().lastFrameReport().shadowCascadesMade, 0xFu);
  view.position.x += 400.0;  // five texels of the finest cascade
  view.timeSeconds += 1.0;
  const CloudView firstSlice = view;
  const ShadowMapImage half = harness().renderShadowMap(view, s);
  EXPECT_EQ(harness().context().lastFrameReport().shadowCascadesMade, 0u);
  EXPECT_EQ(half.texels, old.texels) << "half a cascade is not in the atlas";
  view.position.z += 50.0;
  view.timeSeconds += 1.0;
  const ShadowMapImage sliced = harness().renderShadowMap(view, s);
  EXPECT_EQ(harness().context().lastFrameReport().shadowCascadesMade, 1u);

  clouds::Settings whole = s;
  whole.shadowFramesPerCascade = 1;
  harness().cut();
  const ShadowMapImage once = harness().renderShadowMap(firstSlice, whole);
  const std::uint32_t n = s.shadowMapResolution;
  std::size_t differing = 0;
  std::size_t changed = 0;
  for (std::uint32_t y = 0; y < n; ++y) {
    for (std::uint32_t x = 0; x < n; ++x) {
      const std::size_t i = std::size_t{y} * sliced.width + x;
      if (sliced.texels[i] != once.texels[i]) ++differing;
      if (sliced.texels[i] != old.texels[i]) ++changed;
    }
  }
  EXPECT_EQ(differing, 0u) << "of " << n * n << " texels of the finest cascade";
  EXPECT_GT(changed, std::size_t{n}) << "the cascade was remade where the camera went";
}

TEST_F(CloudShadow, ShadowsTravelWithTheWindBetweenRefreshes) {
  clouds::Settings s = cumulus();
  s.windSpeedMetresPerSecond = 40.0f;
  s.windDirection = {1.0f, 0.0f};
  CloudView view = groundView();
  harness().cut();
  const ShadowMapImage before = harness().renderShadowMap(view, s);
  view.timeSeconds += 2.0;  // 80 m of drift; this frame remakes only the finest cascade
  const ShadowMapImage after = harness().renderShadowMap(view, s);
  ASSERT_EQ(harness().context().lastFrameReport().shadowCascadesMade, 1u);
  // In the second cascade's reach the ground now sees what was 80 m upwind.
  double moved = 0.0;
  double still = 0.0;
  for (int i = 0; i < 400; ++i) {
    const glm::vec3 p(6000.0f + float(i % 20) * 150.0f, -300.0f, -3000.0f + float(i / 20) * 150.0f);
    const glm::vec3 upwind = p - glm::vec3(80.0f, 0.0f, 0.0f);
    moved += std::abs(double(after.transmittance(p)) - double(before.transmittance(upwind)));
    still += std::abs(double(after.transmittance(p)) - double(before.transmittance(p)));
  }
  std::printf("wind: |after(p) - before(p - drift)| %.3f, |after(p) - before(p)| %.3f\n",
              moved / 400.0, still / 400.0);
  EXPECT_LT(moved / 400.0, 1e-3);
  EXPECT_GT(still / 400.0, 10.0 * (moved / 400.0 + 1e-4));
}

TEST_F(CloudShadow, HardCasesStayFinite) {
  struct Case {
    const char* name;
    double elevation, altitude, x;
    float density;
  };
  const Case cases[] = {{"sun below the horizon", -10.0, 300.0, 0.0, 1.0f},
                        {"sun on the horizon", 0.0, 300.0, 0.0, 1.0f},
                        {"sun at the zenith", 90.0, 300.0, 0.0, 1.0f},
                        {"inside the layer", 35.0, 2600.0, 0.0, 1.0f},
                        {"above the layer", 35.0, 9000.0, 0.0, 1.0f},
                        {"density 1e6", 35.0, 300.0, 0.0, 1e6f},
                        {"density 0", 35.0, 300.0, 0.0, 0.0f},
                        {"1000 km from the origin", 35.0, 300.0, 1e6, 1.0f}};
  for (const Case& c : cases) {
    clouds::Settings s = cumulus();
    s.densityMultiplier = c.density;
    CloudView view = groundView();
    view.sunElevationDegrees = c.elevation;
    view.position = {c.x, c.altitude, c.x * 0.5};
    harness().cut();
    const ShadowMapImage map = harness().renderShadowMap(view, s);
    EXPECT_TRUE(finiteMap(map)) << c.name;
    for (int i = 0; i < 64; ++i) {
      const glm::vec3 p(float(i - 32) * 900.0f, -float(c.altitude) + float(i) * 50.0f,
                        float(i % 8) * 700.0f);
      const float t = map.transmittance(p);
      EXPECT_TRUE(std::isfinite(t) && t >= 0.0f && t <= 1.0f) << c.name << ": " << t;
    }
  }
}

// Without cascades there is no shadow map: no image, no memory, nothing recorded.
TEST_F(CloudShadow, NoCascadesNoMapNoMemory) {
  clouds::Settings s = cumulus();
  s.shadowCascades = 0;
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  clouds::tools::CloudHarness h(device(), {64, 64}, options);
  const ShadowMapImage map = h.renderShadowMap(groundView(), s, 2);
  EXPECT_TRUE(map.texels.empty());
  EXPECT_EQ(map.parameters.info.x, 0.0f);
  EXPECT_EQ(h.memoryUsage().shadowBytes, 0u);
  for (const clouds::PassTiming& t : h.lastPassTimings()) {
    EXPECT_STRNE(t.name, "shadow map");
  }
  EXPECT_EQ(map.transmittance({0.0f, -300.0f, 0.0f}), 1.0f);
}

}  // namespace
