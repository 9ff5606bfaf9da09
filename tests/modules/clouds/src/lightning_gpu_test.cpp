// The clouds' lightning on lavapipe (FrameInputs::lightningFlashes, lightningBolts): a flash
// inside an overcast makes the cloud near it glow and lights the cloud beyond its reach with
// its sky light alone; each pixel's glow is the seeds' formula, its height gradient included
// (bases glow little, tops much); a bolt is a line of its energy, hidden by nearer geometry and
// dimmed behind cloud; the frame after a flash equals, to the bit, the frame of a renderer that
// never saw it (neither glow nor bolt enters the temporal history); hard cases stay finite; without
// room for flashes or bolts in the settings they are refused by name. Validation-clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "fxcontracts/lightning_light.h"
#include "gpu_test.h"
#include "lightning_bolts.h"

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
  std::size_t beyondLit = 0;
  double worstSkyLightError = 0.0;
  // Near the flash (within a quarter of its reach), the light gained against the sky light's
  // share of it: the rest is the glow.
  std::size_t near = 0;
  double nearGain = 0.0;
  double nearSkyLight = 0.0;
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
      const double sky =
          fxcontracts::shader::flashSkyLight(float(glm::length(cloud - flash)), 4000.0f);
      const double skyLight = (1.0 - double(before.radiance[i].a)) * sky * 1300.0 / 3.0;
      if (depth > 0.0 && glm::length(cloud - flash) < 1000.0) {
        ++near;
        nearGain += b - a;
        nearSkyLight += skyLight;
      }
      if (depth > 0.0 && glm::length(cloud - flash) > 4000.0 * 1.05) {
        // Beyond the glow's reach the cloud has the flash's sky light alone, as much of it as
        // there is cloud.
        ++beyond;
        beyondLit += b > a ? 1 : 0;
        const double expected = skyLight;
        // The output is half floats: each of a and b is off by up to 2^-11 of itself.
        const double rounding = std::ldexp(std::max(a, b), -11) * 2.0;
        worstSkyLightError =
            std::max(worstSkyLightError, (std::abs(b - a - expected) - rounding) / expected);
      }
    }
  }
  const std::size_t pixels = std::size_t{kExtent.width} * kExtent.height;
  std::printf(
      "flash: %zu of %zu pixels 20%% brighter, mean gain %.3f; %zu beyond its reach, "
      "%zu of them lit, worst error of their sky light %.4f\n",
      brighter, pixels, gain / double(pixels), beyond, beyondLit, worstSkyLightError);
  EXPECT_GT(brighter, pixels / 10);
  EXPECT_EQ(darker, 0u);
  EXPECT_GT(beyond, 0u);
  EXPECT_EQ(beyondLit, beyond) << "the flash's sky light reaches the whole deck";
  std::printf("flash: %zu pixels' clouds within 1 km of it gain %.2f times its sky light\n", near,
              nearGain / nearSkyLight);
  EXPECT_GT(near, 20u);
  // The bases seen here lie low in the layer (height fraction 0.13: the glow's height gradient
  // leaves them an eighth of it), yet near the flash they still gain more than its sky light.
  // The next test checks the glow per pixel.
  EXPECT_GT(nearGain, 1.3 * nearSkyLight) << "the glow: near the flash, more than sky light";
  EXPECT_LT(worstSkyLightError, 0.01) << "beyond its reach, the sky light alone";
}

// Each pixel's light from a flash, against the seeds' formula evaluated on the CPU in double
// precision from the frame without it (its transmittance and depths): per unit of cloud, L x
// (pow(1 - d / r, 12) x height gradient x pseudo-attenuation + sky light), at the pixel's cloud
// (its weighted depth). Near the flash (within 1.2 km, over half cloud): the worst relative error,
// and the mean height fraction of those clouds in the layer.
struct GlowAgainstFormula {
  std::size_t pixels = 0;
  double worstError = 0.0;
  double meanHeightFraction = 0.0;
};

