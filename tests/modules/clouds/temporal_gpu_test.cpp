// Temporal reconstruction, empty-space skipping and quality presets on lavapipe: a static
// camera converges to the Reference, and with temporal upsampling to detail finer than the
// trace; the frame after a cut, a resize or relighting equals a fresh renderer's; NaN in the
// history never reaches the output; the camera in the layer
// turns reprojection off; skipping empty weather cells changes (almost) nothing but the cost;
// each preset costs more than the one below it, by the march's work counters.
#include <gtest/gtest.h>

#include <cmath>

#include "cloud_harness.h"
#include "context_impl.h"
#include "cpu_reference.h"
#include "gpu_test.h"

namespace {

using test::CloudView;
constexpr VkExtent2D kExtent{160, 90};

class CloudTemporal : public test::GpuTest {
 protected:
  // A renderer that counts its work; created per test, so each starts with no history.
  static std::unique_ptr<test::CloudHarness> renderer() {
    test::HarnessOptions options;
    options.workCounters = true;
    options.passTimings = true;
    return std::make_unique<test::CloudHarness>(device(), kExtent, options);
  }
};

// Scattered cumulus seen from the ground, looking a little up (the sample's usual view).
CloudView cumulusView() {
  CloudView view;
  view.position = {0.0, 300.0, 0.0};
  view.pitchDegrees = 20.0;
  view.yawDegrees = 270.0;
  view.timeSeconds = 5.0;
  return view;
}

double meanOpacity(const test::CloudFrame& frame) {
  double sum = 0.0;
  for (const glm::vec4& p : frame.radiance) sum += 1.0 - p.a;
  return sum / double(frame.radiance.size());
}

bool allValid(const test::CloudFrame& frame) {
  for (const glm::vec4& p : frame.radiance) {
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(p[c]) || p[c] < 0.0f) return false;
    }
    if (p.a > 1.0f) return false;
  }
  for (const glm::vec2& d : frame.depth) {
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || d.x < 0.0f || d.y < 0.0f) return false;
  }
  return true;
}

float maxAbsDifference(const test::CloudFrame& a, const test::CloudFrame& b) {
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.radiance.size(); ++i) {
    const glm::vec4 d = glm::abs(a.radiance[i] - b.radiance[i]);
    worst = std::max({worst, d.r, d.g, d.b, d.a});
  }
  return worst;
}

std::uint64_t samples(const clouds::WorkCounters& c) {
  return c.viewSamples + c.lightSamples;
}

TEST_F(CloudTemporal, AStaticCameraConvergesToTheReference) {
  const CloudView view = cumulusView();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  auto r = renderer();
  std::vector<glm::vec3> previous;
  double lateChange = 0.0;  // largest frame-to-frame mean change over the last 16 frames
  for (int frame = 0; frame < 48; ++frame) {
    const std::vector<glm::vec3> image =
        test::tonemappedPixels(r->render(view, high, kExtent), view);
    if (!previous.empty() && frame >= 32) {
      lateChange = std::max(lateChange, test::imageError(image, previous).meanAbs);
    }
    EXPECT_EQ(r->context().lastFrameReport().historyUsed, frame > 0) << "frame " << frame;
    previous = image;
  }
  // Every pixel has been refreshed three times over; what still changes is the new jitter
  // of the refreshed 1-in-16 pixels, blended with their history.
  EXPECT_LT(lateChange, 2.0 / 255.0);

  // The converged Reference: 16 frames whose rays move inside their pixels, averaged.
  const test::CloudFrame reference = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference), kExtent, 16);
  ASSERT_GT(meanOpacity(reference), 0.05) << "the view must show clouds";
  const test::ImageError error =
      test::imageError(previous, test::tonemappedPixels(reference, view));
  EXPECT_GE(error.psnr, 35.0) << "mean abs " << error.meanAbs << ", max abs " << error.maxAbs;
}

// Above the layer, looking down: distant cloud tops are detail finer than High's
// half-resolution trace.
CloudView aboveTheLayerView() {
  CloudView view = cumulusView();
  view.position.y = 6500.0;
  view.pitchDegrees = -25.0;
  return view;
}

