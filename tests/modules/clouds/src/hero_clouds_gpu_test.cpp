// Hero clouds (Nubis³ voxel clouds, cloud_hero.h) on lavapipe: the march draws them as the CPU
// reference does on canonical views (outside at noon, towards a low sun, inside, with the
// layer); the signed distance saves samples without changing the picture; a frame without hero
// clouds is the march without them, to the bit; hard placements stay finite; bad inputs are
// refused with the field's name.
#include <gtest/gtest.h>

#include <cmath>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "clouds/nvdf_build.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "hero_clouds.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::cumulusView;
using test::meanOpacity;

using HeroClouds = test::SharedHarnessTest<128, 72>;
using HeroCloudCost = test::CloudGpuTest;

constexpr VkExtent2D kExtent{128, 72};

// A lumpy cumulus 1.2 km wide and 1 km tall in 25 m voxels, its base centred on its frame's
// origin.
const clouds::NvdfVolume& cumulus() {
  static const clouds::NvdfVolume volume = [] {
    clouds::VoxelDensityGrid grid;
    grid.size = glm::uvec3(48, 40, 48);
    grid.voxelMetres = 25.0f;
    grid.originMetres = glm::vec3(-23.5f * 25.0f, 0.0f, -23.5f * 25.0f);
    grid.density.resize(std::size_t(48) * 40 * 48);
    grid.detailType.resize(grid.density.size());
    for (unsigned z = 0; z < 48; ++z) {
      for (unsigned y = 0; y < 40; ++y) {
        for (unsigned x = 0; x < 48; ++x) {
          const glm::vec3 p = (glm::vec3(x, y, z) - glm::vec3(23.5f, 16.0f, 23.5f)) / 20.0f;
          const float lumps = 0.15f * std::sin(3.0f * p.x) * std::sin(2.5f * p.y + 1.0f) *
                              std::sin(3.5f * p.z + 2.0f);
          const float inside = 1.0f - glm::length(p * glm::vec3(1.0f, 1.15f, 1.0f)) + lumps;
          const std::size_t i = (std::size_t(z) * 40 + y) * 48 + x;
          grid.density[i] = std::clamp(inside * 3.0f, 0.0f, 1.0f);
          grid.detailType[i] = float(y) / 39.0f;
        }
      }
    }
    clouds::Error error;
    std::optional<clouds::NvdfVolume> built = clouds::buildNvdf(grid, {}, &error);
    EXPECT_TRUE(built) << error.message;
    return *built;
  }();
  return volume;
}

// The cumulus, half as large again, 2.5 km ahead of a camera at the origin looking along -z,
// its base at 1.5 km.
clouds::HeroCloud aheadOfTheCamera() {
  clouds::HeroCloud cloud;
  cloud.positionMetres = {0.0, 1500.0, -2500.0};
  cloud.scale = 1.5f;
  cloud.yawRadians = 0.4f;
  return cloud;
}

// Settings whose layer holds no cloud: the picture is the hero cloud's.
clouds::Settings heroOnly() {
  clouds::Settings s;
  s.coverage = 0.0f;
  return s;
}

struct HeroView {
  const char* name;
  CloudView view;
  clouds::Settings settings;
};

std::vector<HeroView> heroViews() {
  std::vector<HeroView> views;
  CloudView noon;
  noon.position = {0.0, 2100.0, 0.0};
  noon.yawDegrees = 0.0;
  noon.pitchDegrees = 0.0;
  noon.sunElevationDegrees = 80.0;
  noon.heroClouds = {aheadOfTheCamera()};
  views.push_back({"outside at noon", noon, heroOnly()});
  CloudView grazing = noon;
  grazing.sunElevationDegrees = 4.0;
  grazing.sunAzimuthDegrees = 10.0;
  grazing.sunIlluminance = {9.0f, 5.0f, 2.5f};
  views.push_back({"grazing towards the sun", grazing, heroOnly()});
  CloudView inside = noon;
  inside.position = {30.0, 2100.0, -2450.0};
  inside.yawDegrees = 30.0;
  views.push_back({"inside", inside, heroOnly()});
  CloudView layer = noon;
  layer.position = {0.0, 800.0, 0.0};
  layer.pitchDegrees = 14.0;
  views.push_back({"with the layer", layer, clouds::Settings{}});
  return views;
}

class Assets {
 public:
  explicit Assets(clouds::Context& context) : context_(context) {
    const clouds::NvdfVolume* list[] = {&cumulus()};
    clouds::Error error;
    EXPECT_TRUE(context_.setHeroCloudAssets(list, &error)) << error.message;
  }
  ~Assets() { context_.setHeroCloudAssets({}, nullptr); }

 private:
  clouds::Context& context_;
};

clouds::tools::CpuTextures withHeroes(clouds::tools::CpuTextures textures,
                                      const clouds::Context::Impl& impl) {
  const clouds::NvdfVolume* list[] = {&cumulus()};
  clouds::detail::HeroAtlasLayout layout = clouds::detail::packHeroAtlas(list);
  textures.heroes.atlas = std::move(layout.texels);
  textures.heroes.extent =
      glm::uvec3(layout.extent.width, layout.extent.height, layout.extent.depth);
  textures.heroes.uniforms = impl.lastHeroClouds();
  return textures;
}

TEST_F(HeroClouds, MatchTheCpuReferenceOnCanonicalViews) {
  const Assets assets(harness().context());
  for (const HeroView& c : heroViews()) {
    const clouds::Settings settings = clouds::tools::singleFrame(c.settings);
    harness().cut();
    const CloudFrame gpu = harness().render(c.view, settings, kExtent);
    ASSERT_EQ(impl().lastHeroClouds().count.x, 1u) << c.name;
    const clouds::tools::CpuTextures textures =
        withHeroes(clouds::tools::readTextures(harness()), impl());
    const CloudFrame cpu = clouds::tools::renderCpuReference(textures, impl().lastUniforms(),
                                                             settings, harness().lastDepth());
    float peak = 1.0f;
    for (const glm::vec4& p : cpu.radiance) peak = std::max({peak, p.r, p.g, p.b});
    const double psnr = clouds::tools::psnr(gpu.radiance, cpu.radiance, peak);
    std::printf("%s: %.1f dB, mean opacity %.3f\n", c.name, psnr, meanOpacity(cpu));
    EXPECT_GE(psnr, 40.0) << c.name;
    EXPECT_GT(meanOpacity(cpu), 0.03) << c.name << " shows no cloud";
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

}  // namespace
