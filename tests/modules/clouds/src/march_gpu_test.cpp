// The march shader on lavapipe: analytic slab transmittance, white furnace, agreement with the
// CPU reference on canonical views, no NaN/Inf/negative output over a sweep of hard cases,
// depth-buffer occlusion, far-from-origin and million-second-uptime invariance, painted weather
// maps, sky ambient, and clear errors for bad inputs. Every test is validation-clean (the fixture
// fails otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "cloud_march.h"
#include "clouds_test_shaders/count_invalid.comp.spv.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "engine/gfx/descriptors.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/upload.h"
#include "gpu_test.h"

namespace {

using namespace clouds::shader;
using clouds::tools::CloudView;

using CloudMarch = test::SharedHarnessTest<160, 90>;

clouds::Settings furnaceSettings(float density, std::uint32_t steps) {
  clouds::Settings s;
  s.densityMultiplier = density;
  s.maxViewSteps = steps;
  s.albedo = 1.0f;
  s.sunStrength = 0.0f;
  s.inScatterStrength = 0.0f;
  s.ambientOcclusionStrength = 0.0f;
  s.ambientStrength = 1.0f;
  s.coverage = 0.75f;
  return s;
}

TEST_F(CloudMarch, HomogeneousSlabTransmittanceMatchesBeerLambert) {
  const VkExtent2D extent{16, 8};
  const DebugFlags homogeneous(kFlagHomogeneous);
  for (double tau : {0.0, 0.01, 1.0, 5.0, 1e4}) {
    for (double pitch : {89.0, 30.0, 8.0}) {
      // One full-resolution frame (per-pixel rays are checked), no weather cells skipped (the
      // homogeneous test slab ignores the weather map).
      clouds::Settings s = clouds::tools::singleFrame({});
      s.emptySpaceSkipping = false;
      s.extinctionPerMetre = static_cast<float>(tau / 2500.0);
      s.viewStepGrowth = 0.0f;
      s.viewStepMetres = 100.0f;
      s.maxViewSteps = 4096;
      s.transmittanceCutoff = 0.0f;
      s.cheapSampling = false;
      CloudView view;
      view.pitchDegrees = pitch;
      view.verticalFovDegrees = 20.0f;
      const clouds::tools::CloudFrame frame = harness().render(view, s, extent);
      const CloudUniforms& u = impl().lastUniforms();
      for (std::uint32_t y = 0; y < extent.height; ++y) {
        for (std::uint32_t x = 0; x < extent.width; ++x) {
          const vec3 dir = pixelRayDirection(vec2(x, y) + 0.5f, vec2(16.0f, 8.0f), u);
          const vec2 segment = layerSegment(u.cameraAltitudeMetres, dir.y, u);
          const double end = std::min(double(segment.y), double(u.maxDistanceMetres));
          const double path = std::max(0.0, end - double(segment.x));
          const double expected = std::exp(-double(u.extinctionPerMetre) * path);
          const float got = frame.radiance[std::size_t{y} * extent.width + x].a;
          ASSERT_NEAR(got, expected, 1e-3) << "tau " << tau << " pitch " << pitch << " pixel " << x
                                           << "," << y << " path " << path;
        }
      }
    }
  }
}

TEST_F(CloudMarch, WhiteFurnaceConservesEnergy) {
  const VkExtent2D extent{48, 27};
  for (double altitude : {300.0, 2500.0}) {
    for (float density : {0.0f, 0.01f, 1.0f, 100.0f, 1e4f, 1e6f}) {
      for (std::uint32_t steps : {4u, 64u, 512u}) {
        CloudView view;
        view.position.y = altitude;
        view.ambientTop = glm::vec3(1.0f);
        view.ambientBottom = glm::vec3(1.0f);
        const clouds::tools::CloudFrame frame = harness().render(
            view, clouds::tools::singleFrame(furnaceSettings(density, steps)), extent);
        for (const glm::vec4& p : frame.radiance) {
          for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(p[c] + p.a, 1.0f, 1e-3f)
                << "altitude " << altitude << " density " << density << " steps " << steps;
          }
        }
      }
    }
  }
}