TEST_F(CloudTemporal, TemporalUpsamplingConvergesToDetailFinerThanTheTrace) {
  const CloudView view = aboveTheLayerView();
  const clouds::Settings upsampled = clouds::settingsFor(clouds::Quality::High);
  ASSERT_TRUE(clouds::upsamplesTemporally(upsampled));
  clouds::Settings traceOnly = upsampled;
  traceOnly.temporalUpsampling = false;
  const std::vector<glm::vec3> reference = test::tonemappedPixels(
      renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                 16),
      view);
  // A trace pixel is refreshed once per 16 frames and covers 2 x 2 output pixels: after 128
  // frames every output pixel holds two rays of its own.
  auto r = renderer();
  std::vector<glm::vec3> image;
  double lateChange = 0.0;
  for (int frame = 0; frame < 136; ++frame) {
    std::vector<glm::vec3> next = test::tonemappedPixels(r->render(view, upsampled, kExtent), view);
    if (frame >= 128) lateChange = std::max(lateChange, test::imageError(next, image).meanAbs);
    image = std::move(next);
  }
  EXPECT_LT(lateChange, 2.0 / 255.0) << "converged: little changes from frame to frame";
  const double upsampledPsnr = test::imageError(image, reference).psnr;
  const double traceOnlyPsnr =
      test::imageError(
          test::tonemappedPixels(renderer()->render(view, traceOnly, kExtent, 136), view),
          reference)
          .psnr;
  // At 160 x 90 the cloud tops are smaller in pixels than at the benchmark's 640 x 360 (where
  // High's 35 dB target is measured): measured here 24.9 dB with the trace alone, 31.8 dB
  // upsampled.
  EXPECT_GE(upsampledPsnr, 30.0) << "trace only: " << traceOnlyPsnr << " dB";
  EXPECT_GE(upsampledPsnr, traceOnlyPsnr + 5.0) << "trace only: " << traceOnlyPsnr << " dB";
}

TEST_F(CloudTemporal, TemporalUpsamplingHelpsUnderWindDriftToo) {
  // Time runs (the wind drifts the clouds' detail, 10 m/s): every frame reprojects and
  // resamples the output history instead of reading it in place.
  CloudView view = aboveTheLayerView();
  const clouds::Settings upsampled = clouds::settingsFor(clouds::Quality::High);
  clouds::Settings traceOnly = upsampled;
  traceOnly.temporalUpsampling = false;
  constexpr int kFrames = 136;
  auto a = renderer();
  auto b = renderer();
  test::CloudFrame withUpsampling, withoutUpsampling;
  for (int frame = 0; frame < kFrames; ++frame) {
    view.timeSeconds = 5.0 + frame / 30.0;
    withUpsampling = a->render(view, upsampled, kExtent);
    withoutUpsampling = b->render(view, traceOnly, kExtent);
    ASSERT_FALSE(frame > 0 && std::string(a->context().lastFrameReport().resetReason) != "")
        << "frame " << frame << ": " << a->context().lastFrameReport().resetReason;
  }
  const std::vector<glm::vec3> reference = test::tonemappedPixels(
      renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                 16),
      view);
  const double upsampledPsnr =
      test::imageError(test::tonemappedPixels(withUpsampling, view), reference).psnr;
  const double traceOnlyPsnr =
      test::imageError(test::tonemappedPixels(withoutUpsampling, view), reference).psnr;
  // Less than in a still view (the detail the own samples hold scrolls with the wind, so they
  // are clamped to this frame's trace neighbourhood), but still well above the trace alone:
  // measured 29.2 dB against 24.9 (still: 31.8).
  EXPECT_GE(upsampledPsnr, traceOnlyPsnr + 3.0) << "trace only: " << traceOnlyPsnr << " dB";
  ASSERT_TRUE(allValid(withUpsampling));
  // Poisoned now (trace and output history), the reprojected path must catch it as well; the
  // frame is rebuilt from its 1-in-16 fresh samples, as in the trace history's NaN test.
  a->poisonHistory();
  view.timeSeconds += 1.0 / 30.0;
  const test::CloudFrame out = a->render(view, upsampled, kExtent);
  ASSERT_TRUE(a->context().lastFrameReport().historyUsed);
  ASSERT_TRUE(allValid(out));
  EXPECT_NEAR(meanOpacity(out), meanOpacity(withUpsampling), 0.5 * meanOpacity(withUpsampling));
}

TEST_F(CloudTemporal, NanInTheOutputHistoryOfAConvergedViewNeverReachesTheOutput) {
  // Converged: most output pixels come from their own samples in the output history, not
  // from the trace; poisoned, they must fall back to the trace.
  const CloudView view = aboveTheLayerView();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  auto r = renderer();
  const test::CloudFrame converged = r->render(view, high, kExtent, 80);
  r->poisonHistory();
  const test::CloudFrame out = r->render(view, high, kExtent);
  ASSERT_TRUE(r->context().lastFrameReport().historyUsed);
  ASSERT_TRUE(allValid(out));
  EXPECT_NEAR(meanOpacity(out), meanOpacity(converged), 0.25 * meanOpacity(converged));
}

