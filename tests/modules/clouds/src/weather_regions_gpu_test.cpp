// Weather regions on lavapipe (FrameInputs::weatherRegions, cloud_weather_regions.h): a storm
// region over a clear sky shows where it lies and nowhere else, the march matches the CPU
// reference there, empty-space skipping skips none of its cloud, each field of its look moves
// its image its way, a region beyond its blend (or the regions' code without one) changes no
// pixel, the history survives flying
// into a region and a region easing but not one jumping, and bad regions are named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cloud_gpu_fixture.h"
#include "clouds/weather.h"
#include "cpu_reference.h"

namespace {

using clouds::WeatherPreset;
using clouds::WeatherRegion;
using clouds::tools::CloudFrame;
using clouds::tools::CloudView;
using test::meanOpacity;
constexpr VkExtent2D kExtent{96, 54};

class WeatherRegions : public test::SharedHarnessTest<96, 54> {
 protected:
  // A renderer of its own (a history of its own) that counts its work.
  static std::unique_ptr<clouds::tools::CloudHarness> counting() {
    clouds::tools::HarnessOptions options;
    options.workCounters = true;
    return std::make_unique<clouds::tools::CloudHarness>(device(), kExtent, options);
  }
};

// The ground camera looking up at 20 degrees along `yawDegrees`.
CloudView groundView(double yawDegrees) {
  CloudView view = test::cumulusView();
  view.yawDegrees = yawDegrees;
  return view;
}

// Sparse weather with a Stormy region 8 km ahead of groundView(0), 3 km across at full strength
// and fading over 3 km beyond.
clouds::Settings sparse() {
  clouds::Settings s = clouds::withWeather(clouds::tools::singleFrame({}),
                                           clouds::weatherPreset(WeatherPreset::Sparse));
  s.jitter = clouds::Jitter::None;  // frames compared pixel for pixel
  s.weatherRegions = clouds::kMaxWeatherRegions;
  return s;
}
WeatherRegion stormAhead() {
  WeatherRegion storm;
  const glm::vec3 ahead = clouds::tools::forwardDirection(groundView(0.0));
  storm.centreMetres =
      glm::dvec2(ahead.x, ahead.z) / glm::length(glm::dvec2(ahead.x, ahead.z)) * 8000.0;
  storm.radiusMetres = 3000.0f;
  storm.blendMetres = 3000.0f;
  return clouds::withWeather(storm, clouds::weatherPreset(WeatherPreset::Stormy));
}

TEST_F(WeatherRegions, AStormRegionShowsWhereItLiesAndMatchesTheCpuReference) {
  clouds::Settings clear = sparse();
  clear.coverage = 0.0f;  // nothing but the region: the sky is not "clear" while it holds cloud
  CloudView towards = groundView(0.0);
  towards.weatherRegions = {stormAhead()};
  CloudView away = groundView(180.0);
  away.weatherRegions = towards.weatherRegions;
  const CloudFrame storm = harness().render(towards, clear, kExtent);
  const double stormOpacity = meanOpacity(storm);
  const double awayOpacity = meanOpacity(harness().render(away, clear, kExtent));
  std::printf("mean opacity towards the storm %.3f, away %.3f\n", stormOpacity, awayOpacity);
  EXPECT_GT(stormOpacity, 0.02);
  EXPECT_EQ(awayOpacity, 0.0) << "the region's cloud reaches beyond its blend";
  harness().render(towards, clear, kExtent);
  const clouds::tools::CloudFrame gpu = harness().render(towards, clear, kExtent);
  const clouds::tools::CloudFrame cpu = clouds::tools::renderCpuReference(
      clouds::tools::readTextures(harness()), impl().lastUniforms(), clear, {});
  float peak = 1.0f;
  for (const glm::vec4& p : cpu.radiance) peak = std::max({peak, p.r, p.g, p.b});
  EXPECT_GE(clouds::tools::psnr(gpu.radiance, cpu.radiance, peak), 40.0);
}

TEST_F(WeatherRegions, EmptySpaceSkippingSkipsNoneOfARegionsCloud) {
  // As CloudCost.EmptySpaceSkippingChangesTheCostNotThePicture: every ray to its end, no coarse
  // steps, short steps; the weather around the storm holds no cloud, so its cells are skipped.
  clouds::Settings on = sparse();
  on.coverage = 0.0f;
  on.maxViewSteps = 4096;
  on.cheapSampling = false;
  on.viewStepMetres = 30.0f;
  on.viewStepGrowth = 0.002f;
  clouds::Settings off = on;
  off.emptySpaceSkipping = false;
  CloudView view = groundView(0.0);
  view.pitchDegrees = 8.0;
  view.weatherRegions = {stormAhead()};
  auto r = counting();
  const CloudFrame skipped = r->render(view, on, kExtent);
  const clouds::WorkCounters with = r->lastWorkCounters();
  r->cut();
  const CloudFrame marched = r->render(view, off, kExtent);
  ASSERT_GT(meanOpacity(marched), 0.02) << "the view must show the storm";
  EXPECT_GT(with.skippedCells, 0u);
  EXPECT_GE(clouds::tools::psnr(skipped.radiance, marched.radiance, 1.0), 40.0);
}

TEST_F(WeatherRegions, EachFieldOfARegionsLookMovesItsImageItsWay) {
  // The camera under the middle of a Cloudy region in Sparse weather.
  const clouds::Settings s = sparse();
  CloudView view = groundView(0.0);
  WeatherRegion region;
  region.centreMetres = {view.position.x, view.position.z};
  region.radiusMetres = 20000.0f;
  region = clouds::withWeather(region, clouds::weatherPreset(WeatherPreset::Cloudy));
  const auto opacityWith = [&](const WeatherRegion& r) {
    CloudView v = view;
    v.weatherRegions = {r};
    return meanOpacity(harness().render(v, s, kExtent));
  };
  const double plain = opacityWith(region);
  ASSERT_GT(plain, 0.05);
  ASSERT_LT(plain, 0.9);
  EXPECT_GT(plain, meanOpacity(harness().render(view, s, kExtent)) + 0.02)
      << "the region's look is not the sky's";
  const auto more = [&](const char* field, WeatherRegion from, auto change) {
    WeatherRegion changed = from;
    change(changed);
    const double before = opacityWith(from);
    const double after = opacityWith(changed);
    std::printf("%s: mean opacity %.4f -> %.4f\n", field, before, after);
    EXPECT_GT(after - before, 0.005) << field;
  };
  WeatherRegion towering = region;
  towering.cloudType = 1.0f;  // anvils are the tops of cumulonimbus
  more("coverage", region, [](WeatherRegion& r) { r.coverage += 0.1f; });
  more("densityMultiplier", region, [](WeatherRegion& r) { r.densityMultiplier *= 2.0f; });
  more("cloudType", region, [](WeatherRegion& r) { r.cloudType = 1.0f; });
  more("anvilBias", towering, [](WeatherRegion& r) { r.anvilBias = 1.0f; });
}

TEST_F(WeatherRegions, ARegionBeyondItsBlendChangesNoPixel) {
  const clouds::Settings s = sparse();
  CloudView view = groundView(0.0);
  const CloudFrame without = harness().render(view, s, kExtent);
  ASSERT_GT(meanOpacity(without), 0.01);
  WeatherRegion far = stormAhead();
  far.densityMultiplier = s.densityMultiplier;  // the extinction's scale stays the sky's
  far.centreMetres *= 40.0;                     // 320 km ahead: beyond the march's reach
  view.weatherRegions = {far};
  const CloudFrame with = harness().render(view, s, kExtent);
  EXPECT_EQ(with.radiance, without.radiance);
  // Nor does the regions' code in a pipeline that has none to read (Settings::weatherRegions).
  clouds::Settings none = s;
  none.weatherRegions = 0;
  view.weatherRegions.clear();
  EXPECT_EQ(harness().render(view, none, kExtent).radiance, without.radiance);
}

TEST_F(WeatherRegions, FarFromTheOriginARegionLiesWhereItLies) {
  const clouds::Settings s = sparse();
  CloudView origin = groundView(0.0);
  origin.weatherRegions = {stormAhead()};
  const CloudFrame atOrigin = harness().render(origin, s, kExtent);
  ASSERT_GT(meanOpacity(atOrigin), 0.05);
  // The weather tile (50 km) divides 10,000 km: the same sky, the region moved with the camera.
  CloudView far = origin;
  far.position.x += 1e7;
  far.position.z -= 1e7;
  far.weatherRegions[0].centreMetres += glm::dvec2(1e7, -1e7);
  EXPECT_GE(clouds::tools::psnr(atOrigin.radiance, harness().render(far, s, kExtent).radiance, 1.0),
            60.0);
}

TEST_F(WeatherRegions, FlyingIntoARegionOrEasingItKeepsTheHistoryAndAJumpDropsIt) {
  clouds::Settings s = clouds::settingsFor(clouds::Quality::Medium);
  s.weatherRegions = 1;
  auto r = counting();
  CloudView view = groundView(0.0);
  view.position.y = 1000.0;
  view.weatherRegions = {stormAhead()};
  const glm::vec3 ahead = clouds::tools::forwardDirection(view);
  const glm::dvec2 step = glm::dvec2(ahead.x, ahead.z) / glm::length(glm::dvec2(ahead.x, ahead.z));
  r->render(view, s, kExtent);
  const float stormCoverage = view.weatherRegions[0].coverage;
  for (int frame = 0; frame < 12; ++frame) {
    view.position += glm::dvec3(step.x, 0.0, step.y) * 400.0;  // 12 km a second at 30 fps:
    view.timeSeconds += 1.0 / 30.0;                            //   into the storm in 20 frames
    view.weatherRegions[0].coverage = stormCoverage - 0.002f * float(frame + 1);  // and easing
    r->render(view, s, kExtent, 1);
    const clouds::FrameReport& report = r->context().lastFrameReport();
    ASSERT_TRUE(report.historyUsed) << "frame " << frame << ": " << report.resetReason;
  }
  view.weatherRegions[0].centreMetres += glm::dvec2(2000.0, 0.0);  // a jump of 2/3 its blend
  r->render(view, s, kExtent, 1);
  EXPECT_FALSE(r->context().lastFrameReport().historyUsed);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "weather regions changed");
  r->render(view, s, kExtent, 1);
  view.weatherRegions.clear();  // and one vanishing
  r->render(view, s, kExtent, 1);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "weather regions changed");
}