// The multiple-scattering term's physical anchor: sunlight on a thick, non-absorbing cloud is
// mostly reflected (two-stream theory puts the plane albedo of an optical depth of 100 with
// g = 0.85 at 0.92). Single scattering alone reflects a small fraction of it, which is why the
// octaves exist; with too little of them (b = 0.7 and 4 octaves, the defaults until 2026-11,
// reflected 0.23 to 0.44 here) a sunlit cloud side reads as grey as its ambient-lit base. The
// check is on the reflectance factor (the radiance over a white Lambertian plane's) at six
// geometries: each above 0.5 and, since it may exceed 1 towards a low sun as thick clouds' does,
// below 1.3; their mean, a rough stand-in for the plane albedo, between 0.6 and 1.
TEST_F(CloudMarch, AThickSunlitSlabReflectsMostOfTheSun) {
  const VkExtent2D extent{8, 8};
  const DebugFlags homogeneous(kFlagHomogeneous);
  clouds::Settings s = clouds::tools::singleFrame({});
  s.emptySpaceSkipping = false;
  s.albedo = 1.0f;
  s.ambientStrength = 0.0f;
  s.inScatterStrength = 0.0f;  // an art term: the physics alone here
  s.maxViewSteps = 512;
  s.lightSteps = 16;
  double sum = 0.0;
  int geometries = 0;
  for (double sunElevation : {80.0, 50.0, 25.0}) {
    for (double viewPitch : {-85.0, -40.0}) {
      CloudView view;
      view.position.y = double(s.layerTopMetres) + 500.0;
      view.pitchDegrees = viewPitch;
      view.verticalFovDegrees = 5.0f;
      view.sunElevationDegrees = sunElevation;
      view.sunAzimuthDegrees = 90.0;  // beside the view: neither glory nor forward peak
      view.sunIlluminance = glm::vec3(1.0f);
      const clouds::tools::CloudFrame frame = harness().render(view, s, extent);
      double radiance = 0.0;
      for (const glm::vec4& p : frame.radiance) radiance += p.r;
      radiance /= double(frame.radiance.size());
      // Bidirectional reflectance factor: the radiance over that of a white Lambertian plane.
      const double reflectance = kPi * radiance / std::sin(glm::radians(sunElevation));
      EXPECT_GT(reflectance, 0.5) << "sun " << sunElevation << " view pitch " << viewPitch;
      EXPECT_LT(reflectance, 1.3) << "sun " << sunElevation << " view pitch " << viewPitch;
      sum += reflectance;
      ++geometries;
    }
  }
  EXPECT_GT(sum / geometries, 0.6);
  EXPECT_LT(sum / geometries, 1.0);
}

TEST_F(CloudMarch, SkyTextureAmbientAndAWhiteGroundKeepTheFurnaceWhite) {
  // A uniform sky radiance of 1 replaces the ambient colours (set to 0 here): the furnace still
  // composites to 1, so the sky pass averaged the texture correctly.
  engine::gfx::Image sky(
      device(), engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                       VK_FORMAT_R32G32B32A32_SFLOAT,
                                       {16, 8, 1},
                                       1,
                                       1,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                       "test sky"});
  std::vector<float> ones(16 * 8 * 4, 1.0f);
  engine::gfx::uploadToImage(device(), sky, std::as_bytes(std::span(ones)),
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  CloudView view;
  view.ambientTop = glm::vec3(0.0f);
  view.ambientBottom = glm::vec3(0.0f);
  view.skyView = sky.view();
  const clouds::tools::CloudFrame frame =
      harness().render(view, furnaceSettings(1.0f, 128), {48, 27});
  float opacity = 0.0f;
  for (const glm::vec4& p : frame.radiance) {
    opacity = std::max(opacity, 1.0f - p.a);
    ASSERT_NEAR(p.r + p.a, 1.0f, 2e-3f);
  }
  EXPECT_GT(opacity, 0.5f) << "the view must contain cloud for the check to mean anything";

  // A white ground under that sky, with no sun, sends back the sky's radiance: bases lit by it
  // (FrameInputs::groundAlbedo) keep the furnace white, from the sky image's horizon band and
  // hemisphere as from the same light given as inputs. A grey ground darkens it.
  view.sunIlluminance = glm::vec3(0.0f);
  CloudView given = view;
  given.skyView = VK_NULL_HANDLE;
  given.ambientTop = glm::vec3(1.0f);
  given.ambientBottom = glm::vec3(1.0f);
  // Each frame whole, so that none reads the history of another's light.
  const clouds::Settings whole = clouds::tools::singleFrame(furnaceSettings(1.0f, 128));
  for (const CloudView& lit : {view, given}) {
    CloudView whiteGround = lit;
    whiteGround.groundAlbedo = glm::vec3(1.0f);
    for (const glm::vec4& p : harness().render(whiteGround, whole, {48, 27}).radiance) {
      ASSERT_NEAR(p.r + p.a, 1.0f, 2e-3f) << (lit.skyView ? "sky image" : "inputs");
    }
    CloudView greyGround = lit;
    greyGround.groundAlbedo = glm::vec3(0.5f);
    float darkest = 1.0f;
    for (const glm::vec4& p : harness().render(greyGround, whole, {48, 27}).radiance) {
      darkest = std::min(darkest, p.r + p.a);
    }
    EXPECT_LT(darkest, 0.97f) << (lit.skyView ? "sky image" : "inputs");
  }
}