TEST_F(CloudTemporal, TheFrameAfterAnOutputOnlyResizeEqualsAFreshRenderers) {
  // 160 and 159 pixels wide trace the same 80 columns: only the output history must go.
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  const VkExtent2D narrower{159, 90};
  auto r = renderer();
  r->render(aboveTheLayerView(), high, kExtent, 40);
  const test::CloudFrame resized = r->render(aboveTheLayerView(), high, narrower);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "resize");
  EXPECT_EQ(r->context().lastFrameReport().traceExtent.width, 80u);
  EXPECT_EQ(maxAbsDifference(resized, renderer()->render(aboveTheLayerView(), high, narrower)),
            0.0f);
}

TEST_F(CloudTemporal, TheFrameAfterACutEqualsAFreshRenderers) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  CloudView before = cumulusView();
  CloudView after = cumulusView();
  after.yawDegrees += 4.0;  // a small change: only the cut flag tells the module to reset
  after.position.x += 50.0;
  auto r = renderer();
  r->render(before, high, kExtent, 6);
  r->cut();
  const test::CloudFrame cut = r->render(after, high, kExtent);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "camera cut");
  const test::CloudFrame fresh = renderer()->render(after, high, kExtent);
  EXPECT_EQ(maxAbsDifference(cut, fresh), 0.0f);
  // Without the cut the same frame reprojects, and differs.
  auto continued = renderer();
  continued->render(before, high, kExtent, 6);
  EXPECT_GT(maxAbsDifference(continued->render(after, high, kExtent), fresh), 0.0f);
}

TEST_F(CloudTemporal, TheFrameAfterAResizeEqualsAFreshRenderers) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  const VkExtent2D smaller{128, 72};
  auto r = renderer();
  r->render(cumulusView(), high, kExtent, 5);
  const test::CloudFrame resized = r->render(cumulusView(), high, smaller);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "resize");
  EXPECT_EQ(maxAbsDifference(resized, renderer()->render(cumulusView(), high, smaller)), 0.0f);
}

TEST_F(CloudTemporal, RelightingDropsTheHistory) {
  // A sun that jumps, or a lightning flash, must not leave last frame's lighting behind.
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  CloudView moved = cumulusView();
  moved.sunAzimuthDegrees += 20.0;
  CloudView flash = cumulusView();
  flash.sunIlluminance *= 4.0f;
  for (const CloudView& relit : {moved, flash}) {
    auto r = renderer();
    r->render(cumulusView(), high, kExtent, 6);
    const test::CloudFrame frame = r->render(relit, high, kExtent);
    EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "relighting");
    EXPECT_EQ(maxAbsDifference(frame, renderer()->render(relit, high, kExtent)), 0.0f);
  }
}

TEST_F(CloudTemporal, NanInTheHistoryNeverReachesTheOutput) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  CloudView view = cumulusView();
  auto r = renderer();
  r->render(view, high, kExtent, 6);
  const double opacity = meanOpacity(r->render(view, high, kExtent));
  for (int frame = 0; frame < 4; ++frame) {
    r->poisonHistory();
    view.yawDegrees += 0.5;  // moving, so history is fetched from between pixels too
    const test::CloudFrame out = r->render(view, high, kExtent);
    ASSERT_TRUE(r->context().lastFrameReport().historyUsed);
    ASSERT_TRUE(allValid(out)) << "frame " << frame;
    EXPECT_NEAR(meanOpacity(out), opacity, 0.5 * opacity) << "rebuilt from fresh samples";
  }
}

TEST_F(CloudTemporal, InsideTheLayerReprojectionIsOffButFramesStayComplete) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  CloudView view = cumulusView();
  view.position.y = 2400.0;
  view.pitchDegrees = 0.0;
  auto r = renderer();
  for (int frame = 0; frame < 6; ++frame) {
    view.position.z -= 40.0;  // flying forward through the layer
    const test::CloudFrame out = r->render(view, high, kExtent);
    const clouds::FrameReport report = r->context().lastFrameReport();
    EXPECT_TRUE(report.insideLayer);
    EXPECT_FALSE(report.historyUsed);
    EXPECT_EQ(report.tileSize, 2u) << "every frame rebuilt from 1 in 4 fresh pixels";
    ASSERT_TRUE(allValid(out));
  }
}

TEST_F(CloudTemporal, GpuWeatherMaximaMatchTheCpu) {
  auto r = renderer();
  r->render(cumulusView(), clouds::Settings{}, kExtent);
  const std::vector<std::uint8_t> weather = r->readWeatherMap();
  const std::vector<std::uint8_t> expected = test::weatherMaxima(
      weather, clouds::shader::kWeatherMapSize, clouds::shader::kWeatherMaxFineSize);
  EXPECT_EQ(r->readWeatherMaxFine(), expected);
  // The maxima must be able to say "empty": this map has cells without any coverage.
  int emptyCells = 0;
  for (std::size_t i = 0; i < expected.size(); i += 4) emptyCells += expected[i] == 0 ? 1 : 0;
  EXPECT_GT(emptyCells, 0);
}

