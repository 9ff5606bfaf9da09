// Hero clouds (Nubis³ voxel clouds, cloud_hero.h) on lavapipe: the march draws them as the CPU
// reference does on canonical views (outside at noon, towards a low sun, inside, with the
// layer); the signed distance saves samples without changing the picture; a frame without hero
// clouds is the march without them, to the bit; hard placements stay finite; bad inputs are
// refused with the field's name.
#include <gtest/gtest.h>

#include <cmath>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "cloud_hero.h"
#include "cloud_march.h"
#include "clouds/nvdf_build.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "hero_cloud_scenes.h"
#include "hero_clouds.h"
#include "synthetic_textures.h"
#include "uniforms.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::againstTheCpu;
using test::aheadOfTheCamera;
using test::Assets;
using test::CpuComparison;
using test::cumulus;
using test::cumulusAtlas;
using test::cumulusOnTheCpu;
using test::cumulusView;
using test::heroOnly;
using test::HeroView;
using test::heroViews;
using test::meanOpacity;
using test::withHeroes;

using HeroClouds = test::SharedHarnessTest<128, 72>;
using HeroCloudCost = test::CloudGpuTest;

constexpr VkExtent2D kExtent{128, 72};

TEST_F(HeroClouds, MatchTheCpuReferenceOnCanonicalViews) {
  const Assets assets(harness().context());
  for (const HeroView& c : heroViews()) {
    const clouds::Settings settings = clouds::tools::singleFrame(c.settings);
    harness().cut();
    const CloudFrame gpu = harness().render(c.view, settings, kExtent);
    ASSERT_EQ(impl().lastHeroClouds().count.x, 1u) << c.name;
    const CpuComparison compared = againstTheCpu(harness(), impl(), gpu, settings);
    std::printf("%s: %.1f dB, mean opacity %.3f\n", c.name, compared.psnr,
                meanOpacity(compared.cpu));
    EXPECT_GE(compared.psnr, 40.0) << c.name;
    EXPECT_GT(meanOpacity(compared.cpu), 0.03) << c.name << " shows no cloud";
  }
}

// Without the hero term the same views lose what the test above found: the hero cloud is
// what the pictures hold (a negative control of the comparison).
TEST_F(HeroClouds, AreWhatThePicturesHold) {
  const Assets assets(harness().context());
  const HeroView c = heroViews()[0];
  const clouds::Settings settings = clouds::tools::singleFrame(c.settings);
  const CloudFrame with = harness().render(c.view, settings, kExtent);
  CloudView none = c.view;
  none.heroClouds.clear();
  harness().cut();
  const CloudFrame without = harness().render(none, settings, kExtent);
  EXPECT_GT(meanOpacity(with), 0.03);
  EXPECT_EQ(meanOpacity(without), 0.0);
}

// A frame without hero clouds runs the march without them: its picture is the one a context
// that never had hero cloud assets makes, to the bit, and such a context holds none of their
// memory.
TEST_F(HeroClouds, AFrameWithoutThemIsTheMarchWithoutThem) {
  CloudView view = cumulusView();
  const clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  harness().cut();
  EXPECT_EQ(harness().memoryUsage().heroCloudBytes, 0u);
  const CloudFrame never = harness().render(view, settings, kExtent);
  {
    const Assets assets(harness().context());
    EXPECT_GT(harness().memoryUsage().heroCloudBytes, cumulus().voxelCount() * 4);
    harness().cut();
    const CloudFrame loaded = harness().render(view, settings, kExtent);
    ASSERT_EQ(never.radiance.size(), loaded.radiance.size());
    for (std::size_t i = 0; i < never.radiance.size(); ++i) {
      ASSERT_EQ(never.radiance[i], loaded.radiance[i]) << i;
    }
  }
  EXPECT_EQ(harness().memoryUsage().heroCloudBytes, 0u);
}

// Far, tiny, huge, and a one-voxel cloud: every output value finite and in range.
TEST_F(HeroClouds, HardPlacementsStayFinite) {
  clouds::VoxelDensityGrid one;
  one.size = glm::uvec3(1);
  one.voxelMetres = 40.0f;
  one.density = {1.0f};
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> voxel = clouds::buildNvdf(one, {}, &error);
  ASSERT_TRUE(voxel) << error.message;
  const clouds::NvdfVolume* list[] = {&cumulus(), &*voxel};
  ASSERT_TRUE(harness().context().setHeroCloudAssets(list, &error)) << error.message;
  CloudView view = heroViews()[0].view;
  clouds::HeroCloud far = aheadOfTheCamera();
  far.positionMetres.z = -100000.0;
  clouds::HeroCloud tiny = aheadOfTheCamera();
  tiny.scale = 0.01f;
  tiny.positionMetres = {2.0, 2100.0, -30.0};
  clouds::HeroCloud huge = aheadOfTheCamera();
  huge.scale = 100.0f;
  huge.positionMetres = {0.0, -50000.0, -20000.0};  // the camera inside its box
  clouds::HeroCloud single = aheadOfTheCamera();
  single.asset = 1;
  single.positionMetres = {0.0, 2100.0, -200.0};
  view.heroClouds = {far, tiny, huge, single};
  for (const clouds::Settings& s : {clouds::tools::singleFrame(heroOnly()), clouds::Settings{}}) {
    harness().cut();
    const CloudFrame frame = harness().render(view, s, kExtent, 3);
    for (const glm::vec4& p : frame.radiance) {
      ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) &&
                  std::isfinite(p.a));
      ASSERT_GE(std::min({p.r, p.g, p.b}), 0.0f);
      ASSERT_GE(p.a, 0.0f);
      ASSERT_LE(p.a, 1.0f);
    }
  }
  harness().context().setHeroCloudAssets({}, nullptr);
}