GlowAgainstFormula glowAgainstFormula(clouds::tools::CloudHarness& h,
                                      const clouds::shader::CloudUniforms& u, const CloudView& view,
                                      const clouds::LightningFlash& flash,
                                      const clouds::Settings& s) {
  h.cut();
  const CloudFrame before = h.render(view, s, kExtent);
  CloudView lit = view;
  lit.lightningFlashes = {flash};
  h.cut();
  const CloudFrame after = h.render(lit, s, kExtent);
  const clouds::tools::PixelRays rays(view, kExtent);
  const glm::dvec3 charge = flash.positionMetres - view.position;
  const double radiance = (flash.radiance.r + flash.radiance.g + flash.radiance.b) / 3.0;
  const double planet = u.planetRadiusMetres;
  GlowAgainstFormula result;
  for (std::uint32_t y = 0; y < kExtent.height; ++y) {
    for (std::uint32_t x = 0; x < kExtent.width; ++x) {
      const std::size_t i = std::size_t{y} * kExtent.width + x;
      const glm::vec2 depth(before.depth[i]);
      const double transmittance = before.radiance[i].a;
      const glm::dvec3 ray(rays.direction(x, y));
      const double d = glm::length(ray * double(depth.y) - charge);
      if (depth.y <= 0.0f || transmittance > 0.5 || d > 1200.0) continue;
      // The seeds' pseudo-attenuation, of the density the pixel's cloud shows (its optical
      // depth, at most 1, over twice its weighted depth past the front).
      const double opticalDepth = std::min(-std::log(std::max(transmittance, 1e-6)), 1.0);
      const double span = std::max(2.0 * (double(depth.y) - double(depth.x)), 1.0);
      const double attenuation =
          1.0 - std::clamp(5.0 * opticalDepth / span / double(u.extinctionPerMetre), 0.0, 1.0);
      // The height gradient: the cloud's height fraction in the layer, over a round planet.
      const double r0 = planet + view.position.y;
      const double t = depth.y;
      const double altitude = std::sqrt(r0 * r0 + t * t + 2.0 * r0 * t * ray.y) - planet;
      const double height = std::clamp(
          (altitude - u.layerBottomMetres) / double(u.layerTopMetres - u.layerBottomMetres), 0.0,
          1.0);
      const float distance = static_cast<float>(d);
      const double expected =
          radiance * (double(fxcontracts::shader::flashGlow(distance, flash.radiusMetres)) *
                          height * attenuation +
                      double(fxcontracts::shader::flashSkyLight(distance, flash.radiusMetres)));
      const double a = luminance(before.radiance[i]);
      const double b = luminance(after.radiance[i]);
      // The output is half floats: each of a and b is off by up to 2^-11 of itself.
      const double rounding = std::ldexp(std::max(a, b), -11) * 2.0;
      const double measured = (b - a) / (1.0 - transmittance);
      result.worstError =
          std::max(result.worstError,
                   (std::abs(measured - expected) - rounding / (1.0 - transmittance)) / expected);
      result.meanHeightFraction += height;
      ++result.pixels;
    }
  }
  result.meanHeightFraction /= double(std::max<std::size_t>(result.pixels, 1));
  return result;
}