struct CanonicalView {
  const char* name;
  CloudView view;
  clouds::Settings settings;
};

std::vector<CanonicalView> canonicalViews() {
  std::vector<CanonicalView> views;
  CloudView noon;
  noon.sunElevationDegrees = 80.0;
  noon.pitchDegrees = 20.0;
  views.push_back({"below the layer at noon", noon, clouds::Settings{}});
  CloudView sunset;
  sunset.sunElevationDegrees = 3.0;
  sunset.sunAzimuthDegrees = 10.0;
  sunset.pitchDegrees = 8.0;
  sunset.sunIlluminance = {9.0f, 5.0f, 2.5f};
  views.push_back({"sunset towards the sun", sunset, clouds::Settings{}});
  CloudView above;
  above.position.y = 6000.0;
  above.pitchDegrees = -25.0;
  views.push_back({"above the layer", above, clouds::Settings{}});
  CloudView inside;
  inside.position.y = 2200.0;
  inside.pitchDegrees = 0.0;
  clouds::Settings overcast;
  overcast.coverage = 0.9f;
  views.push_back({"inside a cloud", inside, overcast});
  return views;
}

TEST_F(CloudMarch, MatchesTheCpuReferenceOnCanonicalViews) {
  const VkExtent2D extent{128, 72};
  for (const CanonicalView& c : canonicalViews()) {
    const clouds::Settings settings = clouds::tools::singleFrame(c.settings);
    const clouds::tools::CloudFrame gpu = harness().render(c.view, settings, extent);
    const clouds::tools::CpuTextures textures = clouds::tools::readTextures(harness());
    const clouds::tools::CloudFrame cpu = clouds::tools::renderCpuReference(
        textures, impl().lastUniforms(), settings, harness().lastDepth());
    float peak = 1.0f;
    for (const glm::vec4& p : cpu.radiance) peak = std::max({peak, p.r, p.g, p.b});
    const double psnr = clouds::tools::psnr(gpu.radiance, cpu.radiance, peak);
    EXPECT_GE(psnr, 40.0) << c.name;
    double opacity = 0.0;
    for (const glm::vec4& p : cpu.radiance) opacity += 1.0 - p.a;
    EXPECT_GT(opacity / double(cpu.radiance.size()), 0.02) << c.name << " shows no cloud";
  }
}

// Inside the layer a frame without history is rebuilt from a sparse pattern of rays by a tent
// (reconstruct.comp); when every pixel is marched (a tile of 1, as the Reference does) each
// pixel is its own ray, and the tent would only blur the clouds' edges: the output is the march.
TEST_F(CloudMarch, AFrameMarchedAtEveryPixelInsideTheLayerIsItsOwnRays) {
  const VkExtent2D extent{128, 72};
  CloudView inside;
  inside.position.y = 2300.0;
  inside.pitchDegrees = 5.0;
  clouds::Settings look;
  look.coverage = 0.55f;
  const clouds::Settings settings = clouds::tools::singleFrame(look);
  const clouds::tools::CloudFrame gpu = harness().render(inside, settings, extent);
  ASSERT_TRUE(harness().context().lastFrameReport().insideLayer);
  const clouds::tools::CloudFrame cpu = clouds::tools::renderCpuReference(
      clouds::tools::readTextures(harness()), impl().lastUniforms(), settings, {});
  float peak = 1.0f;
  for (const glm::vec4& p : cpu.radiance) peak = std::max({peak, p.r, p.g, p.b});
  EXPECT_GE(clouds::tools::psnr(gpu.radiance, cpu.radiance, peak), 40.0);
}