TEST_F(HeroClouds, BadInputsAreRefusedByName) {
  const Assets assets(harness().context());
  const auto refused = [&](const clouds::HeroCloud& cloud, const std::string& field) {
    CloudView view = heroViews()[0].view;
    view.heroClouds = {cloud};
    const std::string message = harness().tryRender(view, heroOnly(), kExtent);
    EXPECT_NE(message.find(field), std::string::npos) << message;
  };
  clouds::HeroCloud cloud = aheadOfTheCamera();
  cloud.asset = 1;
  refused(cloud, "FrameInputs.heroClouds[0].asset = 1: only 1 assets are loaded");
  cloud = aheadOfTheCamera();
  cloud.scale = 0.0f;
  refused(cloud, "FrameInputs.heroClouds[0].scale");
  cloud = aheadOfTheCamera();
  cloud.positionMetres.x = std::nan("");
  refused(cloud, "FrameInputs.heroClouds[0].positionMetres");
  cloud = aheadOfTheCamera();
  cloud.yawRadians = INFINITY;
  refused(cloud, "FrameInputs.heroClouds[0].yawRadians");
  cloud = aheadOfTheCamera();
  cloud.growth = 1.5f;
  refused(cloud, "FrameInputs.heroClouds[0].growth = 1.5");
  cloud = aheadOfTheCamera();
  cloud.dissipation = std::nan("");
  refused(cloud, "FrameInputs.heroClouds[0].dissipation");
  CloudView many = heroViews()[0].view;
  many.heroClouds.assign(clouds::kMaxHeroClouds + 1, aheadOfTheCamera());
  EXPECT_NE(harness().tryRender(many, heroOnly(), kExtent).find("more than the 8"),
            std::string::npos);

  clouds::NvdfVolume broken = cumulus();
  broken.fields.pop_back();
  const clouds::NvdfVolume* list[] = {&cumulus(), &broken};
  clouds::Error error;
  EXPECT_FALSE(harness().context().setHeroCloudAssets(list, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidInputs);
  EXPECT_NE(error.message.find("assets[1]: NvdfVolume.fields"), std::string::npos) << error.message;
}

// Hero clouds cast into the cloud shadow map: its texels are the CPU reference's column march
// (layer and hero clouds along each sun ray), and the ground below the cloud, towards the sun,
// is in its shadow where a sky without it is not.
TEST_F(HeroClouds, CastIntoTheShadowMap) {
  const Assets assets(harness().context());
  clouds::Settings s = heroOnly();
  s.coverage = 0.3f;  // a little layer too: the two share each column
  CloudView view = heroViews()[0].view;
  view.sunElevationDegrees = 50.0;
  harness().cut();
  const clouds::tools::ShadowMapImage map = harness().renderShadowMap(view, s);
  ASSERT_EQ(impl().lastShadowHeroClouds().count.x, 1u);
  const clouds::tools::CpuTextures textures =
      withHeroes(clouds::tools::readTextures(harness()), impl());
  clouds::tools::CpuTextures shadowTextures = textures;
  shadowTextures.heroes.uniforms = impl().lastShadowHeroClouds();
  clouds::tools::CpuTextures layerOnly = textures;
  layerOnly.heroes.uniforms.count.x = 0;
  double worstDepth = 0.0;
  double worstAltitude = 0.0;
  int heroTexels = 0;
  for (const auto& job : impl().lastShadowJobs()) {
    for (std::uint32_t y = 1; y < s.shadowMapResolution; y += 7) {
      for (std::uint32_t x = 2; x < s.shadowMapResolution; x += 7) {
        const glm::vec4 cpu = clouds::tools::cpuShadowTexel(
            shadowTextures, impl().lastShadowUniforms(), job, {x, y}, true);
        const glm::vec4 gpu =
            map.texels[std::size_t{y} * map.width + job.cascade * s.shadowMapResolution + x];
        worstDepth = std::max(worstDepth, std::abs(double(gpu.x - cpu.x)) / (1.0 + cpu.x));
        if (cpu.x > 0.1f) {
          worstAltitude = std::max(
              {worstAltitude, std::abs(double(gpu.y - cpu.y)), std::abs(double(gpu.z - cpu.z))});
        }
        const glm::vec4 layer = clouds::tools::cpuShadowTexel(
            layerOnly, impl().lastShadowUniforms(), job, {x, y}, true);
        heroTexels += cpu.x > layer.x + 0.1f ? 1 : 0;
      }
    }
  }
  std::printf(
      "hero shadow texels vs CPU: worst depth error %.2e, altitude %.2f m, %d darkened "
      "by the hero cloud\n",
      worstDepth, worstAltitude, heroTexels);
  EXPECT_GT(heroTexels, 3) << "the hero cloud must shade some of the compared columns";
  EXPECT_LT(worstDepth, 2e-3);
  EXPECT_LT(worstAltitude, 4.0);

  // The ground under the cloud, on the sun's side away from it: shaded with the hero cloud,
  // not without it (a clear layer).
  const glm::vec3 sun = clouds::tools::sunDirection(view);
  const clouds::HeroCloud cloud = aheadOfTheCamera();
  const glm::dvec3 core = cloud.positionMetres + glm::dvec3(0.0, 600.0, 0.0);
  const glm::dvec3 ground = core - glm::dvec3(sun) * (core.y / double(sun.y));
  const glm::vec3 relative(ground - view.position);
  clouds::Settings clear = s;
  clear.coverage = 0.0f;
  harness().cut();
  const float shaded = harness().renderShadowMap(view, clear).transmittance(relative);
  CloudView none = view;
  none.heroClouds.clear();
  harness().cut();
  const float lit = harness().renderShadowMap(none, clear).transmittance(relative);
  std::printf("the sun on the ground behind the hero cloud: %.3f (without it %.3f)\n", shaded, lit);
  EXPECT_LT(shaded, 0.2f);
  EXPECT_GT(lit, 0.99f);
}

// A living cloud casts what it holds: the shadow map's living variant against the CPU column,
// and less shade than the grown cloud's.
TEST_F(HeroClouds, ALivingCloudCastsWhatItHolds) {
  const Assets assets(harness().context());
  const clouds::Settings s = heroOnly();
  CloudView view = heroViews()[0].view;
  view.sunElevationDegrees = 50.0;
  const auto shade = [&](float dissipation, double* worstDepth) {
    view.heroClouds[0].dissipation = dissipation;
    harness().cut();
    const clouds::tools::ShadowMapImage map = harness().renderShadowMap(view, s);
    clouds::tools::CpuTextures textures =
        withHeroes(clouds::tools::readTextures(harness()), impl());
    textures.heroes.uniforms = impl().lastShadowHeroClouds();
    double total = 0.0;
    for (const auto& job : impl().lastShadowJobs()) {
      for (std::uint32_t y = 1; y < s.shadowMapResolution; y += 5) {
        for (std::uint32_t x = 2; x < s.shadowMapResolution; x += 5) {
          const glm::vec4 cpu = clouds::tools::cpuShadowTexel(textures, impl().lastShadowUniforms(),
                                                              job, {x, y}, true);
          const glm::vec4 gpu =
              map.texels[std::size_t{y} * map.width + job.cascade * s.shadowMapResolution + x];
          *worstDepth = std::max(*worstDepth, std::abs(double(gpu.x - cpu.x)) / (1.0 + cpu.x));
          total += gpu.x;
        }
      }
    }
    return total;
  };
  double worstGrown = 0.0;
  double worstLiving = 0.0;
  const double grown = shade(0.0f, &worstGrown);
  const double living = shade(0.5f, &worstLiving);
  std::printf(
      "shadow map optical depth, summed: grown %.1f, half dissipated %.1f; worst "
      "relative error against the CPU %.2e, %.2e\n",
      grown, living, worstGrown, worstLiving);
  EXPECT_LT(worstLiving, 2e-3);
  EXPECT_GT(living, 0.05 * grown);
  EXPECT_LT(living, 0.8 * grown);
}

// Nubis³'s SDF march: the signed distance lets the march jump the clear air inside a hero
// cloud's box (and the air between the layer and the box): far fewer samples, and no less
// accurate than the dense march against the converged Reference (whose finer steps and
// averaged jitter make the picture the march converges to).
TEST_F(HeroCloudCost, TheSignedDistanceSavesSamplesNotAccuracy) {
  auto r = renderer();
  const clouds::NvdfVolume* list[] = {&cumulus()};
  clouds::Error error;
  ASSERT_TRUE(r->context().setHeroCloudAssets(list, &error)) << error.message;
  const CloudView view = heroViews()[0].view;
  clouds::Settings on = clouds::tools::singleFrame(heroOnly());
  clouds::Settings off = on;
  off.emptySpaceSkipping = false;
  const CloudFrame skipped = r->render(view, on, test::kExtent);
  const clouds::WorkCounters with = r->lastWorkCounters();
  r->cut();
  const CloudFrame marched = r->render(view, off, test::kExtent);
  const clouds::WorkCounters without = r->lastWorkCounters();
  r->cut();
  const CloudFrame converged =
      r->renderAveraged(view, clouds::referenceSettings(heroOnly()), test::kExtent, 16);
  ASSERT_GT(meanOpacity(converged), 0.03);
  float peak = 1.0f;
  for (const glm::vec4& p : converged.radiance) peak = std::max({peak, p.r, p.g, p.b});
  const double skippedDb = clouds::tools::psnr(skipped.radiance, converged.radiance, peak);
  const double marchedDb = clouds::tools::psnr(marched.radiance, converged.radiance, peak);
  const double fraction = double(with.viewSamples) / double(without.viewSamples);
  std::printf(
      "against the Reference: SDF march %.1f dB, dense march %.1f dB; %.2f of its "
      "samples\n",
      skippedDb, marchedDb, fraction);
  EXPECT_GE(skippedDb, marchedDb - 0.5);
  EXPECT_LT(fraction, 0.5);
}

// A layer step ends at the hero clouds' box. Rays that cross an empty layer (coverage 0,
// stepped, not skipped) in its coarse steps reach the cumulus as the rays do that start at its
// box (the layer put out of their way): the march inside the box is the same, so the cloud is
// too. (A coarse layer step that ran on into the box took its first sample of hero cloud with
// the layer's 200 m step: dark lines down a hero cloud, where a jump over an empty cell ended
// just short of the box.)
TEST(HeroCloudMarch, ALayerStepEndsAtTheHeroBox) {
  CloudView view = heroViews()[0].view;  // the cumulus 2.5 km ahead, the camera 2.1 km up
  view.verticalFovDegrees = 25.0f;       // the rays on the cloud
  const clouds::HeroCloud cloud = view.heroClouds[0];
  clouds::tools::CpuTextures textures = test::syntheticTextures();
  textures.heroes = test::cumulusPlaced(cloud, view.position).heroes;
  const VkExtent2D extent{48, 27};
  const auto transmittances = [&](const clouds::Settings& s) {
    clouds::FrameInputs in;
    in.view = clouds::tools::viewMatrix(view);
    in.projection = clouds::tools::projectionMatrix(view, extent);
    in.cameraPosition = view.position;
    in.sunDirection = clouds::tools::sunDirection(view);
    clouds::detail::UniformContext context;
    context.traceExtent = extent;
    context.fullExtent = extent;
    const clouds::shader::CloudUniforms u = clouds::detail::buildUniforms(in, s, context);
    clouds::shader::MarchOptions options{};
    options.cheapSampling = 1u;
    options.lightSteps = 1u;
    const clouds::tools::CpuHeroScope scope(textures, in.sunDirection);
    std::vector<float> t;
    for (unsigned y = 0; y < extent.height; ++y) {
      for (unsigned x = 0; x < extent.width; ++x) {
        const glm::vec3 ray = clouds::shader::pixelRayDirection(
            glm::vec2(x, y) + 0.5f, glm::vec2(extent.width, extent.height), u);
        for (const float jitter : {0.1f, 0.4f, 0.7f}) {
          t.push_back(clouds::shader::marchClouds(ray, clouds::shader::kInfiniteDistance, jitter,
                                                  glm::vec3(0.5f), u, options)
                          .transmittance);
        }
      }
    }
    return t;
  };
  clouds::Settings crossed = heroOnly();
  crossed.emptySpaceSkipping = false;
  crossed.heroDetail = clouds::HeroDetail::Off;
  crossed.coarseStepFactor = 3.3f;  // High's: 200 m coarse steps
  ASSERT_LT(crossed.layerBottomMetres, view.position.y);
  ASSERT_GT(crossed.layerTopMetres, view.position.y + 1000.0);
  clouds::Settings clear = crossed;
  clear.layerBottomMetres = 20000.0f;
  clear.layerTopMetres = 25000.0f;
  const std::vector<float> through = transmittances(crossed);
  const std::vector<float> fromTheBox = transmittances(clear);
  double difference = 0.0;
  double largest = 0.0;
  int cloudy = 0;
  for (std::size_t i = 0; i < through.size(); ++i) {
    difference += std::abs(through[i] - fromTheBox[i]);
    largest = std::max(largest, double(std::abs(through[i] - fromTheBox[i])));
    cloudy += fromTheBox[i] < 0.9f ? 1 : 0;
  }
  difference /= double(through.size());
  std::printf("%d of %zu rays in cloud; transmittance apart %.5f on average, %.4f at most\n",
              cloudy, through.size(), difference, largest);
  ASSERT_GT(cloudy, int(through.size() / 10));
  EXPECT_LT(largest, 1e-3);  // the same march, but for rounding (0.012 stepping into the box)
}

// A cloud's life (HeroCloud::growth, ::dissipation) on the CPU, with the shared model's own
// functions: the cumulus at the origin of a camera at the origin, so camera-relative points
// are its frame's metres (its base at y = 0, its core about 400 m up, 500 m in radius).
class HeroLife {
 public:
  explicit HeroLife(clouds::HeroCloud cloud) {
    textures_.heroes = cumulusOnTheCpu(
        clouds::detail::heroCloudUniforms(cumulusAtlas().assets, {&cloud, 1}, glm::dvec3(0.0)));
    uniforms_.extinctionPerMetre = 0.004f;  // about 3 optical depths through the core
  }
  bool present() const { return textures_.heroes.uniforms.count.x == 1; }
  // The profile its voxels hold at index coordinate `c`, and the weight its life gives it.
  glm::vec2 profileAndWeight(glm::vec3 c) const {
    const clouds::tools::CpuHeroScope scope(textures_);
    const clouds::shader::HeroCloudInstance& h = textures_.heroes.uniforms.instance[0];
    const glm::vec4 fields = clouds::shader::heroFields(h, c);
    return {fields.x, clouds::shader::heroLifeWeight(h, c, fields.w)};
  }
  float extinction(glm::vec3 metres) const {
    const clouds::tools::CpuHeroScope scope(textures_);
    return clouds::shader::heroField(metres, uniforms_).sigmaT;
  }
  // Transmittance along x through the cloud at height y and depth z (m), in 5 m steps.
  float transmittanceAlongX(float y, float z) const {
    const clouds::tools::CpuHeroScope scope(textures_);
    float tau = 0.0f;
    for (float x = -700.0f; x <= 700.0f; x += 5.0f) {
      tau += clouds::shader::heroField(glm::vec3(x, y, z), uniforms_).sigmaT * 5.0f;
    }
    return std::exp(-tau);
  }
  // How far in from x = -700 m the first cloud lies along that line (m).
  float firstCloudAlongX(float y, float z) const {
    for (float x = -700.0f; x <= 700.0f; x += 2.0f) {
      if (extinction({x, y, z}) > 0.0f) return x + 700.0f;
    }
    return 1400.0f;
  }

 private:
  clouds::tools::CpuTextures textures_;
  clouds::shader::CloudUniforms uniforms_{};
};

clouds::HeroCloud living(float growth, float dissipation) {
  clouds::HeroCloud cloud;
  cloud.growth = growth;
  cloud.dissipation = dissipation;
  return cloud;
}

// The camera's place against the boxes: in one, near one (within the margin), or out.
TEST(HeroCloudLives, TheCameraIsInABoxOrNot) {
  const auto inBox = [&](glm::dvec3 camera, float margin) {
    const clouds::HeroCloud cloud;  // its base's centre at the origin, 1200 x 1000 x 1200 m
    const clouds::shader::HeroCloudUniforms block =
        clouds::detail::heroCloudUniforms(cumulusAtlas().assets, {&cloud, 1}, camera);
    return clouds::detail::cameraInHeroCloudBox(block, margin);
  };
  EXPECT_TRUE(inBox({0.0, 500.0, 0.0}, 0.0f));
  EXPECT_TRUE(inBox({580.0, 990.0, -580.0}, 0.0f));
  EXPECT_FALSE(inBox({0.0, 1100.0, 0.0}, 50.0f));
  EXPECT_TRUE(inBox({0.0, 1100.0, 0.0}, 120.0f));
  EXPECT_FALSE(inBox({0.0, 500.0, -700.0}, 0.0f));
  const clouds::shader::HeroCloudUniforms none{};
  EXPECT_FALSE(clouds::detail::cameraInHeroCloudBox(none, 1e9f));
}

// Grown and not dissipating, a cloud is its voxels: wherever their profile reaches, its life
// weighs exactly 1 (so the life costs a grown cloud's picture nothing, to the bit), at any
// scale.
TEST(HeroCloudLives, AGrownCloudIsItsVoxels) {
  for (const float scale : {0.01f, 1.0f, 37.0f}) {
    clouds::HeroCloud cloud = living(1.0f, 0.0f);
    cloud.scale = scale;
    const HeroLife life(cloud);
    int reached = 0;
    for (float z = -1.0f; z <= 48.0f; z += 0.61f) {
      for (float y = -1.0f; y <= 40.0f; y += 0.53f) {
        for (float x = -1.0f; x <= 48.0f; x += 0.67f) {
          const glm::vec2 at = life.profileAndWeight({x, y, z});
          if (at.x == 0.0f) continue;
          ++reached;
          ASSERT_EQ(at.y, 1.0f) << scale << " at (" << x << ", " << y << ", " << z << ")";
        }
      }
    }
    EXPECT_GT(reached, 10000);
  }
}

// Growing, its top rises from its base: half grown, nothing in its upper part (where the grown
// cloud is thick), and cloud near its base.
TEST(HeroCloudLives, GrowingRisesFromTheBase) {
  const HeroLife grown(living(1.0f, 0.0f));
  const HeroLife growing(living(0.35f, 0.0f));
  EXPECT_LT(grown.transmittanceAlongX(650.0f, 0.0f), 0.5f);
  EXPECT_EQ(growing.transmittanceAlongX(650.0f, 0.0f), 1.0f);
  EXPECT_LT(growing.transmittanceAlongX(120.0f, 0.0f), 0.9f);
  // Just born it is next to nothing (no deep core pops in with it), and at 0 not drawn at all.
  const HeroLife justBorn(living(0.02f, 0.0f));
  for (const float y : {20.0f, 120.0f, 300.0f, 450.0f}) {
    EXPECT_GT(justBorn.transmittanceAlongX(y, 0.0f), 0.99f) << y << " m up";
  }
  const HeroLife newborn(living(0.0f, 0.0f));
  EXPECT_FALSE(newborn.present());
}

// Growing, it also swells from its cores out (its edge lies further in than the grown
// cloud's), and dissipating it thins from the edge in: at its edge nothing, in its core the
// same cloud, faded, to the last.
TEST(HeroCloudLives, ItsEdgeMovesAlongTheDistanceField) {
  const HeroLife grown(living(1.0f, 0.0f));
  const HeroLife growing(living(0.35f, 0.0f));
  const float grownEdge = grown.firstCloudAlongX(150.0f, 0.0f);
  EXPECT_GT(growing.firstCloudAlongX(150.0f, 0.0f), grownEdge + 50.0f);

  const HeroLife dissipating(living(1.0f, 0.5f));
  const glm::vec3 edge(grownEdge - 700.0f + 20.0f, 150.0f, 0.0f);
  const glm::vec3 core(0.0f, 400.0f, 0.0f);
  ASSERT_GT(grown.extinction(edge), 0.0f);
  EXPECT_EQ(dissipating.extinction(edge), 0.0f);
  // Half dissipated (eased: 0.5), the core keeps its shape at half its density.
  EXPECT_NEAR(dissipating.extinction(core), 0.5f * grown.extinction(core),
              1e-6f * grown.extinction(core));
  // Nearly gone, the core is the last of it: thin, and still there.
  const HeroLife fading(living(1.0f, 0.95f));
  EXPECT_GT(fading.extinction(core), 0.0f);
  EXPECT_LT(fading.extinction(core), 0.05f * grown.extinction(core));
  const HeroLife gone(living(1.0f, 1.0f));
  EXPECT_FALSE(gone.present());
}

// No pops: as growth runs 0 -> 1 and then dissipation 0 -> 1, the transmittance of each line
// through the cloud changes step by step in proportion to the step. Halving the step halves
// each line's largest change (a jump anywhere would not shrink); so the default life (300 s to
// grow and to dissipate, HeroCloudLifecycle) at 30 frames a second changes no line by a
// visible 1/255 from one frame to the next.
TEST(HeroCloudLives, ALifeNeverPops) {
  // Height and depth (m) of lines along x: base, flanks, core, cap.
  const std::vector<glm::vec2> lines = {
      {120.0f, 0.0f},   {300.0f, -200.0f}, {450.0f, 150.0f},  {600.0f, 0.0f}, {750.0f, 60.0f},
      {300.0f, 380.0f}, {20.0f, -90.0f},   {500.0f, -330.0f}, {790.0f, 0.0f}, {400.0f, 0.0f}};
  const auto largestChanges = [&](int steps) {
    std::vector<float> largest(lines.size(), 0.0f);
    std::vector<float> previous(lines.size(), 1.0f);  // growth 0: clear
    for (int k = 1; k <= 2 * steps; ++k) {
      const float growth = std::min(float(k) / float(steps), 1.0f);
      const float dissipation = std::max(float(k - steps) / float(steps), 0.0f);
      const HeroLife life(living(growth, dissipation));
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const float t = life.present() ? life.transmittanceAlongX(lines[i].x, lines[i].y) : 1.0f;
        largest[i] = std::max(largest[i], std::abs(t - previous[i]));
        previous[i] = t;
      }
    }
    return largest;
  };
  const std::vector<float> coarse = largestChanges(160);
  const std::vector<float> fine = largestChanges(320);
  float worst = 0.0f;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::printf(
        "line at %4.0f m up, %4.0f m deep: largest change a step %.4f (160 steps a "
        "phase), %.4f (320)\n",
        lines[i].x, lines[i].y, coarse[i], fine[i]);
    ASSERT_GT(coarse[i], 1e-3f) << "every line must cross the cloud";
    EXPECT_LT(fine[i], 0.6f * coarse[i]) << "a jump on the line at " << lines[i].x << " m";
    worst = std::max(worst, fine[i]);
  }
  const float framesAPhase = 300.0f * 30.0f;
  EXPECT_LT(worst * 320.0f / framesAPhase, 1.0f / 255.0f);
}