TEST_F(Lightning, EachPixelsGlowIsTheSeedsFormulaHeightGradientIncluded) {
  const clouds::Settings s = clouds::tools::singleFrame(overcast());
  harness().cut();
  harness().render(underTheOvercast(), s, kExtent);
  const clouds::shader::CloudUniforms u = impl().lastUniforms();
  // From below, the flash just inside the base: the bases it lights glow little.
  const GlowAgainstFormula below =
      glowAgainstFormula(harness(), u, underTheOvercast(), flashAhead(), s);
  // From above, looking down 35 degrees, a flash 300 m under the layer's top ahead: the
  // towers' upper parts glow.
  CloudView above = underTheOvercast();
  above.position.y = u.layerTopMetres + 1500.0;
  above.pitchDegrees = -35.0;
  clouds::LightningFlash high = flashAhead();
  high.positionMetres = {0.0, u.layerTopMetres - 300.0,
                         -(above.position.y - u.layerTopMetres) / std::tan(glm::radians(35.0))};
  const GlowAgainstFormula fromAbove = glowAgainstFormula(harness(), u, above, high, s);
  for (const auto& [name, g] : {std::pair{"below", below}, std::pair{"above", fromAbove}}) {
    std::printf(
        "%s: %zu pixels near the flash, their clouds' mean height fraction %.2f, worst "
        "error against the formula %.4f\n",
        name, g.pixels, g.meanHeightFraction, g.worstError);
    EXPECT_GT(g.pixels, 20u) << name;
    EXPECT_LT(g.worstError, 0.02) << name;
  }
  // The two views see clouds low and high in the layer: without the gradient each would be off
  // the formula by 1 / (height fraction) - 1 (several times over from below).
  EXPECT_LT(below.meanHeightFraction, 0.2);
  EXPECT_GT(fromAbove.meanHeightFraction, 2.0 * below.meanHeightFraction);
}

// The glow is less where the cloud is dense (the seeds' pseudo-attenuation): near the flash,
// the glow per unit of cloud (what it adds over its sky light, over the cloud's opacity) of an
// overcast ten times as dense is clearly less (0.71 of it; 1.01 without the attenuation).
double nearGlowPerCloud(clouds::tools::CloudHarness& h, float densityMultiplier) {
  clouds::Settings s = clouds::tools::singleFrame(overcast());
  s.densityMultiplier = densityMultiplier;
  CloudView view = underTheOvercast();
  h.cut();
  const CloudFrame before = h.render(view, s, kExtent);
  view.lightningFlashes = {flashAhead()};
  h.cut();
  const CloudFrame after = h.render(view, s, kExtent);
  const clouds::tools::PixelRays rays(view, kExtent);
  const glm::dvec3 flash = flashAhead().positionMetres - view.position;
  double glow = 0.0;
  std::size_t near = 0;
  for (std::uint32_t y = 0; y < kExtent.height; ++y) {
    for (std::uint32_t x = 0; x < kExtent.width; ++x) {
      const std::size_t i = std::size_t{y} * kExtent.width + x;
      const double depth = before.depth[i].y;
      const double d = glm::length(glm::dvec3(rays.direction(x, y)) * depth - flash);
      const double cloud = 1.0 - double(before.radiance[i].a);
      if (depth <= 0.0 || d > 1000.0 || cloud < 0.5) continue;
      const double sky = fxcontracts::shader::flashSkyLight(float(d), 4000.0f) * 1300.0 / 3.0;
      glow += (luminance(after.radiance[i]) - luminance(before.radiance[i])) / cloud - sky;
      ++near;
    }
  }
  return near > 20 ? glow / double(near) : -1.0;
}

TEST_F(Lightning, DenseCloudGlowsLess) {
  const double thin = nearGlowPerCloud(harness(), 1.0f);
  const double dense = nearGlowPerCloud(harness(), 10.0f);
  std::printf("glow per unit of cloud near the flash: %.2f, ten times as dense %.2f\n", thin,
              dense);
  ASSERT_GT(thin, 0.0) << "cloud near the flash";
  ASSERT_GT(dense, 0.0) << "cloud near the flash";
  EXPECT_LT(dense, 0.85 * thin);
}

// With temporal reuse (1 pixel in 16 marched a frame), two renderers over 12 frames, `light`
// adding lightning to frames 6 to 8 of one: it shows while it lasts, and frame 9 equals the
// unlit renderer's to the bit (nothing of it entered a history).
void expectNothingLeftBehind(engine::gfx::Device& device, const clouds::Settings& s, CloudView view,
                             const std::function<void(CloudView&)>& light, const char* what) {
  clouds::tools::CloudHarness lit(device, kExtent);
  clouds::tools::CloudHarness never(device, kExtent);
  for (int frame = 0; frame < 12; ++frame) {
    CloudView withLight = view;
    if (frame >= 6 && frame < 9) light(withLight);
    const CloudFrame a = lit.render(withLight, s, kExtent);
    const CloudFrame b = never.render(view, s, kExtent);
    if (frame == 7) {
      EXPECT_NE(a.radiance, b.radiance) << what << " shows while it lasts";
    }
    if (frame == 9) {
      EXPECT_EQ(a.radiance, b.radiance) << "nothing of " << what << " left in the history";
      EXPECT_EQ(a.depth, b.depth);
    }
    view.timeSeconds += 1.0 / 30.0;
  }
}