// The light integral is one integral (the extinction along the cone towards the sun), which more
// light steps estimate with less noise: inside a dense cloud, where a pixel shows what its near
// samples are lit by, the Reference averaged over 8 frames comes closer to itself with 64 light
// steps as its steps grow (measured: 39.2, 44.5 and 50.0 dB), and its own 24 are within 47 dB of
// it. (With a fixed hashed cone kernel per step count each count was its own cone: 6, 12 and 24
// steps were 35.2, 31.8 and 27.0 dB from 64.)
TEST_F(CloudMarch, TheReferencesLightIntegralConvergesAsItsStepsGrow) {
  const VkExtent2D extent{96, 54};
  CloudView inside;
  inside.position.y = 2300.0;
  inside.pitchDegrees = 0.0;
  inside.yawDegrees = 270.0;
  clouds::Settings look;
  look.coverage = 0.85f;
  const auto render = [&](std::uint32_t steps) {
    clouds::Settings s = clouds::referenceSettings(look);
    s.lightSteps = steps;
    return harness().renderAveraged(inside, s, extent, 8);
  };
  const clouds::tools::CloudFrame converged = render(64);
  double previous = 0.0;
  for (const std::uint32_t steps : {6u, 12u, 24u}) {
    const double psnr = clouds::tools::psnr(render(steps).radiance, converged.radiance, 1.0);
    std::printf("%u light steps: %.1f dB from 64\n", steps, psnr);
    EXPECT_GT(psnr, previous + 2.0) << steps << " light steps";
    previous = psnr;
  }
  EXPECT_GE(previous, 47.0) << "the Reference's 24 light steps";
}

// Counts non-finite, negative and out-of-range outputs of the last render with a shader.
struct InvalidCounts {
  std::uint32_t nonFinite, negative, transmittanceOutOfRange, pixels;
};

InvalidCounts countInvalid(engine::gfx::Device& device, VkImageView radiance, VkImageView depth,
                           VkExtent2D extent) {
  static engine::gfx::Pipeline* pipeline = [&] {
    engine::gfx::ComputePipelineDesc desc;
    desc.spirv = count_invalid_comp_spv;
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R16G16B16A16_SFLOAT},
                     {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R32G32_SFLOAT},
                     {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    desc.pushConstantBytes = 8;
    desc.debugName = "count invalid";
    return new engine::gfx::Pipeline(device, desc);
  }();
  engine::gfx::Buffer counters(
      device, engine::gfx::BufferDesc{
                  16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  engine::gfx::MemoryUsage::Readback, "invalid counters"});
  std::memset(counters.mapped(), 0, 16);
  engine::gfx::DescriptorArena arena(device, "count invalid descriptors");
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    engine::gfx::DescriptorWriter writer;
    writer.storageImage(0, radiance).storageImage(1, depth).storageBuffer(2, counters.vk());
    engine::gfx::bindPipeline(device, cmd, *pipeline, arena, writer);
    const std::uint32_t size[2] = {extent.width, extent.height};
    vkCmdPushConstants(cmd, pipeline->layout(), pipeline->pushConstantStages(), 0, 8, size);
    vkCmdDispatch(cmd, engine::gfx::groupCount(extent.width, 8),
                  engine::gfx::groupCount(extent.height, 8), 1);
    engine::gfx::bufferBarrier(cmd, counters.vk(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                               VK_ACCESS_2_HOST_READ_BIT);
  });
  InvalidCounts counts{};
  std::memcpy(&counts, counters.mapped(), sizeof(counts));
  return counts;
}