// The GPU lives a cloud's life as the CPU reference does: a growing and a dissipating cumulus,
// outside at noon, at >= 40 dB, each less cloud than the grown one and more than none.
TEST_F(HeroClouds, ALifeMatchesTheCpuReference) {
  const Assets assets(harness().context());
  HeroView c = heroViews()[0];
  const clouds::Settings settings = clouds::tools::singleFrame(c.settings);
  harness().cut();
  const double grown = meanOpacity(harness().render(c.view, settings, kExtent));
  for (const glm::vec2 life : {glm::vec2(0.45f, 0.0f), glm::vec2(1.0f, 0.6f)}) {
    c.view.heroClouds[0].growth = life.x;
    c.view.heroClouds[0].dissipation = life.y;
    harness().cut();
    const CloudFrame gpu = harness().render(c.view, settings, kExtent);
    const CpuComparison compared = againstTheCpu(harness(), impl(), gpu, settings);
    std::printf("growth %.2f, dissipation %.2f: %.1f dB, mean opacity %.3f (grown %.3f)\n", life.x,
                life.y, compared.psnr, meanOpacity(compared.cpu), grown);
    EXPECT_GE(compared.psnr, 40.0);
    EXPECT_GT(meanOpacity(gpu), 0.1 * grown);
    EXPECT_LT(meanOpacity(gpu), 0.9 * grown);
  }
}