TEST_F(WeatherRegions, BadRegionsAreRefusedNamingTheField) {
  const clouds::Settings s = sparse();
  const auto refusal = [&](const std::vector<WeatherRegion>& regions) {
    CloudView view = groundView(0.0);
    view.weatherRegions = regions;
    return harness().tryRender(view, s, kExtent);
  };
  WeatherRegion ok;
  EXPECT_EQ(refusal({ok}), "");
  std::vector<WeatherRegion> many(clouds::kMaxWeatherRegions + 1, ok);
  EXPECT_NE(refusal(many).find("FrameInputs.weatherRegions: 9 regions, more than "
                               "Settings.weatherRegions = 8"),
            std::string::npos);
  const struct {
    void (*spoil)(WeatherRegion&);
    const char* field;
  } cases[] = {
      {[](WeatherRegion& r) { r.centreMetres.x = std::nan(""); }, "weatherRegions[1].centreMetres"},
      {[](WeatherRegion& r) { r.headingDegrees = INFINITY; }, "weatherRegions[1].headingDegrees"},
      {[](WeatherRegion& r) { r.halfSidesMetres.y = -1.0f; },
       "weatherRegions[1].halfSidesMetres.y"},
      {[](WeatherRegion& r) { r.radiusMetres = 2e7f; }, "weatherRegions[1].radiusMetres"},
      {[](WeatherRegion& r) { r.blendMetres = 50.0f; }, "weatherRegions[1].blendMetres"},
      {[](WeatherRegion& r) { r.coverage = std::nanf(""); }, "weatherRegions[1].coverage"},
      {[](WeatherRegion& r) { r.cloudType = 1.5f; }, "weatherRegions[1].cloudType"},
      {[](WeatherRegion& r) { r.densityMultiplier = -1.0f; },
       "weatherRegions[1].densityMultiplier"},
      {[](WeatherRegion& r) { r.anvilBias = 2.0f; }, "weatherRegions[1].anvilBias"},
  };
  for (const auto& c : cases) {
    WeatherRegion bad = ok;
    c.spoil(bad);
    const std::string error = refusal({ok, bad});
    EXPECT_NE(error.find(std::string("FrameInputs.") + c.field), std::string::npos) << error;
  }
}

}  // namespace