TEST_F(CloudMarch, HardCasesProduceNoNanInfOrNegativeValues) {
  const VkExtent2D extent{40, 24};
  int cases = 0;
  for (double altitude : {300.0, 2600.0, 9000.0}) {        // below, inside, above the layer
    for (double pitch : {-89.9, -3.0, 0.0, 0.05, 89.9}) {  // vertical and grazing rays
      for (double sun : {-20.0, -0.5, 0.0, 12.0, 90.0}) {  // sun below the horizon to zenith
        for (float density : {0.0f, 1.0f, 1e6f}) {
          for (float coverage : {0.0f, 1.0f}) {
            CloudView view;
            view.position.y = altitude;
            view.pitchDegrees = pitch;
            view.sunElevationDegrees = sun;
            view.timeSeconds = cases % 2 == 0 ? 0.0 : 3.0e7;  // a year of wind and weather
            clouds::Settings s;
            s.densityMultiplier = density;
            s.coverage = coverage;
            harness().render(view, s, extent);
            const clouds::Outputs out = harness().context().outputs();
            const InvalidCounts counts =
                countInvalid(device(), out.radiance.view, out.depth.view, extent);
            ASSERT_EQ(counts.pixels, extent.width * extent.height);
            ASSERT_EQ(counts.nonFinite, 0u) << "altitude " << altitude << " pitch " << pitch
                                            << " sun " << sun << " density " << density;
            ASSERT_EQ(counts.negative, 0u) << "altitude " << altitude << " pitch " << pitch;
            ASSERT_EQ(counts.transmittanceOutOfRange, 0u);
            ++cases;
          }
        }
      }
    }
  }
  EXPECT_EQ(cases, 3 * 5 * 5 * 3 * 2);
}

TEST_F(CloudMarch, TheCounterCatchesInvalidValues) {
  // Negative control for the reduction: images seeded with one NaN, one infinity, one negative
  // radiance and one transmittance above 1 must be counted as such.
  using engine::gfx::Image;
  using engine::gfx::ImageDesc;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  Image radiance(device(), ImageDesc{VK_IMAGE_TYPE_2D,
                                     VK_FORMAT_R16G16B16A16_SFLOAT,
                                     {4, 2, 1},
                                     1,
                                     1,
                                     usage,
                                     "seeded radiance"});
  Image depth(
      device(),
      ImageDesc{VK_IMAGE_TYPE_2D, VK_FORMAT_R32G32_SFLOAT, {4, 2, 1}, 1, 1, usage, "seeded depth"});
  const std::uint16_t one = 0x3C00, nan = 0x7E00, inf = 0x7C00, minusOne = 0xBC00, two = 0x4000;
  std::vector<std::uint16_t> texels(8 * 4, one);
  texels[1 * 4 + 0] = nan;
  texels[2 * 4 + 1] = inf;
  texels[3 * 4 + 2] = minusOne;
  texels[4 * 4 + 3] = two;
  std::vector<float> depths(8 * 2, 10.0f);
  const engine::gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL,
                                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
  engine::gfx::uploadToImage(device(), radiance, std::as_bytes(std::span(texels)), general);
  engine::gfx::uploadToImage(device(), depth, std::as_bytes(std::span(depths)), general);
  const InvalidCounts counts = countInvalid(device(), radiance.view(), depth.view(), {4, 2});
  EXPECT_EQ(counts.pixels, 8u);
  EXPECT_EQ(counts.nonFinite, 2u);
  EXPECT_EQ(counts.negative, 1u);
  EXPECT_EQ(counts.transmittanceOutOfRange, 1u);
}

TEST_F(CloudMarch, GroundHidesCloudsBehindItAndCloudsInFrontCoverIt) {
  const VkExtent2D extent{64, 36};
  clouds::Settings s;
  s.coverage = 0.8f;
  // From below, looking level: pixels that see the ground are untouched by clouds.
  CloudView below;
  below.pitchDegrees = 0.0;
  below.groundDepth = true;
  const clouds::tools::CloudFrame low = harness().render(below, s, extent);
  const std::vector<float> depth = harness().lastDepth();
  int ground = 0;
  int cloudyAbove = 0;
  for (std::size_t i = 0; i < low.radiance.size(); ++i) {
    if (depth[i] > 0.0f) {
      ++ground;
      ASSERT_EQ(low.radiance[i].a, 1.0f) << "cloud drawn over ground in front of it";
      ASSERT_EQ(low.radiance[i].r, 0.0f);
    } else if (low.radiance[i].a < 0.9f) {
      ++cloudyAbove;
    }
  }
  EXPECT_GT(ground, 100);
  EXPECT_GT(cloudyAbove, 100);
  // From above, looking down: clouds between the camera and the ground cover it.
  CloudView above;
  above.position.y = 6000.0;
  above.pitchDegrees = -60.0;
  above.groundDepth = true;
  const clouds::tools::CloudFrame high = harness().render(above, s, extent);
  int covered = 0;
  for (const glm::vec4& p : high.radiance) covered += p.a < 0.5f ? 1 : 0;
  EXPECT_GT(covered, int(high.radiance.size() / 4));
}