// Settings whose layer holds no cloud and lies far above the flight below: the camera is in a
// hero cloud, not in the layer.
clouds::Settings aboveTheFlight() {
  clouds::Settings s = heroOnly();
  s.layerBottomMetres = 6000.0f;
  s.layerTopMetres = 8000.0f;
  return s;
}

// The camera in or near a hero cloud's box is told apart from one outside it (the temporal
// reconstruction refreshes more while it moves there).
TEST_F(HeroClouds, TheReportSaysWhenTheCameraIsInAHeroCloud) {
  const Assets assets(harness().context());
  const clouds::Settings settings = clouds::tools::singleFrame(aboveTheFlight());
  for (const HeroView& c : heroViews()) {
    if (std::string(c.name) == "with the layer") continue;
    harness().cut();
    harness().render(c.view, settings, kExtent);
    const clouds::FrameReport report = harness().context().lastFrameReport();
    EXPECT_EQ(report.insideHeroCloud, std::string(c.name) == "inside") << c.name;
    EXPECT_FALSE(report.insideLayer) << c.name;
  }
}

// Whether the camera of the frame `r` last rendered stands in the test cumulus's density (the
// shared model on the CPU).
bool cameraInTheCumulus(clouds::tools::CloudHarness& r) {
  clouds::tools::CpuTextures textures;
  textures.heroes =
      cumulusOnTheCpu(clouds::detail::ContextAccess::impl(r.context()).lastHeroClouds());
  textures.heroes.noise = r.readHeroNoise();
  clouds::shader::CloudUniforms u{};
  u.extinctionPerMetre = 1.0f;
  const clouds::tools::CpuHeroScope scope(textures);
  return clouds::shader::heroField(glm::vec3(0.0f), u).sigmaT > 0.0f;
}

