// Temporal reconstruction on lavapipe: a static camera converges to the Reference, and with
// temporal upsampling to detail finer than the trace, its few own samples blended with the
// trace where the trace agrees; the frame after a cut, a resize or relighting equals a fresh
// renderer's; NaN in the history never reaches the output; a camera held or moving inside the
// layer keeps its history; a turning camera's history stays sharp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "cloud_gpu_fixture.h"
#include "cpu_reference.h"

namespace {
using clouds::tools::CloudView;
using test::allValid;
using test::cumulusView;
using test::kExtent;
using test::maxAbsDifference;
using test::meanOpacity;
using CloudTemporal = test::CloudGpuTest;

TEST_F(CloudTemporal, AStaticCameraConvergesToTheReference) {
  const CloudView view = cumulusView();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  auto r = renderer();
  std::vector<glm::vec3> previous;
  double lateChange = 0.0;  // largest frame-to-frame mean change over the last 16 frames
  for (int frame = 0; frame < 48; ++frame) {
    const std::vector<glm::vec3> image =
        clouds::tools::tonemappedPixels(r->render(view, high, kExtent), view);
    if (!previous.empty() && frame >= 32) {
      lateChange = std::max(lateChange, clouds::tools::imageError(image, previous).meanAbs);
    }
    EXPECT_EQ(r->context().lastFrameReport().historyUsed, frame > 0) << "frame " << frame;
    previous = image;
  }
  // Every pixel has been refreshed three times over; what still changes is the new jitter
  // of the refreshed 1-in-16 pixels, blended with their history.
  EXPECT_LT(lateChange, 2.0 / 255.0);

  // The converged Reference: 16 frames whose rays move inside their pixels, averaged.
  const clouds::tools::CloudFrame reference = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference), kExtent, 16);
  ASSERT_GT(meanOpacity(reference), 0.05) << "the view must show clouds";
  const engine::assets::ImageError error =
      clouds::tools::imageError(previous, clouds::tools::tonemappedPixels(reference, view));
  EXPECT_GE(error.psnr(), 35.0) << "mean abs " << error.meanAbs << ", max abs " << error.maxAbs;
}

// Above the layer, looking down: distant cloud tops are detail finer than High's
// half-resolution trace.
CloudView aboveTheLayerView() {
  CloudView view = cumulusView();
  view.position.y = 6500.0;
  view.pitchDegrees = -25.0;
  return view;
}

// High without the noise's level of detail: at 160 x 90 a pixel is 4 times as wide as at the
// benchmark's 640 x 360, so the coarser noise levels start 4 times nearer, at the distance of
// these cloud tops, and take away part of the detail whose recovery these tests measure (the
// level of detail's own accuracy is the benchmark's to measure, at 640 x 360).
clouds::Settings highWithFinestNoise() {
  clouds::Settings s = clouds::settingsFor(clouds::Quality::High);
  s.noiseLevelOfDetail = false;
  return s;
}

TEST_F(CloudTemporal, TemporalUpsamplingConvergesToDetailFinerThanTheTrace) {
  const CloudView view = aboveTheLayerView();
  const clouds::Settings upsampled = highWithFinestNoise();
  ASSERT_TRUE(clouds::upsamplesTemporally(upsampled));
  clouds::Settings traceOnly = upsampled;
  traceOnly.temporalUpsampling = false;
  const std::vector<glm::vec3> reference = clouds::tools::tonemappedPixels(
      renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                 16),
      view);
  // A trace pixel is refreshed once per 16 frames and covers 2 x 2 output pixels: after 128
  // frames every output pixel holds two rays of its own.
  auto r = renderer();
  std::vector<glm::vec3> image;
  double lateChange = 0.0;
  for (int frame = 0; frame < 136; ++frame) {
    std::vector<glm::vec3> next =
        clouds::tools::tonemappedPixels(r->render(view, upsampled, kExtent), view);
    if (frame >= 128)
      lateChange = std::max(lateChange, clouds::tools::imageError(next, image).meanAbs);
    image = std::move(next);
  }
  EXPECT_LT(lateChange, 2.0 / 255.0) << "converged: little changes from frame to frame";
  const double upsampledPsnr = clouds::tools::imageError(image, reference).psnr();
  const double traceOnlyPsnr =
      clouds::tools::imageError(
          clouds::tools::tonemappedPixels(renderer()->render(view, traceOnly, kExtent, 136), view),
          reference)
          .psnr();
  // At 160 x 90 the cloud tops are smaller in pixels than at the benchmark's 640 x 360 (where
  // High's 35 dB target is measured). Measured here 22.1 dB with the trace alone, 27.7 dB
  // upsampled, since the multiple-scattering retune (2026-11) lit the tops with most of the sun
  // (their shading has twice the contrast it had, and detail is harder to match); before it,
  // 24.9 and 31.8 dB. The gain over the trace is the property; the floor guards a collapse.
  EXPECT_GE(upsampledPsnr, 26.0) << "trace only: " << traceOnlyPsnr << " dB";
  EXPECT_GE(upsampledPsnr, traceOnlyPsnr + 5.0) << "trace only: " << traceOnlyPsnr << " dB";
}

