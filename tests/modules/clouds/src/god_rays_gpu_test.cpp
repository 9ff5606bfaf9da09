// The god-ray mask on lavapipe (fxcontracts/god_rays.h): its occlusion image against the frame it
// was made from (the clouds' transmittance where the host's depth is sky), its radial blur
// against the shared blur on the CPU, a clear sky that hides nothing, the ground's shadow
// below the horizon, a fade to a clear mask when the sun leaves the screen, a mask that does not
// flicker as the camera turns, and no pass or memory without god rays. Validation-clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "fxcontracts/god_rays.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudView;
using clouds::tools::GodRayImages;

constexpr VkExtent2D kExtent{160, 96};  // a 40 x 24 mask
using GodRays = test::SharedHarnessTest<160, 96>;

// The images the CPU blur reads (one test at a time).
const GodRayImages* gImages = nullptr;

}  // namespace

float fxcontracts::shader::fetchGodRayOcclusion(glm::vec2 uv) {
  return gImages->occlusionAt(uv);
}

namespace {

// Broken cumulus towards a sun 12 degrees up, over flat ground (the host's depth).
CloudView towardsTheSun() {
  CloudView view;
  view.position = {0.0, 300.0, 0.0};
  view.sunElevationDegrees = 12.0;
  view.sunAzimuthDegrees = 200.0;
  view.yawDegrees = 200.0;
  view.pitchDegrees = 8.0;
  view.groundDepth = true;
  view.timeSeconds = 5.0;
  return view;
}

clouds::Settings withGodRays(float density = 1.0f) {
  clouds::Settings s = clouds::tools::singleFrame(clouds::Settings{});
  s.coverage = 0.55f;
  s.cloudType = 0.9f;
  s.densityMultiplier = density;
  s.godRaySamples = 24;
  return s;
}

// Clouds so thin they hide nothing, but marched (a sky that cannot hold cloud is not, and has
// no god rays: nothing on screen is known to hide the sun).
constexpr float kInvisible = 1e-9f;

// The GPU's occlusion against `frame`'s own: each texel the mean of the frame's transmittance over
// its 4 x 4 pixels where they show the sky.
struct OcclusionAgreement {
  double mean = 0.0;       // the mean difference
  double worst = 0.0;      // the largest
  std::size_t exact = 0;   // texels within 1e-3
  std::size_t texels = 0;  // of these
  double hidden = 0.0;     // the mean of 1 - occlusion: how much the texels hide of the sun
};
OcclusionAgreement occlusionAgainstTheFrame(const CloudView& view,
                                            const clouds::tools::CloudFrame& frame,
                                            const GodRayImages& images) {
  const clouds::tools::PixelRays rays(view, kExtent);
  OcclusionAgreement a;
  for (std::uint32_t ty = 0; ty < images.height; ++ty) {
    for (std::uint32_t tx = 0; tx < images.width; ++tx) {
      double clear = 0.0;
      for (std::uint32_t y = 4 * ty; y < 4 * ty + 4; ++y) {
        for (std::uint32_t x = 4 * tx; x < 4 * tx + 4; ++x) {
          const bool sky = rays.direction(x, y).y >= 0.0f;  // the ground is at y = 0, below
          clear += sky ? frame.radiance[std::size_t{y} * kExtent.width + x].a : 0.0;
        }
      }
      const double gpu = images.occlusion[std::size_t{ty} * images.width + tx];
      const double d = std::abs(gpu - clear / 16.0);
      a.mean += d;
      a.worst = std::max(a.worst, d);
      a.exact += d < 1e-3 ? 1 : 0;
      a.hidden += 1.0 - gpu;
    }
  }
  a.texels = std::size_t{images.width} * images.height;
  a.mean /= double(a.texels);
  a.hidden /= double(a.texels);
  return a;
}

TEST_F(GodRays, TheOcclusionIsTheCloudsTransmittanceOverTheSky) {
  const CloudView view = towardsTheSun();
  harness().cut();
  const clouds::tools::CloudFrame frame = harness().render(view, withGodRays(), kExtent);
  const GodRayImages images = harness().readGodRays();
  ASSERT_EQ(images.width, 40u);
  ASSERT_EQ(images.height, 24u);
  const OcclusionAgreement a = occlusionAgainstTheFrame(view, frame, images);
  std::printf("occlusion: %zu of %zu texels exact, worst %.4f (a pixel on the horizon is 1/16)\n",
              a.exact, a.texels, a.worst);
  EXPECT_LE(a.worst, 1.0 / 16.0 + 1e-3) << "at most one pixel of a texel on the horizon";
  EXPECT_GE(a.exact, a.texels * 9 / 10);
  EXPECT_GT(a.hidden, 0.2) << "the view must hide the sun in places";
}

// With the near/far split (Settings::nearFieldMetres) the trace image holds each ray's far
// part: in the layer, where the near 200 m hide much of the sun, the occlusion lays the near
// field over it as the frame does, and is the frame's transmittance over the sky still.
// (Without the near field it is 0.015 apart on average, 0.047 at worst.)
TEST_F(GodRays, InTheLayerTheNearFieldHidesTheSunToo) {
  CloudView view = towardsTheSun();
  view.position.y = 2500.0;  // 1 km into a thin overcast
  clouds::Settings split = withGodRays(0.02f);
  split.coverage = 1.0f;
  split.nearFieldMetres = 200.0f;
  harness().cut();
  const clouds::tools::CloudFrame frame = harness().render(view, split, kExtent);
  ASSERT_TRUE(harness().context().lastFrameReport().nearField);
  const OcclusionAgreement a = occlusionAgainstTheFrame(view, frame, harness().readGodRays());
  std::printf("occlusion against the split frame: %.4f on average, worst %.4f; %.2f hidden\n",
              a.mean, a.worst, a.hidden);
  EXPECT_LT(a.mean, 0.003);
  EXPECT_GT(a.hidden, 0.5) << "the view must hide the sun";
}

TEST_F(GodRays, TheMaskIsTheSharedBlurOfTheOcclusion) {
  harness().cut();
  harness().render(towardsTheSun(), withGodRays(), kExtent);
  const GodRayImages images = harness().readGodRays();
  ASSERT_GT(images.sun.z, 0.99f) << "the sun is on screen";
  EXPECT_EQ(images.sun.w, 24.0f);
  gImages = &images;
  fxcontracts::shader::GodRayParameters p{};
  p.sun = images.sun;
  p.blur = images.blur;
  double worst = 0.0;
  double sum = 0.0;
  float lowest = 1.0f;
  for (std::uint32_t y = 0; y < images.height; ++y) {
    for (std::uint32_t x = 0; x < images.width; ++x) {
      const glm::vec2 uv((float(x) + 0.5f) / float(images.width),
                         (float(y) + 0.5f) / float(images.height));
      const float gpu = images.mask[std::size_t{y} * images.width + x];
      const double d = std::abs(double(gpu) - double(fxcontracts::shader::godRayMaskAt(uv, p)));
      worst = std::max(worst, d);
      sum += d;
      lowest = std::min(lowest, gpu);
      ASSERT_TRUE(std::isfinite(gpu) && gpu >= 0.0f && gpu <= 1.0f) << x << ", " << y;
    }
  }
  gImages = nullptr;
  const double mean = sum / double(images.mask.size());
  // The GPU's linear filter weighs texels with a few bits of sub-texel precision.
  std::printf("mask against the CPU blur: mean |d| %.2e, worst %.2e; lowest texel %.3f\n", mean,
              worst, double(lowest));
  EXPECT_LT(mean, 2e-3);
  EXPECT_LT(worst, 2e-2);
  EXPECT_LT(lowest, 0.5f) << "shafts of shadow";
}

TEST_F(GodRays, AClearSkyHidesNothing) {
  CloudView view = towardsTheSun();
  view.groundDepth = false;
  for (float density : {0.0f, kInvisible}) {
    harness().cut();
    harness().render(view, withGodRays(density), kExtent);
    const GodRayImages images = harness().readGodRays();
    ASSERT_FALSE(images.mask.empty());
    EXPECT_EQ(images.sun.z, density > 0.0f ? 1.0f : 0.0f) << "nothing marched: no mask";
    for (float m : images.mask) ASSERT_NEAR(m, 1.0f, 1e-5f) << "density " << density;
  }
}

// A sky clear of cloud over flat ground: what lies above the horizon sees the sun (its way climbs
// towards it); below, the more of the way is ground, the less.
TEST_F(GodRays, TheGroundShadowsTheAirBelowTheHorizon) {
  harness().cut();
  harness().render(towardsTheSun(), withGodRays(kInvisible), kExtent);
  const GodRayImages images = harness().readGodRays();
  const std::uint32_t x = images.width / 2;
  const auto at = [&](std::uint32_t y) { return images.mask[std::size_t{y} * images.width + x]; };
  EXPECT_NEAR(at(0), 1.0f, 1e-5f) << "the top of the screen, above the sun";
  EXPECT_LT(at(images.height - 1), 0.6f) << "the bottom, far below the horizon";
  for (std::uint32_t y = 1; y < images.height; ++y) {
    EXPECT_LE(at(y), at(y - 1) + 1e-6f) << "row " << y;
  }
}

TEST_F(GodRays, TheMaskIsClearWhenTheSunIsOffScreenOrBehind) {
  for (double yaw : {200.0 + 110.0, 20.0}) {
    CloudView view = towardsTheSun();
    view.yawDegrees = yaw;
    harness().cut();
    harness().render(view, withGodRays(), kExtent);
    const GodRayImages images = harness().readGodRays();
    EXPECT_EQ(images.sun.z, 0.0f) << "yaw " << yaw;
    for (float m : images.mask) ASSERT_EQ(m, 1.0f) << "yaw " << yaw;
  }
}

// The sun crossing the screen's edge, a quarter of a degree at a time (the horizontal half
// field of view at 160 x 96 is 49.4 degrees): the mask and its fade stay finite and in range.
TEST_F(GodRays, TheSunAtTheScreensEdgeStaysFinite) {
  for (double off = 48.0; off <= 51.0; off += 0.25) {
    CloudView view = towardsTheSun();
    view.yawDegrees = 200.0 + off;
    harness().cut();
    harness().render(view, withGodRays(), kExtent);
    const GodRayImages images = harness().readGodRays();
    ASSERT_TRUE(std::isfinite(images.sun.x) && std::isfinite(images.sun.y)) << off;
    EXPECT_GE(images.sun.z, 0.0f);
    EXPECT_LE(images.sun.z, 1.0f);
    for (float m : images.mask) {
      ASSERT_TRUE(std::isfinite(m) && m >= 0.0f && m <= 1.0f) << "yaw +" << off << ": " << m;
    }
  }
}

// Turning the camera by a twentieth of a degree (a twentieth of a pixel at 160 wide) moves
// the mask with it, without flicker: the frame-to-frame change is small everywhere.
TEST_F(GodRays, TheMaskDoesNotFlickerAsTheCameraTurns) {
  CloudView view = towardsTheSun();
  harness().cut();
  harness().render(view, withGodRays(), kExtent);
  GodRayImages previous = harness().readGodRays();
  double worstMean = 0.0;
  for (int frame = 0; frame < 6; ++frame) {
    view.yawDegrees += 0.05;
    harness().render(view, withGodRays(), kExtent);
    const GodRayImages images = harness().readGodRays();
    double sum = 0.0;
    for (std::size_t i = 0; i < images.mask.size(); ++i) {
      sum += std::abs(double(images.mask[i]) - double(previous.mask[i]));
    }
    worstMean = std::max(worstMean, sum / double(images.mask.size()));
    previous = images;
  }
  std::printf("camera turning 0.05 degrees a frame: mask |d| mean, worst frame %.2e\n", worstMean);
  EXPECT_LT(worstMean, 5e-3);
}

TEST_F(GodRays, NoGodRaysNoPassNoMemory) {
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  clouds::tools::CloudHarness h(device(), kExtent, options);
  clouds::Settings s = withGodRays();
  s.godRaySamples = 0;
  h.render(towardsTheSun(), s, kExtent, 2);
  EXPECT_EQ(h.context().outputs().godRayMask.image, VK_NULL_HANDLE);
  EXPECT_EQ(h.memoryUsage().godRayBytes, 0u);
  for (const clouds::PassTiming& t : h.lastPassTimings()) EXPECT_STRNE(t.name, "god rays");
  s.godRaySamples = 16;
  h.render(towardsTheSun(), s, kExtent, 2);
  EXPECT_NE(h.context().outputs().godRayMask.image, VK_NULL_HANDLE);
  // Two R32F images and an RGBA16F one of 40 x 24.
  EXPECT_GE(h.memoryUsage().godRayBytes, 40u * 24u * (4u + 4u + 8u));
  EXPECT_LT(h.memoryUsage().godRayBytes, 64u * 1024u);
  bool timed = false;
  for (const clouds::PassTiming& t : h.lastPassTimings()) {
    timed = timed || std::string(t.name) == "god rays";
  }
  EXPECT_TRUE(timed);
}

}  // namespace