TEST_F(CloudMarch, SkySeenThroughOnePixelGapsInNearGeometryShowsItsClouds) {
  // A wall 100 m away with single sky pixels in it, 5 pixels apart: every position inside a
  // trace pixel's footprint of 1, 2 x 2 or 4 x 4 pixels, and in the uneven footprints of the
  // 45 rows halved and quartered (23 and 12 trace rows, rounded up). Each trace pixel
  // must take the farthest geometry of its footprint, so that the clouds behind a gap are
  // marched. A gap a trace pixel missed shows no cloud at all.
  const VkExtent2D extent{80, 45};
  CloudView wall;
  wall.pitchDegrees = 25.0;
  const float wallDepth = 0.5f / 100.0f;  // reversed-Z, near plane 0.5 m
  wall.hostDepth.assign(std::size_t(extent.width) * extent.height, wallDepth);
  std::vector<std::size_t> gaps;
  for (std::uint32_t y = 1; y < extent.height; y += 5) {
    for (std::uint32_t x = 2; x < extent.width; x += 5) {
      gaps.push_back(std::size_t(y) * extent.width + x);
      wall.hostDepth[gaps.back()] = 0.0f;
    }
  }
  CloudView open = wall;
  open.hostDepth.clear();
  for (float traceScale : {1.0f, 0.5f, 0.25f}) {
    clouds::Settings s = clouds::tools::singleFrame({});
    s.coverage = 0.8f;
    s.traceScale = traceScale;
    const clouds::tools::CloudFrame sky = harness().render(open, s, extent);
    const clouds::tools::CloudFrame seen = harness().render(wall, s, extent);
    int cloudyGaps = 0;
    for (std::size_t i : gaps) {
      const float opacity = 1.0f - sky.radiance[i].a;
      if (opacity < 0.2f) continue;
      ++cloudyGaps;
      // The gap's own trace pixel weighs at least 0.625^2 in its bilinear estimate; the
      // others may be wall.
      EXPECT_GE(1.0f - seen.radiance[i].a, 0.3f * opacity)
          << "gap " << i % extent.width << ", " << i / extent.width << " at trace scale "
          << traceScale;
    }
    EXPECT_GT(cloudyGaps, int(gaps.size() / 2)) << "the sky behind the wall must be cloudy";
  }
}

TEST_F(CloudMarch, FramesFarFromTheOriginMatchTheOrigin) {
  // The default tiles (weather 50 km, shape 6.25 km, detail 1.25 km, curl 12.5 km) all divide
  // 100 km and 10,000 km, so the same clouds must appear; float world coordinates would not
  // even place the samples correctly out there.
  const VkExtent2D extent{96, 54};
  clouds::Settings s = clouds::tools::singleFrame({});
  s.coverage = 0.65f;
  s.jitter = clouds::Jitter::None;  // the frame index changes between renders
  CloudView origin;
  origin.pitchDegrees = 15.0;
  origin.timeSeconds = 12.0;
  const clouds::tools::CloudFrame atOrigin = harness().render(origin, s, extent);
  double opacity = 0.0;
  for (const glm::vec4& p : atOrigin.radiance) opacity += 1.0 - p.a;
  ASSERT_GT(opacity / double(atOrigin.radiance.size()), 0.1) << "the view must show clouds";
  for (double distance : {1e5, 1e7}) {
    CloudView far = origin;
    far.position.x += distance;
    far.position.z -= distance;
    const clouds::tools::CloudFrame atFar = harness().render(far, s, extent);
    EXPECT_GE(clouds::tools::psnr(atOrigin.radiance, atFar.radiance, 1.0), 60.0)
        << distance << " m";
  }
  CloudView shifted = origin;
  shifted.position.x += 3000.0;  // and a real move does change the picture
  EXPECT_LT(
      clouds::tools::psnr(atOrigin.radiance, harness().render(shifted, s, extent).radiance, 1.0),
      40.0);
}