// Two own samples are a noisy point sample of their pixel: where the trace pixels around agree
// on the cover, the spatial estimate is blended in (a third of it for two samples), and on a
// silhouette it is not. With upsamplingMaxSamples at 2 the two samples are a settled running
// mean, trusted alone everywhere: the blend's gain shows against it.
TEST_F(CloudTemporal, FewOwnSamplesAreBlendedWithTheTraceWhereItAgrees) {
  // Without edge rays, which give silhouettes four own samples in the 128 frames: the blend's
  // gain is measured where every pixel has two.
  clouds::Settings high = highWithFinestNoise();
  high.edgeRays = 0;
  clouds::Settings ownAlone = high;
  ownAlone.upsamplingMaxSamples = 2;
  // PSNR of each setting against 16 Reference frames after 128 frames (two own samples per
  // output pixel): {the blend, own samples alone}.
  const auto psnrAfter128Frames = [&](const CloudView& view) {
    const std::vector<glm::vec3> reference = clouds::tools::tonemappedPixels(
        renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                   16),
        view);
    const auto psnr = [&](const clouds::Settings& settings) {
      const clouds::tools::CloudFrame frame = renderer()->render(view, settings, kExtent, 129);
      return clouds::tools::imageError(clouds::tools::tonemappedPixels(frame, view), reference)
          .psnr();
    };
    return std::pair{psnr(high), psnr(ownAlone)};
  };
  // Measured: cumulus from below 45.42 dB against 44.86 alone; above the layer 29.21 against
  // 27.97. With the blend everywhere, silhouettes too: 45.03 and 27.95 (above the layer no
  // better than alone: its far rims are most of its error).
  const auto [belowBlended, belowAlone] = psnrAfter128Frames(cumulusView());
  EXPECT_GE(belowBlended, belowAlone + 0.35);
  const auto [aboveBlended, aboveAlone] = psnrAfter128Frames(aboveTheLayerView());
  EXPECT_GE(aboveBlended, aboveAlone + 0.6);
}

