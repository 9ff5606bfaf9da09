// The clouds' lightning glow on lavapipe (FrameInputs::lightningFlashes): a flash inside an
// overcast makes the cloud near it glow and leaves the cloud beyond its reach exactly as it
// was; the frame after a flash equals, to the bit, the frame of a renderer that never saw it
// (the glow never enters the temporal history); hard cases stay finite; without room for
// flashes in the settings a flash is refused by name. Validation-clean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;

constexpr VkExtent2D kExtent{96, 64};
using Lightning = test::SharedHarnessTest<96, 64>;

// Under an overcast, looking up into it at dusk (the sun low: the glow stands out).
CloudView underTheOvercast() {
  CloudView view;
  view.position = {0.0, 300.0, 0.0};
  view.pitchDegrees = 35.0;
  view.yawDegrees = 0.0;
  view.sunElevationDegrees = 3.0;
  view.timeSeconds = 5.0;
  return view;
}

clouds::Settings overcast() {
  clouds::Settings s;
  s.coverage = 0.9f;
  s.cloudType = 0.5f;
  s.lightningFlashes = 4;
  return s;
}

// A flash just inside the cloud base, where the camera looks (yaw 0 looks along -z, 35
// degrees up: the base at 1.5 km is 2.7 km ahead).
clouds::LightningFlash flashAhead() {
  clouds::LightningFlash flash;
  flash.positionMetres = {0.0, 1800.0, -2200.0};
  flash.radiusMetres = 4000.0f;
  flash.radiance = glm::vec3(400.0f, 400.0f, 500.0f);
  return flash;
}

double luminance(const glm::vec4& p) {
  return (double(p.r) + double(p.g) + double(p.b)) / 3.0;
}

TEST_F(Lightning, AFlashMakesTheCloudNearItGlow) {
  const clouds::Settings s = clouds::tools::singleFrame(overcast());
  CloudView dark = underTheOvercast();
  harness().cut();
  const CloudFrame before = harness().render(dark, s, kExtent);
  CloudView lit = dark;
  lit.lightningFlashes = {flashAhead()};
  harness().cut();
  const CloudFrame after = harness().render(lit, s, kExtent);
  ASSERT_TRUE(test::allValid(after));
  ASSERT_GT(test::meanOpacity(before), 0.5) << "the view must be overcast";
  const clouds::tools::PixelRays rays(dark, kExtent);
  const glm::dvec3 flash = flashAhead().positionMetres - dark.position;
  std::size_t brighter = 0;
  std::size_t beyond = 0;
  std::size_t beyondChanged = 0;
  std::size_t darker = 0;
  double gain = 0.0;
  for (std::uint32_t y = 0; y < kExtent.height; ++y) {
    for (std::uint32_t x = 0; x < kExtent.width; ++x) {
      const std::size_t i = std::size_t{y} * kExtent.width + x;
      const double a = luminance(before.radiance[i]);
      const double b = luminance(after.radiance[i]);
      ASSERT_EQ(before.radiance[i].a, after.radiance[i].a) << "the glow is light, not cloud";
      darker += b < a ? 1 : 0;
      brighter += b > 1.2 * a + 1e-6 ? 1 : 0;
      gain += b - a;
      // Where the pixel's cloud (at its weighted depth) lies beyond the flash's reach.
      const double depth = before.depth[i].y;
      const glm::dvec3 cloud = glm::dvec3(rays.direction(x, y)) * depth;
      if (depth > 0.0 && glm::length(cloud - flash) > 4000.0 * 1.05) {
        ++beyond;
        beyondChanged += b != a ? 1 : 0;
      }
    }
  }
  const std::size_t pixels = std::size_t{kExtent.width} * kExtent.height;
  std::printf(
      "flash: %zu of %zu pixels 20%% brighter, mean gain %.3f; %zu beyond its reach, "
      "%zu of them changed\n",
      brighter, pixels, gain / double(pixels), beyond, beyondChanged);
  EXPECT_GT(brighter, pixels / 10);
  EXPECT_EQ(darker, 0u);
  EXPECT_GT(beyond, 0u);
  EXPECT_EQ(beyondChanged, 0u) << "no glow beyond the flash's reach";
}