TEST_F(CloudMarch, FramesAfterAMillionSecondsMatchTheSameMomentOfTheWindsCycle) {
  // After 1.28e6 s a 125 m/s wind has scrolled the noise 1.6e8 m, a whole number of shape,
  // detail and curl tiles, and a weather evolving 1/1024 of a cycle a second (exact in float)
  // has gone through a whole 1250 cycles: the same clouds must appear. With the scroll rounded
  // to float (16 m steps out there) this measured 52 dB.
  const VkExtent2D extent{96, 54};
  clouds::Settings s = clouds::tools::singleFrame({});
  s.coverage = 0.65f;
  s.jitter = clouds::Jitter::None;
  s.weatherEvolutionPerSecond = 1.0f / 1024.0f;
  s.windSpeedMetresPerSecond = 125.0f;
  CloudView early;
  early.pitchDegrees = 15.0;
  early.timeSeconds = 12.3;
  const clouds::tools::CloudFrame atEarly = harness().render(early, s, extent);
  CloudView late = early;
  late.timeSeconds += 1.28e6;
  const clouds::tools::CloudFrame atLate = harness().render(late, s, extent);
  for (const glm::vec4& p : atLate.radiance) {
    ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.a) && p.a >= 0.0f && p.a <= 1.0f);
  }
  EXPECT_GE(clouds::tools::psnr(atEarly.radiance, atLate.radiance, 1.0), 60.0);
  CloudView later = late;
  later.timeSeconds += 100.0;  // and 1 km more of wind does change the picture
  EXPECT_LT(clouds::tools::psnr(atEarly.radiance, harness().render(later, s, extent).radiance, 1.0),
            40.0);
}

TEST_F(CloudMarch, PaintedWeatherMapControlsCoverage) {
  const VkExtent2D extent{48, 27};
  auto paint = [&](std::uint8_t coverage) {
    engine::gfx::Image image(device(), engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                                              VK_FORMAT_R8G8B8A8_UNORM,
                                                              {8, 8, 1},
                                                              1,
                                                              1,
                                                              VK_IMAGE_USAGE_SAMPLED_BIT |
                                                                  VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                              "painted weather"});
    std::vector<std::uint8_t> texels(8 * 8 * 4);
    for (std::size_t i = 0; i < 64; ++i) {
      texels[4 * i + 0] = coverage;
      texels[4 * i + 1] = 255;  // cumulus
      texels[4 * i + 2] = 255;  // full density
      texels[4 * i + 3] = 255;
    }
    engine::gfx::uploadToImage(device(), image, std::as_bytes(std::span(texels)),
                               engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    return image;
  };
  const engine::gfx::Image clear = paint(0);
  const engine::gfx::Image full = paint(255);
  CloudView view;
  view.weatherView = clear.view();
  const clouds::tools::CloudFrame none = harness().render(view, clouds::Settings{}, extent);
  for (const glm::vec4& p : none.radiance) ASSERT_EQ(p.a, 1.0f) << "a painted hole has clouds";
  view.weatherView = full.view();
  const clouds::tools::CloudFrame cloudy = harness().render(view, clouds::Settings{}, extent);
  double opacity = 0.0;
  for (const glm::vec4& p : cloudy.radiance) opacity += 1.0 - p.a;
  EXPECT_GT(opacity / double(cloudy.radiance.size()), 0.3);
}

TEST_F(CloudMarch, BadInputsAreRejectedWithTheFieldName) {
  CloudView view;
  clouds::Settings bad;
  bad.coverage = 2.0f;
  EXPECT_NE(harness().tryRender(view, bad, {16, 16}).find("Settings.coverage"), std::string::npos);
  EXPECT_NE(harness().tryRender(view, clouds::Settings{}, {4096, 16}).find("renderExtent"),
            std::string::npos);
  CloudView nan = view;
  nan.position.x = std::nan("");
  EXPECT_NE(harness().tryRender(nan, clouds::Settings{}, {16, 16}).find("cameraPosition"),
            std::string::npos);
  CloudView negative = view;
  negative.sunIlluminance = glm::vec3(-1.0f);
  EXPECT_NE(harness().tryRender(negative, clouds::Settings{}, {16, 16}).find("negative"),
            std::string::npos);
}

}  // namespace