// Edge rays: a tile whose trace pixels around ranged from cloud to clear last frame marches two
// more rays, through other output pixels of its trace pixel, so that output pixels on
// silhouettes gather own samples three times as fast. Above the layer the far rims are most of the
// error: High gains there against High without them, and only the silhouettes' tiles march
// them.
TEST_F(CloudTemporal, EdgeRaysGatherOwnSamplesOnSilhouettes) {
  const CloudView view = aboveTheLayerView();
  const clouds::Settings high = highWithFinestNoise();
  ASSERT_EQ(high.edgeRays, 2u) << "High marches two edge rays per edge tile";
  clouds::Settings without = high;
  without.edgeRays = 0;
  const std::vector<glm::vec3> reference = clouds::tools::tonemappedPixels(
      renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                 16),
      view);
  clouds::WorkCounters work;
  const auto psnr = [&](const clouds::Settings& settings) {
    auto r = renderer();
    const clouds::tools::CloudFrame frame = r->render(view, settings, kExtent, 129);
    work = r->lastWorkCounters();
    return clouds::tools::imageError(clouds::tools::tonemappedPixels(frame, view), reference)
        .psnr();
  };
  const double withoutPsnr = psnr(without);
  EXPECT_EQ(work.edgeRays, 0u);
  const double withPsnr = psnr(high);
  std::printf("above the layer: %.2f dB with edge rays (%llu of %llu rays), %.2f without\n",
              withPsnr, static_cast<unsigned long long>(work.edgeRays),
              static_cast<unsigned long long>(work.tracedPixels), withoutPsnr);
  // 1 in 16 trace pixels marches a ray each frame; some of those an edge ray as well.
  const std::uint64_t tiles = work.tracedPixels - work.edgeRays;
  EXPECT_GT(work.edgeRays, tiles / 50) << tiles << " tiles";
  EXPECT_LT(work.edgeRays, tiles / 2) << tiles << " tiles";
  // Measured: 31.9 dB against 29.2 without (56 edge rays beside 240 tiles' rays); no gain with
  // the edge rays marched but not taken by the upsample.
  EXPECT_GE(withPsnr, withoutPsnr + 1.5) << "without: " << withoutPsnr << " dB";
}

TEST_F(CloudTemporal, TemporalUpsamplingHelpsUnderWindDriftToo) {
  // Time runs (the wind drifts the clouds' detail, 10 m/s): every frame reprojects and
  // resamples the output history instead of reading it in place.
  CloudView view = aboveTheLayerView();
  const clouds::Settings upsampled = highWithFinestNoise();
  clouds::Settings traceOnly = upsampled;
  traceOnly.temporalUpsampling = false;
  constexpr int kFrames = 136;
  auto a = renderer();
  auto b = renderer();
  clouds::tools::CloudFrame withUpsampling, withoutUpsampling;
  for (int frame = 0; frame < kFrames; ++frame) {
    view.timeSeconds = 5.0 + frame / 30.0;
    withUpsampling = a->render(view, upsampled, kExtent);
    withoutUpsampling = b->render(view, traceOnly, kExtent);
    ASSERT_FALSE(frame > 0 && std::string(a->context().lastFrameReport().resetReason) != "")
        << "frame " << frame << ": " << a->context().lastFrameReport().resetReason;
  }
  const std::vector<glm::vec3> reference = clouds::tools::tonemappedPixels(
      renderer()->renderAveraged(view, clouds::settingsFor(clouds::Quality::Reference), kExtent,
                                 16),
      view);
  const double upsampledPsnr =
      clouds::tools::imageError(clouds::tools::tonemappedPixels(withUpsampling, view), reference)
          .psnr();
  const double traceOnlyPsnr =
      clouds::tools::imageError(clouds::tools::tonemappedPixels(withoutUpsampling, view), reference)
          .psnr();
  // Less than in a still view (the detail the own samples hold scrolls with the wind, so they
  // are clamped to this frame's trace neighbourhood), but still well above the trace alone:
  // measured 29.2 dB against 24.9 (still: 31.8).
  EXPECT_GE(upsampledPsnr, traceOnlyPsnr + 3.0) << "trace only: " << traceOnlyPsnr << " dB";
  ASSERT_TRUE(allValid(withUpsampling));
  // Poisoned now (trace and output history), the reprojected path must catch it as well; the
  // frame is rebuilt from its 1-in-16 fresh samples, as in the trace history's NaN test.
  a->poisonHistory();
  view.timeSeconds += 1.0 / 30.0;
  const clouds::tools::CloudFrame out = a->render(view, upsampled, kExtent);
  ASSERT_TRUE(a->context().lastFrameReport().historyUsed);
  ASSERT_TRUE(allValid(out));
  EXPECT_NEAR(meanOpacity(out), meanOpacity(withUpsampling), 0.5 * meanOpacity(withUpsampling));
}

