// What frames cost, by the march's work counters and the pass timestamps: skipping empty
// weather cells changes the cost and not the picture, a clear sky is not marched, each preset
// costs more than the one below it, and the pass times account for the frame.
#include <gtest/gtest.h>

#include "cloud_gpu_fixture.h"

namespace {

using clouds::tools::CloudView;
using test::cumulusView;
using test::kExtent;
using test::meanOpacity;
using test::samples;
using CloudCost = test::CloudGpuTest;

TEST_F(CloudCost, EmptySpaceSkippingChangesTheCostNotThePicture) {
  // Coverage 0.4: broken cumulus; 0.3: a few clouds in a mostly clear sky.
  for (float coverage : {0.4f, 0.3f}) {
    clouds::Settings on = clouds::tools::singleFrame({});
    on.coverage = coverage;
    on.jitter = clouds::Jitter::None;
    on.maxViewSteps = 4096;    // every ray reaches its end either way: the same clouds in reach
    on.cheapSampling = false;  // coarse steps would miss different small clouds either way
    // Half the default steps: after a jump the samples restart at the cell's boundary, a shift
    // whose effect on the picture is the march's discretisation error, which the dark edges'
    // sharp falloff (in-scatter probability) made larger (39.6 dB at coverage 0.4 with the
    // default steps, 42.6 before that term read the coarse profile; 51.1 and 56.8 dB at the two
    // coverages with these).
    on.viewStepMetres = 30.0f;
    on.viewStepGrowth = 0.002f;
    clouds::Settings off = on;
    off.emptySpaceSkipping = false;
    CloudView view = cumulusView();
    view.pitchDegrees = 6.0;
    auto r = renderer();
    const clouds::tools::CloudFrame skipped = r->render(view, on, kExtent);
    const clouds::WorkCounters with = r->lastWorkCounters();
    r->cut();
    const clouds::tools::CloudFrame marched = r->render(view, off, kExtent);
    const clouds::WorkCounters without = r->lastWorkCounters();
    SCOPED_TRACE(coverage);
    ASSERT_GT(meanOpacity(marched), 0.002) << "the view must show clouds";
    EXPECT_GT(with.skippedCells, 0u);
    EXPECT_EQ(without.skippedCells, 0u);
    // Samples restart at cell boundaries, so they move a little: equal up to that.
    EXPECT_GE(clouds::tools::psnr(skipped.radiance, marched.radiance, 1.0), 40.0);
    // The fewer cells hold cloud, the more is skipped. A cell is empty only where its
    // coverage is zero everywhere (the noise inside is not known), so broken skies, where
    // most 780 m cells hold some coverage, save less than clear ones (measured: 0.85 and
    // 0.68 of the samples; a sky with no coverage at all is not marched, see the next test).
    const double fraction = double(with.viewSamples) / double(without.viewSamples);
    EXPECT_LT(fraction, coverage > 0.35f ? 0.9 : 0.75);
  }
}

TEST_F(CloudCost, ClearSkyCostsLessThanATenthOfOvercast) {
  clouds::Settings clear = clouds::settingsFor(clouds::Quality::High);
  clear.coverage = 0.0f;
  clouds::Settings overcast = clear;
  overcast.coverage = 1.0f;
  overcast.cloudType = 0.1f;  // a stratus deck
  auto r = renderer();
  const clouds::tools::CloudFrame empty = r->render(cumulusView(), clear, kExtent, 3);
  const clouds::WorkCounters clearWork = r->lastWorkCounters();
  // Coverage 0 cannot show a cloud anywhere: the module clears its outputs instead of marching.
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "clear sky: nothing to march");
  EXPECT_EQ(clearWork.tracedPixels, 0u);
  for (const glm::vec4& p : empty.radiance) ASSERT_EQ(p, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (const glm::vec2& d : empty.depth) ASSERT_EQ(d, glm::vec2(0.0f));
  // Back to cloud, without a cut: nothing stale from before the clear frames is reused.
  r->render(cumulusView(), overcast, kExtent, 1);
  EXPECT_FALSE(r->context().lastFrameReport().historyUsed);
  r->render(cumulusView(), overcast, kExtent, 2);
  const clouds::WorkCounters overcastWork = r->lastWorkCounters();
  EXPECT_GT(samples(overcastWork), 0u);
}

// A sky that stays clear is cleared once: its later frames leave the outputs as they are. The
// clears come back whenever something else wrote the outputs (a cloudy frame) or they were
// replaced (a larger render extent), each of which would otherwise show through.
TEST_F(CloudCost, AClearSkyIsClearedOnceThenLeftAsItIs) {
  clouds::Settings clear = clouds::settingsFor(clouds::Quality::Medium);
  clear.coverage = 0.0f;
  clouds::Settings overcast = clear;
  overcast.coverage = 1.0f;
  const auto expectEmptySky = [](const clouds::tools::CloudFrame& frame, const char* when) {
    SCOPED_TRACE(when);
    for (const glm::vec4& p : frame.radiance) ASSERT_EQ(p, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (const glm::vec2& d : frame.depth) ASSERT_EQ(d, glm::vec2(0.0f));
  };
  auto r = renderer();
  r->render(cumulusView(), clear, {kExtent.width / 2, kExtent.height / 2});
  expectEmptySky(r->render(cumulusView(), clear, kExtent), "outputs replaced by larger ones");
  const glm::vec4 mark(1.0f, 2.0f, 3.0f, 0.5f);
  r->markRadianceOutput(mark);
  const clouds::tools::CloudFrame kept = r->render(cumulusView(), clear, kExtent);
  for (const glm::vec4& p : kept.radiance) ASSERT_EQ(p, mark) << "a clear frame cleared again";
  r->render(cumulusView(), overcast, kExtent);
  expectEmptySky(r->render(cumulusView(), clear, kExtent), "after a cloudy frame");
}

TEST_F(CloudCost, EachPresetCostsMoreThanTheOneBelowIt) {
  const clouds::Quality presets[] = {clouds::Quality::Low, clouds::Quality::Medium,
                                     clouds::Quality::High, clouds::Quality::Ultra,
                                     clouds::Quality::Reference};
  std::uint64_t previous = 0;
  for (clouds::Quality q : presets) {
    auto r = renderer();
    // A steady-state frame: history in use where the preset reuses it.
    r->render(cumulusView(), clouds::settingsFor(q), kExtent, 3);
    const clouds::WorkCounters work = r->lastWorkCounters();
    EXPECT_GT(samples(work), previous) << clouds::qualityName(q);
    EXPECT_GT(work.tracedPixels, 0u);
    previous = samples(work);
  }
}

TEST_F(CloudCost, PassTimingsAccountForTheFrame) {
  auto r = renderer();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  r->render(cumulusView(), high, kExtent, 1);
  std::vector<std::string> first;
  for (const clouds::PassTiming& t : r->lastPassTimings()) first.emplace_back(t.name);
  EXPECT_EQ(first.front(), "noise") << "the first frame generates the noise";
  r->render(cumulusView(), high, kExtent, 1);
  ASSERT_FALSE(r->lastPassTimings().empty());
  EXPECT_EQ(std::string(r->lastPassTimings().front().name), "weather")
      << "the next period's weather map is prepared a band per frame";
  // 16 bands make the next map; after that a frame at the same time does no weather work.
  r->render(cumulusView(), high, kExtent, 16);
  std::vector<std::string> names;
  double sum = 0.0;
  for (const clouds::PassTiming& t : r->lastPassTimings()) {
    names.emplace_back(t.name);
    EXPECT_GT(t.milliseconds, 0.0) << t.name;
    sum += t.milliseconds;
  }
  const std::vector<std::string> expected = {"scene distance", "march", "reconstruct", "upsample"};
  EXPECT_EQ(names, expected) << "same weather period, next map ready: no weather work";
  // The passes lie inside the dispatch: together at most its whole time. (How much of the
  // frame they cover is not asserted: on a loaded CPU device the time between passes, when
  // lavapipe's threads are preempted, grows without bound. The list above says every pass is
  // there.)
  EXPECT_LE(sum, r->lastGpuMilliseconds() * 1.02 + 0.05);
}

}  // namespace