TEST_F(Lightning, TheFrameAfterAFlashIsAsIfItNeverWas) {
  expectNothingLeftBehind(
      device(), clouds::settingsFor(clouds::Quality::Medium, overcast()), underTheOvercast(),
      [](CloudView& v) { v.lightningFlashes = {flashAhead()}; }, "the flash");
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

// A layer without room for flashes or bolts has no lightning memory at all; room for flashes
// adds the glow image and the flashes' blocks, room for bolts their buffers.
TEST_F(Lightning, NoLightningNoBuffer) {
  clouds::tools::CloudHarness none(device(), kExtent);
  clouds::Settings s = clouds::tools::singleFrame(overcast());
  s.lightningFlashes = 0;
  none.render(underTheOvercast(), s, kExtent);
  EXPECT_EQ(none.memoryUsage().lightningBytes, 0u);
  s.lightningFlashes = 4;
  none.render(underTheOvercast(), s, kExtent);
  const std::uint64_t flashes = none.memoryUsage().lightningBytes;
  EXPECT_GT(flashes, 0u) << "the glow and the flashes' blocks";
  s.lightningBoltSegments = 8;
  none.render(underTheOvercast(), s, kExtent);
  EXPECT_GT(none.memoryUsage().lightningBytes, flashes) << "the bolts' buffers";
}

// Looking level from 300 m up, a bolt straight ahead: from inside the cloud (base 1.5 km) down
// through the screen's centre column, `distance` metres ahead, `yEnd` its lower end.
CloudView lookingAtTheBolt() {
  CloudView view = underTheOvercast();
  view.pitchDegrees = 0.0;
  return view;
}

clouds::LightningBoltSegment boltAhead(double distance, double yStart, double yEnd) {
  clouds::LightningBoltSegment piece;
  piece.fromMetres = {0.0, yStart, -distance};
  piece.toMetres = {0.0, yEnd, -distance};
  piece.radiance = glm::vec3(1e4f);
  piece.widthMetres = 3.0f;
  return piece;
}

clouds::Settings withBolts(clouds::Settings s) {
  s.lightningBoltSegments = 8;
  return s;
}

// The light a bolt adds to each output row (summed across the row), and the pixels it
// changes outside the centre columns.
struct BoltRows {
  std::vector<double> light;
  std::size_t outside = 0;
};

BoltRows boltRows(const CloudFrame& with, const CloudFrame& without) {
  BoltRows rows;
  rows.light.assign(kExtent.height, 0.0);
  for (std::uint32_t y = 0; y < kExtent.height; ++y) {
    for (std::uint32_t x = 0; x < kExtent.width; ++x) {
      const std::size_t i = std::size_t{y} * kExtent.width + x;
      const double added = luminance(with.radiance[i]) - luminance(without.radiance[i]);
      rows.light[y] += added;
      if (added != 0.0 && (x < kExtent.width / 2 - 2 || x > kExtent.width / 2 + 1)) ++rows.outside;
    }
  }
  return rows;
}

// Below the cloud, a bolt thinner than a pixel is a line of its energy: each row gains its
// radiance times its width over the pixel's footprint, in the centre columns only; inside the
// cloud, less (seen through it).
TEST_F(Lightning, ABoltIsALineOfItsEnergy) {
  const clouds::Settings s = withBolts(clouds::tools::singleFrame(overcast()));
  CloudView view = lookingAtTheBolt();
  harness().cut();
  const CloudFrame without = harness().render(view, s, kExtent);
  view.lightningBolts = {boltAhead(3000.0, 2500.0, 0.0)};
  harness().cut();
  const CloudFrame with = harness().render(view, s, kExtent);
  ASSERT_TRUE(test::allValid(with));
  const BoltRows rows = boltRows(with, without);
  EXPECT_EQ(rows.outside, 0u) << "the bolt is a line down the centre";
  // The centre row looks at the bolt 3 km ahead, square on: a pixel there is 3 km times the
  // angle it spans.
  const double pixelMetres = 3000.0 * 2.0 * std::tan(glm::radians(35.0)) / kExtent.height;
  const double expected = 1e4 * 3.0 / pixelMetres;
  const std::uint32_t centre = kExtent.height / 2;
  std::printf("bolt: centre row gains %.2f (expected %.2f)\n", rows.light[centre], expected);
  EXPECT_NEAR(rows.light[centre], expected, 0.02 * expected) << "its energy, not more or less";
  // The row that sees the bolt at 1.9 km, 400 m inside the cloud's base (1.5 km): there it is
  // seen through the cloud.
  const double up = (1900.0 - view.position.y) / 3000.0;  // tangent of the angle above level
  const auto inCloud =
      centre - std::uint32_t(0.5 * kExtent.height * up / std::tan(glm::radians(35.0)));
  std::printf("bolt: row %u (in the cloud) gains %.2f\n", inCloud, rows.light[inCloud]);
  EXPECT_LT(rows.light[inCloud], 0.5 * expected) << "the cloud in front dims it";
}

// Geometry nearer than a bolt hides it: below a flat ground, a bolt shows without the ground
// in the depth buffer and not at all with it.
TEST_F(Lightning, GeometryNearerThanABoltHidesIt) {
  const clouds::Settings s = withBolts(clouds::tools::singleFrame(overcast()));
  for (bool ground : {false, true}) {
    CloudView view = lookingAtTheBolt();
    view.groundDepth = ground;
    harness().cut();
    const CloudFrame without = harness().render(view, s, kExtent);
    view.lightningBolts = {boltAhead(3000.0, -100.0, -1500.0)};
    harness().cut();
    const CloudFrame with = harness().render(view, s, kExtent);
    double light = 0.0;
    for (double row : boltRows(with, without).light) light += row;
    if (ground) {
      EXPECT_EQ(light, 0.0) << "the ground in front hides it";
    } else {
      EXPECT_GT(light, 100.0) << "without the ground it shows";
    }
  }
}

// A bolt (with its flash) on three frames leaves nothing in the temporal history.
TEST_F(Lightning, TheFrameAfterABoltIsAsIfItNeverWas) {
  expectNothingLeftBehind(
      device(), withBolts(clouds::settingsFor(clouds::Quality::Medium, overcast())),
      lookingAtTheBolt(),
      [](CloudView& v) {
        v.lightningFlashes = {flashAhead()};
        v.lightningBolts = {boltAhead(3000.0, 2500.0, 0.0)};
      },
      "the bolt");
}

TEST_F(Lightning, BoltHardCasesStayFinite) {
  const clouds::Settings s = withBolts(clouds::tools::singleFrame(overcast()));
  const CloudView base = lookingAtTheBolt();
  const glm::dvec3 eye = base.position;
  struct Case {
    const char* name;
    glm::dvec3 from;
    glm::dvec3 to;
  };
  const Case cases[] = {
      {"through the camera", eye + glm::dvec3(0.0, 500.0, 0.0), eye - glm::dvec3(0.0, 500.0, 0.0)},
      {"from behind to ahead", eye + glm::dvec3(0.0, 0.0, 500.0),
       eye - glm::dvec3(0.0, 0.0, 500.0)},
      {"behind the camera", eye + glm::dvec3(0.0, 0.0, 500.0), eye + glm::dvec3(10.0, 0.0, 900.0)},
      {"a point", {0.0, 300.0, -1000.0}, {0.0, 300.0, -1000.0}},
      {"1000 km long", {-1e6, 300.0, -1000.0}, {1e6, 300.0, -1000.0}},
      {"1000 km away", {0.0, 3000.0, -1e6}, {0.0, 0.0, -1e6}},
      {"at the near plane", eye + glm::dvec3(-1.0, 0.0, -0.01), eye + glm::dvec3(1.0, 0.0, -0.01)}};
  for (const Case& c : cases) {
    CloudView view = base;
    clouds::LightningBoltSegment piece = boltAhead(0.0, 0.0, 0.0);
    piece.fromMetres = c.from;
    piece.toMetres = c.to;
    piece.radiance = glm::vec3(1e9f);
    view.lightningBolts = {piece, piece};
    harness().cut();
    const CloudFrame frame = harness().render(view, s, kExtent);
    EXPECT_TRUE(test::allValid(frame)) << c.name;
  }
}

TEST_F(Lightning, BoltsNeedRoomInTheSettings) {
  clouds::Settings s = withBolts(clouds::tools::singleFrame(overcast()));
  CloudView view = lookingAtTheBolt();
  view.lightningBolts.assign(9, boltAhead(3000.0, 2500.0, 0.0));
  const std::string many = harness().tryRender(view, s, kExtent);
  EXPECT_NE(many.find("FrameInputs.lightningBolts: 9 segments"), std::string::npos) << many;
  view.lightningBolts.resize(2);
  view.lightningBolts[1].widthMetres = 0.0f;
  const std::string thin = harness().tryRender(view, s, kExtent);
  EXPECT_NE(thin.find("FrameInputs.lightningBolts[1].widthMetres"), std::string::npos) << thin;
}

// A bolt too big to list its blocks (wide and near, across a 640x480 frame) is drawn over its
// bounds instead, whole: light along all of its line, in every quarter of the frame.
TEST_F(Lightning, AScreenWideBoltIsDrawnWhole) {
  constexpr VkExtent2D kLarge{640, 480};
  clouds::tools::CloudHarness large(device(), kLarge);
  const clouds::Settings s = withBolts(clouds::tools::singleFrame(overcast()));
  CloudView view = lookingAtTheBolt();
  const CloudFrame without = large.render(view, s, kLarge);
  clouds::LightningBoltSegment piece = boltAhead(0.0, 0.0, 0.0);
  piece.fromMetres = view.position + glm::dvec3(-40.0, 25.0, -30.0);
  piece.toMetres = view.position + glm::dvec3(40.0, -25.0, -30.0);
  piece.widthMetres = 8.0f;
  view.lightningBolts = {piece};
  // The projection lists no blocks for it: more than kBoltMaxBlocks.
  clouds::FrameInputs inputs;
  inputs.renderExtent = kLarge;
  inputs.cameraPosition = view.position;
  inputs.view = glm::mat4(1.0f);
  inputs.projection = glm::perspective(glm::radians(view.verticalFovDegrees),
                                       float(kLarge.width) / float(kLarge.height), 1.0f, 1e5f);
  inputs.lightningBolts = view.lightningBolts;
  ASSERT_TRUE(clouds::detail::projectBolts(inputs).blocks.empty());
  const CloudFrame with = large.render(view, s, kLarge);
  ASSERT_TRUE(test::allValid(with));
  std::size_t quarters[4] = {0, 0, 0, 0};
  for (std::uint32_t y = 0; y < kLarge.height; ++y) {
    for (std::uint32_t x = 0; x < kLarge.width; ++x) {
      const std::size_t i = std::size_t{y} * kLarge.width + x;
      if (luminance(with.radiance[i]) > luminance(without.radiance[i]) + 1.0) {
        ++quarters[(x < kLarge.width / 2 ? 0 : 1) + (y < kLarge.height / 2 ? 0 : 2)];
      }
    }
  }
  std::printf("screen-wide bolt: lit pixels by quarter %zu %zu %zu %zu\n", quarters[0], quarters[1],
              quarters[2], quarters[3]);
  EXPECT_GT(quarters[0], 1000u) << "upper left: from there";
  EXPECT_GT(quarters[3], 1000u) << "lower right: to there";
}

}  // namespace