// Near clouds keep their detail: a cumulus a few hundred metres overhead (the benchmark's
// "near cumulus" view), converged at High, against the Reference; the blur of a reduced trace
// (a quarter-resolution one, as Low and Medium trace) is what it must not show.
TEST_F(CloudTemporal, ACloudAFewHundredMetresAwayKeepsItsDetail) {
  CloudView view = cumulusView();
  view.position.y = 1200.0;  // 300 m below the base
  view.pitchDegrees = 40.0;
  view.yawDegrees = 90.0;
  clouds::Settings look;
  look.coverage = 0.6f;
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High, look);
  clouds::Settings quarterTrace = high;
  quarterTrace.traceScale = 0.25f;
  const clouds::tools::CloudFrame referenceFrame = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference, look), kExtent, 16);
  ASSERT_GT(meanOpacity(referenceFrame), 0.2) << "the view must be full of near cloud";
  const std::vector<glm::vec3> reference = clouds::tools::tonemappedPixels(referenceFrame, view);
  const auto psnrAfter48Frames = [&](const clouds::Settings& s) {
    return clouds::tools::imageError(
               clouds::tools::tonemappedPixels(renderer()->render(view, s, kExtent, 48), view),
               reference)
        .psnr();
  };
  const double highPsnr = psnrAfter48Frames(high);
  const double quarterPsnr = psnrAfter48Frames(quarterTrace);
  std::printf("near cumulus: High %.1f dB, its trace at a quarter of the resolution %.1f dB\n",
              highPsnr, quarterPsnr);
  EXPECT_GE(highPsnr, 38.0);
  EXPECT_GE(highPsnr, quarterPsnr + 4.0);
}

TEST_F(CloudTemporal, NanInTheOutputHistoryOfAConvergedViewNeverReachesTheOutput) {
  // Converged: most output pixels come from their own samples in the output history, not
  // from the trace; poisoned, they must fall back to the trace.
  const CloudView view = aboveTheLayerView();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  auto r = renderer();
  const clouds::tools::CloudFrame converged = r->render(view, high, kExtent, 80);
  r->poisonHistory();
  const clouds::tools::CloudFrame out = r->render(view, high, kExtent);
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
  const clouds::tools::CloudFrame resized = r->render(aboveTheLayerView(), high, narrower);
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
  const clouds::tools::CloudFrame cut = r->render(after, high, kExtent);
  EXPECT_EQ(std::string(r->context().lastFrameReport().resetReason), "camera cut");
  const clouds::tools::CloudFrame fresh = renderer()->render(after, high, kExtent);
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
  const clouds::tools::CloudFrame resized = r->render(cumulusView(), high, smaller);
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
    const clouds::tools::CloudFrame frame = r->render(relit, high, kExtent);
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
    const clouds::tools::CloudFrame out = r->render(view, high, kExtent);
    ASSERT_TRUE(r->context().lastFrameReport().historyUsed);
    ASSERT_TRUE(allValid(out)) << "frame " << frame;
    EXPECT_NEAR(meanOpacity(out), opacity, 0.5 * opacity) << "rebuilt from fresh samples";
  }
}

// The PSNR (dB) of a frame against the converged Reference of its view.
double psnrAgainst(const clouds::tools::CloudFrame& frame,
                   const clouds::tools::CloudFrame& reference, const CloudView& view) {
  return clouds::tools::imageError(clouds::tools::tonemappedPixels(frame, view),
                                   clouds::tools::tonemappedPixels(reference, view))
      .psnr();
}

// Inside the layer, looking a little down.
CloudView insideTheLayerView() {
  CloudView view = cumulusView();
  view.position.y = 2400.0;
  view.pitchDegrees = -10.0;
  return view;
}

TEST_F(CloudTemporal, ACameraHeldInsideTheLayerKeepsItsHistory) {
  // A turn reprojects without depths, and the wind's drift is slow.
  const CloudView view = insideTheLayerView();
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  auto r = renderer();
  clouds::tools::CloudFrame first;
  clouds::tools::CloudFrame frame;
  for (int i = 0; i < 48; ++i) {
    frame = r->render(view, high, kExtent);
    if (i == 0) first = frame;
    ASSERT_EQ(r->context().lastFrameReport().historyUsed, i > 0) << "frame " << i;
    ASSERT_TRUE(r->context().lastFrameReport().insideLayer);
  }
  const clouds::tools::CloudFrame reference = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference), kExtent, 16);
  const double held = psnrAgainst(frame, reference, view);
  const double alone = psnrAgainst(first, reference, view);
  std::printf("held inside the layer: %.1f dB after 48 frames, %.1f dB the first\n", held, alone);
  EXPECT_GT(held, alone + 0.5) << "the history is used, and helps";
}