// How far a flown frame differs from a history-free frame of the same view: the worst
// transmittance difference, and the worst radiance difference over `brightest`.
struct Ghost {
  float transmittance = 0.0f;
  float radiance = 0.0f;
};
Ghost ghostOf(const CloudFrame& flown, const CloudFrame& alone, float brightest) {
  Ghost g;
  for (std::size_t i = 0; i < flown.radiance.size(); ++i) {
    g.transmittance =
        std::max(g.transmittance, std::abs(flown.radiance[i].a - alone.radiance[i].a));
    const glm::vec3 d = glm::abs(glm::vec3(flown.radiance[i]) - glm::vec3(alone.radiance[i]));
    g.radiance = std::max(g.radiance, std::max({d.r, d.g, d.b}) / brightest);
  }
  return g;
}

// Leaving a cloud leaves no ghost: flown at 300 m/s at High out of the cumulus's far side, two
// frames after the camera left its density no pixel of the frame differs from a history-free
// frame's by more than 4/255 (transmittance, and radiance of the path's brightest cloud). The
// history the reconstruction kept of the air it flew through (every pixel's cloud began at the
// camera) is clamped to the fresh samples (reconstruct.comp's kFlownThroughMoves); left to the
// depth's parallax, it held the cloud's grey: 0.017 of transmittance. The voxels are kept smooth
// (HeroDetail::Off): with the half-metre detail the flown frame, which averages many frames'
// samples of it, and a frame of one sample set differ by up to 0.22 at a pixel, which this
// measure cannot tell from a ghost.
TEST_F(HeroCloudCost, LeavingACloudLeavesNoGhost) {
  auto flying = renderer();
  auto fresh = renderer();
  const clouds::NvdfVolume* list[] = {&cumulus()};
  clouds::Error error;
  for (auto* r : {flying.get(), fresh.get()}) {
    ASSERT_TRUE(r->context().setHeroCloudAssets(list, &error)) << error.message;
  }
  clouds::Settings high = clouds::settingsFor(clouds::Quality::High, aboveTheFlight());
  high.heroDetail = clouds::HeroDetail::Off;
  CloudView view = heroViews()[0].view;
  view.sunElevationDegrees = 50.0;
  view.position = {100.0, 2000.0, -2900.0};  // inside, 250 m before the far side's edge
  int left = -1;
  float brightest = 1.0f;
  for (int frame = 0; frame < 80; ++frame, view.position.z -= 10.0) {
    const CloudFrame flown = flying->render(view, high, test::kExtent);
    for (const glm::vec4& p : flown.radiance) brightest = std::max({brightest, p.r, p.g, p.b});
    const bool inside = cameraInTheCumulus(*flying);
    ASSERT_TRUE(frame > 0 || inside) << "the flight starts in the cloud";
    if (!inside && left < 0) left = frame;
    if (left < 0 || frame < left + 2) continue;
    fresh->cut();
    const CloudFrame alone = fresh->render(view, high, test::kExtent);
    const Ghost ghost = ghostOf(flown, alone, brightest);
    std::printf("left at frame %d; two frames out: transmittance off by %.4f, radiance %.4f\n",
                left, ghost.transmittance, ghost.radiance);
    EXPECT_LE(ghost.transmittance, 4.0f / 255.0f);
    EXPECT_LE(ghost.radiance, 4.0f / 255.0f);
    EXPECT_GT(left, 5) << "flown in the cloud for a while";
    return;
  }
  FAIL() << "the flight never left the cloud";
}