TEST_F(CloudTemporal, AWeatherMapPreparedOverFramesEqualsOneGeneratedAtOnce) {
  // 30 frames per one-second weather period: the next period's map is generated a band of
  // rows per frame; at t = 1 s it is swapped in. A fresh renderer generates it at once.
  clouds::Settings settings;
  settings.weatherUpdateSeconds = 1.0f;
  settings.weatherEvolutionPerSecond = 0.01f;  // fast enough that periods differ visibly
  CloudView view = cumulusView();
  auto running = renderer();
  const std::vector<std::uint8_t> first = [&] {
    view.timeSeconds = 0.0;
    running->render(view, settings, kExtent);
    return running->readWeatherMap();
  }();
  for (int frame = 1; frame <= 31; ++frame) {
    view.timeSeconds = frame / 30.0;
    running->render(view, settings, kExtent);
    if (frame < 30) {
      // Still period 0 while period 1 is being prepared in the other map.
      ASSERT_EQ(running->readWeatherMap(), first) << "frame " << frame;
    }
  }
  auto fresh = renderer();
  fresh->render(view, settings, kExtent);
  const std::vector<std::uint8_t> prepared = running->readWeatherMap();
  EXPECT_NE(prepared, first);
  EXPECT_EQ(prepared, fresh->readWeatherMap());
  EXPECT_EQ(running->readWeatherMaxFine(), fresh->readWeatherMaxFine());
}

TEST_F(CloudTemporal, EmptySpaceSkippingChangesTheCostNotThePicture) {
  // Coverage 0.4: broken cumulus; 0.3: a few clouds in a mostly clear sky.
  for (float coverage : {0.4f, 0.3f}) {
    clouds::Settings on = test::singleFrame({});
    on.coverage = coverage;
    on.jitter = clouds::Jitter::None;
    on.maxViewSteps = 4096;    // every ray reaches its end either way: the same clouds in reach
    on.cheapSampling = false;  // coarse steps would miss different small clouds either way
    clouds::Settings off = on;
    off.emptySpaceSkipping = false;
    CloudView view = cumulusView();
    view.pitchDegrees = 6.0;
    auto r = renderer();
    const test::CloudFrame skipped = r->render(view, on, kExtent);
    const clouds::WorkCounters with = r->lastWorkCounters();
    r->cut();
    const test::CloudFrame marched = r->render(view, off, kExtent);
    const clouds::WorkCounters without = r->lastWorkCounters();
    SCOPED_TRACE(coverage);
    ASSERT_GT(meanOpacity(marched), 0.002) << "the view must show clouds";
    EXPECT_GT(with.skippedCells, 0u);
    EXPECT_EQ(without.skippedCells, 0u);
    // Samples restart at cell boundaries, so they move a little: equal up to that.
    EXPECT_GE(test::psnr(skipped.radiance, marched.radiance, 1.0), 40.0);
    // The fewer cells hold cloud, the more is skipped. A cell is empty only where its
    // coverage is zero everywhere (the noise inside is not known), so broken skies, where
    // most 780 m cells hold some coverage, save less than clear ones (measured: 0.85 and
    // 0.68 of the samples; a sky with no coverage at all is not marched, see the next test).
    const double fraction = double(with.viewSamples) / double(without.viewSamples);
    EXPECT_LT(fraction, coverage > 0.35f ? 0.9 : 0.75);
  }
}

TEST_F(CloudTemporal, ClearSkyCostsLessThanATenthOfOvercast) {
  clouds::Settings clear = clouds::settingsFor(clouds::Quality::High);
  clear.coverage = 0.0f;
  clouds::Settings overcast = clear;
  overcast.coverage = 1.0f;
  overcast.cloudType = 0.1f;  // a stratus deck
  auto r = renderer();
  const test::CloudFrame empty = r->render(cumulusView(), clear, kExtent, 3);
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

TEST_F(CloudTemporal, EachPresetCostsMoreThanTheOneBelowIt) {
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

TEST_F(CloudTemporal, PassTimingsAccountForTheFrame) {
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
  // The passes are the frame: together at most the whole dispatch, and most of it.
  EXPECT_LE(sum, r->lastGpuMilliseconds() * 1.02 + 0.05);
  EXPECT_GE(sum, r->lastGpuMilliseconds() * 0.5);
}

}  // namespace