// Flying through the layer (150 m/s at 30 fps), the history is reprojected (clamped to the
// fresh samples around each pixel as far as the parallax makes it uncertain) and 1 in 4 trace
// pixels is refreshed each frame: more accurate than rebuilding every frame from those rays
// alone (what reprojection off gives: the tent of reconstruct.comp).
TEST_F(CloudTemporal, MovingInsideTheLayerTheHistoryIsReprojected) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  clouds::Settings rebuilt = high;
  rebuilt.temporalReuse = false;
  CloudView view = insideTheLayerView();
  auto reprojecting = renderer();
  auto rebuilding = renderer();
  clouds::tools::CloudFrame withHistory, withoutHistory;
  for (int frame = 0; frame < 24; ++frame) {
    view.position.z -= 5.0;
    withHistory = reprojecting->render(view, high, kExtent);
    const clouds::FrameReport report = reprojecting->context().lastFrameReport();
    ASSERT_TRUE(report.insideLayer);
    ASSERT_EQ(report.historyUsed, frame > 0) << "frame " << frame << ": " << report.resetReason;
    ASSERT_EQ(report.tileSize, 2u) << "frame " << frame << ": 1 in 4 fresh, not 1 in 16";
    ASSERT_TRUE(allValid(withHistory)) << "frame " << frame;
    withoutHistory = rebuilding->render(view, rebuilt, kExtent);
  }
  const clouds::tools::CloudFrame reference = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference), kExtent, 16);
  const double reprojected = psnrAgainst(withHistory, reference, view);
  const double alone = psnrAgainst(withoutHistory, reference, view);
  std::printf("moving inside the layer: %.1f dB reprojected, %.1f dB rebuilt each frame\n",
              reprojected, alone);
  EXPECT_GT(reprojected, alone + 2.0);
}