// The flight target, not met yet (so not run by default; run it with
// --gtest_also_run_disabled_tests). A pilot's flight from clear air into the cumulus and out of
// its far side at 300 m/s, at High (temporal reconstruction and upsampling): along the path
// each frame should stay within 33 dB of the converged Reference of that frame, and two frames
// after leaving the cloud no pixel should hold a ghost of it (the frame a history-free
// render's, within 4/255). Measured (docs/measurements.md), with the half-metre detail and the
// near/far split: 44 to 56 dB inside, but 24.0 and 23.1 dB approaching the cloud and 26.0
// leaving it (smooth voxels: 28.9 and 32.4 approaching, where a history-free High frame scores
// 31.5 and 30.5: its half-resolution picture of the near cloud at 160x90). Two frames out the
// detail's sampling differs from a history-free frame's by 0.13 of transmittance, which this
// measure cannot tell from a ghost; the ghost of smooth voxels is held by
// LeavingACloudLeavesNoGhost.
TEST_F(HeroCloudCost, DISABLED_AFlightThroughAHeroCloudStaysCloseAndLeavesNoGhost) {
  auto flying = renderer();
  auto fresh = renderer();
  auto converged = renderer();
  const clouds::NvdfVolume* list[] = {&cumulus()};
  clouds::Error error;
  for (auto* r : {flying.get(), fresh.get(), converged.get()}) {
    ASSERT_TRUE(r->context().setHeroCloudAssets(list, &error)) << error.message;
  }
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High, aboveTheFlight());
  const clouds::Settings reference = clouds::referenceSettings(aboveTheFlight());
  CloudView view = heroViews()[0].view;
  view.sunElevationDegrees = 50.0;
  view.position = {100.0, 2000.0, -1200.0};
  float brightest = 1.0f;  // the path's brightest cloud: the white the ghost is measured on
  constexpr double kMetresPerFrame = 10.0;  // 300 m/s at 30 frames a second
  constexpr int kReferenceEvery = 24;

  double worstDb = 1e9;
  int entered = -1;
  int left = -1;
  int frame = 0;
  for (; frame < 400; ++frame, view.position.z -= kMetresPerFrame) {
    const CloudFrame flown = flying->render(view, high, test::kExtent);
    ASSERT_TRUE(test::allValid(flown)) << "frame " << frame;
    const bool inside = cameraInTheCumulus(*flying);
    if (inside && entered < 0) entered = frame;
    if (!inside && entered >= 0 && left < 0) left = frame;
    if (frame % kReferenceEvery == kReferenceEvery - 1) {
      converged->cut();
      const CloudFrame truth = converged->renderAveraged(view, reference, test::kExtent, 8);
      float peak = 1.0f;
      for (const glm::vec4& p : truth.radiance) peak = std::max({peak, p.r, p.g, p.b});
      brightest = std::max(brightest, peak);
      const double db = clouds::tools::psnr(flown.radiance, truth.radiance, peak);
      std::printf("frame %3d (z %6.0f m, %s): %.1f dB against the Reference\n", frame,
                  view.position.z, inside ? "inside" : "outside", db);
      worstDb = std::min(worstDb, db);
    }
    if (left >= 0 && frame == left + 2) {
      fresh->cut();
      const CloudFrame alone = fresh->render(view, high, test::kExtent);
      const Ghost ghost = ghostOf(flown, alone, brightest);
      std::printf(
          "two frames out (frame %d): worst transmittance difference %.4f, radiance %.4f "
          "of the path's brightest\n",
          frame, ghost.transmittance, ghost.radiance);
      EXPECT_LE(ghost.transmittance, 4.0f / 255.0f);
      EXPECT_LE(ghost.radiance, 4.0f / 255.0f);
      break;
    }
  }
  std::printf("entered at frame %d, left at %d; worst %.1f dB\n", entered, left, worstDb);
  ASSERT_GT(entered, 10) << "the flight starts in clear air";
  ASSERT_GT(left, entered + 20) << "and flies through the cloud";
  EXPECT_GE(worstDb, 33.0);
}

}  // namespace