// With temporal reuse (1 pixel in 16 marched a frame), a flash on one frame must leave nothing
// behind: the next frame equals that of a renderer that never saw the flash.
TEST_F(Lightning, TheFrameAfterAFlashIsAsIfItNeverWas) {
  clouds::Settings s = clouds::settingsFor(clouds::Quality::Medium, overcast());
  clouds::tools::CloudHarness flashed(device(), kExtent);
  clouds::tools::CloudHarness never(device(), kExtent);
  CloudView view = underTheOvercast();
  CloudFrame a;
  CloudFrame b;
  for (int frame = 0; frame < 12; ++frame) {
    CloudView withFlash = view;
    if (frame >= 6 && frame < 9) withFlash.lightningFlashes = {flashAhead()};
    a = flashed.render(withFlash, s, kExtent);
    b = never.render(view, s, kExtent);
    if (frame == 7) {
      EXPECT_NE(a.radiance, b.radiance) << "the flash shows while it lasts";
    }
    if (frame == 9) {
      EXPECT_EQ(a.radiance, b.radiance) << "no glow left in the history";
      EXPECT_EQ(a.depth, b.depth);
    }
    view.timeSeconds += 1.0 / 30.0;
  }
}

TEST_F(Lightning, HardCasesStayFinite) {
  const clouds::Settings s = clouds::tools::singleFrame(overcast());
  const CloudView base = underTheOvercast();
  struct Case {
    const char* name;
    glm::dvec3 position;
    float radius;
    float radiance;
  };
  const Case cases[] = {{"at the camera", base.position, 3000.0f, 40.0f},
                        {"energy 0", {0.0, 1800.0, -2200.0}, 3000.0f, 0.0f},
                        {"energy 1e9", {0.0, 1800.0, -2200.0}, 3000.0f, 1e9f},
                        {"100 km away", {0.0, 1800.0, -100000.0}, 3000.0f, 40.0f},
                        {"a 1 mm flash", {0.0, 1800.0, -2200.0}, 1e-3f, 40.0f},
                        {"a 1000 km flash", {0.0, 1800.0, -2200.0}, 1e6f, 40.0f}};
  for (const Case& c : cases) {
    CloudView view = base;
    clouds::LightningFlash flash;
    flash.positionMetres = c.position;
    flash.radiusMetres = c.radius;
    flash.radiance = glm::vec3(c.radiance);
    view.lightningFlashes = {flash, flash, flash, flash};  // four at once, all the room
    harness().cut();
    const CloudFrame frame = harness().render(view, s, kExtent);
    EXPECT_TRUE(test::allValid(frame)) << c.name;
  }
}

TEST_F(Lightning, FlashesNeedRoomInTheSettings) {
  clouds::Settings s = clouds::tools::singleFrame(overcast());
  CloudView view = underTheOvercast();
  view.lightningFlashes = {flashAhead(), flashAhead()};
  s.lightningFlashes = 1;
  const std::string error = harness().tryRender(view, s, kExtent);
  EXPECT_NE(error.find("FrameInputs.lightningFlashes: 2 flashes"), std::string::npos) << error;
  s.lightningFlashes = 2;
  view.lightningFlashes[1].radiusMetres = -1.0f;
  const std::string bad = harness().tryRender(view, s, kExtent);
  EXPECT_NE(bad.find("FrameInputs.lightningFlashes[1].radiusMetres"), std::string::npos) << bad;
}

// A layer without room for flashes has no flashes' buffer; with room, one per frame in flight.
TEST_F(Lightning, NoLightningNoBuffer) {
  clouds::tools::CloudHarness none(device(), kExtent);
  clouds::Settings s = clouds::tools::singleFrame(overcast());
  s.lightningFlashes = 0;
  none.render(underTheOvercast(), s, kExtent);
  const std::uint64_t without = none.memoryUsage().bufferBytes;
  s.lightningFlashes = 4;
  none.render(underTheOvercast(), s, kExtent);
  EXPECT_GT(none.memoryUsage().bufferBytes, without) << "the flashes' blocks";
}

}  // namespace