// The near field (High: Settings::nearFieldMetres 200) flying through the layer: every pixel
// of the near field's image (half the trace's resolution) marches the first 200 m of its ray
// each frame and the tiles march the rest, laid over it. Against the same flight with one
// march, the clouds cover as much of the screen (the near part is laid over the far one: left
// out, the cloud within 200 m goes missing), and the frames are as accurate or more. Measured:
// through dense layer (coverage 0.7) 42.9 dB against 41.6 (42.6 without the resolve's history,
// each frame's near field alone; 39.6 with the near field marched but not laid over); through
// sparse layer (0.5), next to no cloud within 200 m, 33.9 against 33.9 (33.2 with the far part
// starting at the split with a coarse step). Since the wind carries the noise downwind (it used
// to carry it upwind, against the reprojection) other clouds stand along the flight: 51.2
// against 50.0 dense, 33.7 against 34.2 sparse, so "as accurate" is held to 0.5 dB there. The
// march is pinned to High's when this was
// measured (60 m steps growing 0.2% of the distance, 96 of them): with the ladder's finer High
// (35 m, 0.15%, 168) one march is more accurate and the near field gains 0.96 dB (42.66
// against 41.70).
TEST_F(CloudTemporal, FlyingThroughTheLayerTheNearFieldIsMarchedApart) {
  struct Flight {
    double splitPsnr, wholePsnr, splitCover, wholeCover;
  };
  const auto fly = [&](float coverage) {
    clouds::Settings look;
    look.coverage = coverage;
    clouds::Settings high = clouds::settingsFor(clouds::Quality::High, look);
    EXPECT_EQ(high.nearFieldMetres, 200.0f) << "High splits at Nubis³'s 200 m";
    high.viewStepMetres = 60.0f;
    high.viewStepGrowth = 0.002f;
    high.maxViewSteps = 96;
    clouds::Settings oneMarch = high;
    oneMarch.nearFieldMetres = 0.0f;
    CloudView view = insideTheLayerView();
    auto split = renderer();
    auto whole = renderer();
    clouds::tools::CloudFrame withNearField, withoutNearField;
    for (int frame = 0; frame < 24; ++frame) {
      view.position.z -= 5.0;
      withNearField = split->render(view, high, kExtent);
      const clouds::FrameReport report = split->context().lastFrameReport();
      EXPECT_TRUE(report.nearField) << "frame " << frame;
      EXPECT_EQ(report.historyUsed, frame > 0) << "frame " << frame << ": " << report.resetReason;
      const std::uint64_t nearPixels =
          std::uint64_t(report.traceExtent.width + 1) / 2 * ((report.traceExtent.height + 1) / 2);
      EXPECT_EQ(split->lastWorkCounters().nearFieldRays, nearPixels)
          << "every pixel at half the trace's, every frame";
      EXPECT_TRUE(allValid(withNearField)) << "frame " << frame;
      withoutNearField = whole->render(view, oneMarch, kExtent);
      EXPECT_FALSE(whole->context().lastFrameReport().nearField);
      EXPECT_EQ(whole->lastWorkCounters().nearFieldRays, 0u);
    }
    const clouds::tools::CloudFrame reference = renderer()->renderAveraged(
        view, clouds::settingsFor(clouds::Quality::Reference, look), kExtent, 16);
    const Flight flight{psnrAgainst(withNearField, reference, view),
                        psnrAgainst(withoutNearField, reference, view), meanOpacity(withNearField),
                        meanOpacity(withoutNearField)};
    std::printf(
        "flying through the layer at coverage %.1f: %.2f dB with the near field, %.2f with one "
        "march; cover %.3f against %.3f\n",
        coverage, flight.splitPsnr, flight.wholePsnr, flight.splitCover, flight.wholeCover);
    EXPECT_NEAR(flight.splitCover, flight.wholeCover, 0.05 * flight.wholeCover);
    return flight;
  };
  const Flight dense = fly(0.7f);
  EXPECT_GT(dense.splitPsnr, dense.wholePsnr + 1.0);
  const Flight sparse = fly(0.5f);
  EXPECT_GT(sparse.splitPsnr, sparse.wholePsnr - 0.5);
}

// A turning camera (0.13 degrees a frame, a sixth of a trace pixel at 160x90) reads its history
// a fraction of a pixel off at every frame, up to 16 times between refreshes: it loses some
// accuracy against a camera held still (whose history averages more rays), but resampled
// bilinearly it also blurred. Measured: 4.7 dB below the held camera with Catmull-Rom
// (catmullRomWeights), 5.3 dB with bilinear weights; 5.2 with Catmull-Rom since the wind carries
// the noise downwind, the way the history is reprojected (other clouds in view, 37.2 against a
// held camera's 42.4), so the bound is 5.5 dB. Without edge rays, which sharpen the
// held camera's silhouettes more than the turning one's (their own samples are resampled with
// the history): this measures the history's resampling.
TEST_F(CloudTemporal, ATurningCameraKeepsItsHistorySharp) {
  clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  high.edgeRays = 0;
  CloudView view = cumulusView();
  auto turning = renderer();
  clouds::tools::CloudFrame turned;
  for (int frame = 0; frame < 64; ++frame) {
    view.yawDegrees += 0.13;
    turned = turning->render(view, high, kExtent);
    ASSERT_EQ(turning->context().lastFrameReport().historyUsed, frame > 0);
  }
  auto held = renderer();
  clouds::tools::CloudFrame still;
  for (int frame = 0; frame < 64; ++frame) still = held->render(view, high, kExtent);
  const clouds::tools::CloudFrame reference = renderer()->renderAveraged(
      view, clouds::settingsFor(clouds::Quality::Reference), kExtent, 16);
  const double turnedPsnr = psnrAgainst(turned, reference, view);
  const double stillPsnr = psnrAgainst(still, reference, view);
  std::printf("turning: %.2f dB, held still: %.2f dB\n", turnedPsnr, stillPsnr);
  EXPECT_GT(turnedPsnr, stillPsnr - 5.5);
}

}  // namespace
