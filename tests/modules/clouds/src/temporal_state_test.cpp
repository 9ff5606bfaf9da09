// The temporal reconstruction's per-frame decisions, without a GPU: when last frame's result
// may be reprojected and why not, the refresh order inside a tile, the history ping-pong.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "temporal_state.h"
#include "uniforms.h"

namespace {

using clouds::detail::TemporalFrame;
using clouds::detail::TemporalState;
using clouds::detail::tilePhase;

constexpr VkExtent2D kTrace{80, 45};

clouds::FrameInputs groundCamera() {
  clouds::FrameInputs in;
  in.cameraPosition = {0.0, 1200.0, 0.0};  // below the layer (1500 m) and its margin (50 m)
  in.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.2f, -1.0f), glm::vec3(0, 1, 0));
  in.sunDirection = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
  in.sunIlluminance = glm::vec3(10.0f);
  return in;
}

// The ground camera with a projection, for building a frame's uniforms.
clouds::FrameInputs projectedGroundCamera() {
  clouds::FrameInputs in = groundCamera();
  in.projection = glm::perspective(1.0f, 16.0f / 9.0f, 0.5f, 1000.0f);
  return in;
}

// A frame at 160 x 90 with a half-resolution trace refreshed 1 in 16 that keeps its output
// history (temporal upsampling accumulates).
clouds::detail::UniformContext upsamplingFrame() {
  clouds::detail::UniformContext context;
  context.traceExtent = {80, 45};
  context.fullExtent = {160, 90};
  context.temporal.tileSize = 4;
  context.temporal.useOutputHistory = true;
  return context;
}

// Runs `frames` identical frames and returns the plan of the last.
TemporalFrame run(TemporalState& state, const clouds::FrameInputs& in, const clouds::Settings& s,
                  int frames = 1, VkExtent2D trace = kTrace) {
  TemporalFrame frame;
  for (int i = 0; i < frames; ++i) {
    frame = state.plan(in, s, trace);
    state.commit(frame, in, s, trace);
  }
  return frame;
}

TEST(TemporalState, FirstFrameHasNoHistoryThenAStaticCameraReprojects) {
  TemporalState state;
  const clouds::Settings s;  // updateInterval 16: 4 x 4 tiles
  const TemporalFrame first = run(state, groundCamera(), s);
  EXPECT_FALSE(first.useHistory);
  EXPECT_EQ(std::string(first.resetReason), "first frame");
  EXPECT_EQ(first.temporalIndex, 0u);
  EXPECT_EQ(first.tileSize, 2u) << "without history a frame marches at most 2 x 2 tiles";
  const TemporalFrame second = run(state, groundCamera(), s);
  EXPECT_TRUE(second.useHistory);
  EXPECT_EQ(std::string(second.resetReason), "");
  EXPECT_EQ(second.tileSize, 4u);
  EXPECT_EQ(second.temporalIndex, 1u);
  EXPECT_EQ(second.readHistory, first.writeHistory) << "reads what the last frame wrote";
  EXPECT_TRUE(second.still);
  EXPECT_EQ(second.writeHistory, second.readHistory) << "nothing moved: updated in place";
  clouds::FrameInputs moved = groundCamera();
  moved.cameraPosition.x += 1.0;
  const TemporalFrame third = run(state, moved, s);
  EXPECT_FALSE(third.still);
  EXPECT_EQ(third.readHistory, second.writeHistory);
  EXPECT_NE(third.writeHistory, third.readHistory) << "reprojected into the other image";
}

TEST(TemporalState, TilePhasesVisitEveryPixelOfTheTileInBayerOrder) {
  for (std::uint32_t k : {1u, 2u, 4u, 8u}) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (std::uint32_t n = 0; n < k * k; ++n) {
      const glm::uvec2 p = tilePhase(k, n);
      ASSERT_LT(p.x, k);
      ASSERT_LT(p.y, k);
      seen.insert({p.x, p.y});
    }
    EXPECT_EQ(seen.size(), std::size_t{k} * k) << "k = " << k;
    EXPECT_EQ(tilePhase(k, k * k), tilePhase(k, 0)) << "the order repeats";
  }
  // Consecutive refreshes land far apart (Bayer), not on neighbours.
  const glm::ivec2 a(tilePhase(4, 0)), b(tilePhase(4, 1));
  EXPECT_GE(std::abs(a.x - b.x) + std::abs(a.y - b.y), 2);
  // The order is the classic Bayer matrix's: the first four of a 4 x 4 tile are its corners'
  // pattern, and the 8 x 8 order refines the 4 x 4 one.
  EXPECT_EQ(tilePhase(4, 1), glm::uvec2(2, 2));
  EXPECT_EQ(tilePhase(4, 2), glm::uvec2(2, 0));
  EXPECT_EQ(tilePhase(4, 4), glm::uvec2(1, 1));
  for (std::uint32_t n = 0; n < 16; ++n) EXPECT_EQ(tilePhase(8, n), tilePhase(4, n) * 2u);
  EXPECT_EQ(clouds::detail::tileSizeFor(64), 8u);
  EXPECT_EQ(clouds::detail::tileSizeFor(16), 4u);
  EXPECT_EQ(clouds::detail::tileSizeFor(1), 1u);
}

TEST(TemporalState, OutputHistoryIsReadOnlyAfterAFrameThatWroteIt) {
  clouds::Settings s = clouds::settingsFor(clouds::Quality::High);
  ASSERT_TRUE(clouds::upsamplesTemporally(s));
  TemporalState state;
  const TemporalFrame first = run(state, groundCamera(), s);
  EXPECT_TRUE(first.upsampleTemporally);
  EXPECT_FALSE(first.useOutputHistory) << "nothing written yet";
  EXPECT_TRUE(run(state, groundCamera(), s).useOutputHistory);
  // A frame without temporal upsampling writes no output history: the next one must not read.
  clouds::Settings off = s;
  off.temporalUpsampling = false;
  EXPECT_FALSE(run(state, groundCamera(), off).upsampleTemporally);
  const TemporalFrame back = run(state, groundCamera(), s);
  EXPECT_TRUE(back.useHistory) << "the trace history is still good";
  EXPECT_FALSE(back.useOutputHistory);
  EXPECT_TRUE(run(state, groundCamera(), s).useOutputHistory);
  // At full trace resolution there is nothing to upsample.
  clouds::Settings full = s;
  full.traceScale = 1.0f;
  EXPECT_FALSE(clouds::upsamplesTemporally(full));
}

TEST(TemporalState, UpsamplingRaysVisitEveryOutputPixelOfTheirTracePixelFirst) {
  // Half-resolution trace, 1-in-16 refresh: a trace pixel is refreshed once per 16-frame
  // round and covers 2 x 2 output pixels; its rays must hit each of them in the first four
  // rounds, whatever the frame inside the round.
  const clouds::Settings s = clouds::settingsFor(clouds::Quality::High);
  const clouds::FrameInputs in = projectedGroundCamera();
  clouds::detail::UniformContext context = upsamplingFrame();
  std::set<std::pair<int, int>> hit;
  for (std::uint32_t round = 0; round < 4; ++round) {
    context.temporal.temporalIndex = round * 16 + 5;
    const glm::vec2 offset =
        glm::vec2(clouds::detail::buildUniforms(in, s, context).subpixelOffset);
    ASSERT_LT(glm::max(std::abs(offset.x), std::abs(offset.y)), 0.5f) << "inside the pixel";
    const glm::ivec2 outputPixel(glm::floor((offset + 0.5f) * 2.0f));
    hit.insert({outputPixel.x, outputPixel.y});
    for (std::uint32_t frame : {1u, 11u, 16u}) {  // the frame after a reset is index 0
      context.temporal.temporalIndex = round * 16 + frame;
      EXPECT_EQ(glm::vec2(clouds::detail::buildUniforms(in, s, context).subpixelOffset), offset)
          << "one offset per round, frame " << frame;
    }
  }
  EXPECT_EQ(hit.size(), 4u);
  // A frame rebuilt without output history marches through pixel centres.
  context.temporal.useOutputHistory = false;
  EXPECT_EQ(glm::vec2(clouds::detail::buildUniforms(in, s, context).subpixelOffset),
            glm::vec2(0.0f));
}

// Edge rays go through the other output pixels of their trace pixel, and keep each output
// pixel's samples centred as the rays alone do: samples off centre on the whole shift the
// accumulated image (edge rays at the rays' points moved by thirds of a pixel put a pixel's
// mean sample 0.17 pixel off in y and cost 2.6 dB above the layer).
TEST(TemporalState, EdgeRaysHitOtherOutputPixelsAndKeepTheirSamplesCentred) {
  const clouds::Settings s = clouds::settingsFor(clouds::Quality::High);
  ASSERT_EQ(s.edgeRays, 2u);
  const clouds::FrameInputs in = projectedGroundCamera();
  clouds::detail::UniformContext context = upsamplingFrame();
  // Each output pixel's points (in the pixel, [0, 1)^2) over eight rounds: all rays, and the
  // rays alone.
  std::map<std::pair<int, int>, std::vector<glm::vec2>> all, rays;
  const auto add = [&](glm::vec2 offset, bool ray) {
    ASSERT_TRUE(glm::all(glm::greaterThanEqual(offset, glm::vec2(-0.5f))) &&
                glm::all(glm::lessThan(offset, glm::vec2(0.5f))))
        << "inside the trace pixel";
    const glm::vec2 output = (offset + 0.5f) * 2.0f;  // 2 x 2 output pixels per trace pixel
    const std::pair<int, int> pixel{int(std::floor(output.x)), int(std::floor(output.y))};
    all[pixel].push_back(glm::fract(output));
    if (ray) rays[pixel].push_back(glm::fract(output));
  };
  for (std::uint32_t round = 0; round < 8; ++round) {
    context.temporal.temporalIndex = round * 16 + 5;
    const clouds::shader::CloudUniforms u = clouds::detail::buildUniforms(in, s, context);
    ASSERT_NE(u.flags & clouds::shader::kFlagEdgeRays, 0u);
    ASSERT_EQ(u.edgeRaysPerTile, 2u);
    const glm::vec2 ray(u.subpixelOffset);
    const glm::vec2 first(u.edgeSubpixelOffsets.x, u.edgeSubpixelOffsets.y);
    const glm::vec2 second(u.edgeSubpixelOffsets.z, u.edgeSubpixelOffsets.w);
    add(ray, true);
    add(first, false);
    add(second, false);
    const auto pixelOf = [](glm::vec2 o) { return glm::ivec2(glm::floor((o + 0.5f) * 2.0f)); };
    EXPECT_NE(pixelOf(first), pixelOf(ray)) << "round " << round;
    EXPECT_NE(pixelOf(second), pixelOf(ray)) << "round " << round;
    EXPECT_NE(pixelOf(second), pixelOf(first)) << "round " << round;
  }
  ASSERT_EQ(all.size(), 4u);
  const auto mean = [](const std::vector<glm::vec2>& points) {
    glm::vec2 sum(0.0f);
    for (glm::vec2 p : points) sum += p;
    return sum / float(points.size());
  };
  for (const auto& [pixel, points] : all) {
    EXPECT_EQ(points.size(), 6u) << "two rays and four edge rays in eight rounds";
    const glm::vec2 offCentre = glm::abs(mean(points) - 0.5f);
    const glm::vec2 raysOffCentre = glm::abs(mean(rays.at(pixel)) - 0.5f);
    EXPECT_LE(offCentre.x, raysOffCentre.x + 0.01f) << pixel.first << ", " << pixel.second;
    EXPECT_LE(offCentre.y, raysOffCentre.y + 0.01f) << pixel.first << ", " << pixel.second;
  }
  // No output history to keep them: no edge rays.
  context.temporal.useOutputHistory = false;
  EXPECT_EQ(clouds::detail::buildUniforms(in, s, context).flags & clouds::shader::kFlagEdgeRays,
            0u);
}

TEST(TemporalState, InsideTheLayerTheHistoryIsKeptAndAMovingCameraRefreshesMore) {
  const clouds::Settings s;
  TemporalState state;
  clouds::FrameInputs inside = groundCamera();
  inside.cameraPosition.y = 2500.0;
  EXPECT_EQ(std::string(run(state, inside, s).resetReason), "first frame");
  const TemporalFrame held = run(state, inside, s);
  EXPECT_TRUE(held.useHistory) << held.resetReason;
  EXPECT_EQ(held.tileSize, 4u) << "1 in 16 again";
  clouds::FrameInputs turned = inside;  // a turn reprojects without depths
  turned.view = glm::rotate(inside.view, 0.05f, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_TRUE(run(state, turned, s).useHistory);
  clouds::FrameInputs moved = turned;
  moved.cameraPosition.z -= 20.0;
  const TemporalFrame flying = run(state, moved, s);
  EXPECT_TRUE(flying.useHistory) << flying.resetReason;
  EXPECT_EQ(flying.tileSize, 2u) << "the cloud all around changes: 1 in 4";
  clouds::FrameInputs below = moved;  // out of the layer (and its margin): 1 in 16 again
  below.cameraPosition.y = 1400.0;
  const TemporalFrame left = run(state, below, s);
  EXPECT_TRUE(left.useHistory) << left.resetReason;
  EXPECT_EQ(left.tileSize, 4u);

  // A host that would rather not march 4 times the rays there (Medium) keeps its interval.
  clouds::Settings steady = s;
  steady.movingInsideUpdateInterval = 16;
  moved.cameraPosition.z -= 20.0;
  run(state, moved, steady);
  moved.cameraPosition.z -= 20.0;
  EXPECT_EQ(run(state, moved, steady).tileSize, 4u);
  EXPECT_EQ(clouds::settingsFor(clouds::Quality::Medium).movingInsideUpdateInterval, 16u);
  steady.movingInsideUpdateInterval = 5;
  EXPECT_NE(clouds::validateSettings(steady).find("Settings.movingInsideUpdateInterval"),
            std::string::npos);
}

// A governor moving between Medium, High and Ultra (all at half the resolution) changes the
// march's precision knobs only: away from the layer the history is kept, so the change is no
// rebuild (4 to 16 times a frame's march); Low's quarter-resolution trace is a resize.
TEST(TemporalState, APresetChangeKeepsTheHistoryWhereTheTraceAllows) {
  const clouds::Quality ladder[] = {clouds::Quality::Medium, clouds::Quality::High,
                                    clouds::Quality::Ultra, clouds::Quality::High,
                                    clouds::Quality::Medium};
  TemporalState state;
  run(state, groundCamera(), clouds::settingsFor(ladder[0]), 3);
  for (const clouds::Quality q : ladder) {
    const TemporalFrame frame = run(state, groundCamera(), clouds::settingsFor(q));
    EXPECT_TRUE(frame.useHistory) << clouds::qualityName(q) << ": " << frame.resetReason;
  }
  const VkExtent2D quarter{kTrace.width / 2, kTrace.height / 2};
  const TemporalFrame low =
      run(state, groundCamera(), clouds::settingsFor(clouds::Quality::Low), 1, quarter);
  EXPECT_EQ(std::string(low.resetReason), "resize");
}

// The near field (Settings::nearFieldMetres) is marched apart while the camera is within that
// distance of the layer or of a hero cloud's box, and not elsewhere; its uniform says where the
// split lies (0: none). The history holds the far part only while it is on, so turning it on or
// off drops the history.
TEST(TemporalState, TheNearFieldIsSplitOffOnlyNearTheClouds) {
  clouds::Settings s;
  s.nearFieldMetres = 200.0f;
  TemporalState state;
  clouds::FrameInputs in = projectedGroundCamera();  // 300 m below the layer
  const auto plan = [&](double altitude, bool nearHeroCloud) {
    in.cameraPosition.y = altitude;
    const TemporalFrame frame = state.plan(in, s, kTrace, false, nearHeroCloud);
    state.commit(frame, in, s, kTrace);
    return frame;
  };
  const auto splitAt = [&](const TemporalFrame& frame) {
    clouds::detail::UniformContext context;
    context.traceExtent = kTrace;
    context.fullExtent = kTrace;
    context.temporal = frame;
    return clouds::detail::buildUniforms(in, s, context).nearFieldMetres;
  };
  plan(1200.0, false);
  const TemporalFrame away = plan(1200.0, false);
  EXPECT_FALSE(away.nearField);
  EXPECT_TRUE(away.useHistory) << away.resetReason;
  EXPECT_EQ(splitAt(away), 0.0f);
  const TemporalFrame approaching = plan(1350.0, false);  // 150 m below the base
  EXPECT_TRUE(approaching.nearField);
  EXPECT_EQ(std::string(approaching.resetReason), "near field on");
  EXPECT_EQ(splitAt(approaching), 200.0f);
  const TemporalFrame inside = plan(2500.0, false);
  EXPECT_TRUE(inside.nearField);
  EXPECT_TRUE(inside.useHistory) << inside.resetReason;
  s.nearFieldMetres = 300.0f;  // the far history held the clouds beyond 200 m
  EXPECT_EQ(std::string(plan(2500.0, false).resetReason), "near field moved");
  s.nearFieldMetres = 200.0f;
  plan(2500.0, false);
  const TemporalFrame byAHeroCloud = plan(1200.0, true);
  EXPECT_TRUE(byAHeroCloud.nearField);
  EXPECT_TRUE(byAHeroCloud.useHistory) << byAHeroCloud.resetReason;
  const TemporalFrame leaving = plan(1200.0, false);
  EXPECT_FALSE(leaving.nearField);
  EXPECT_EQ(std::string(leaving.resetReason), "near field off");
  s.nearFieldMetres = 0.0f;  // no split at all, even inside the layer
  plan(2500.0, false);
  EXPECT_FALSE(plan(2500.0, true).nearField);
}

// In a hero cloud's box, well away from the layer, the same: a moving camera refreshes more.
TEST(TemporalState, MovingInAHeroCloudRefreshesMoreToo) {
  const clouds::Settings s;
  TemporalState state;
  clouds::FrameInputs in = groundCamera();
  const auto plan = [&](bool inHeroCloud) {
    const TemporalFrame frame = state.plan(in, s, kTrace, inHeroCloud);
    state.commit(frame, in, s, kTrace);
    return frame;
  };
  plan(true);
  const TemporalFrame held = plan(true);
  EXPECT_TRUE(held.insideHeroCloud);
  EXPECT_FALSE(held.insideLayer);
  EXPECT_EQ(held.tileSize, 4u) << "held still: 1 in 16";
  in.cameraPosition.z -= 20.0;
  const TemporalFrame flying = plan(true);
  EXPECT_TRUE(flying.useHistory) << flying.resetReason;
  EXPECT_EQ(flying.tileSize, 2u) << "the cloud all around changes: 1 in 4";
  in.cameraPosition.z -= 20.0;
  EXPECT_EQ(plan(false).tileSize, 4u) << "out of it: 1 in 16 again";
}

TEST(TemporalState, AStillFrameWeighsItsFreshSamplesLess) {
  // Nothing moved: the history is exact, and averages the rays' noise over more refreshes.
  clouds::Settings s;
  s.temporalFreshWeight = 0.6f;
  s.temporalStillFreshWeight = 0.2f;
  clouds::detail::UniformContext context;
  context.traceExtent = {80, 45};
  context.fullExtent = {160, 90};
  context.temporal.tileSize = 4;
  context.temporal.useHistory = true;
  context.temporal.still = false;
  EXPECT_FLOAT_EQ(clouds::detail::buildUniforms(groundCamera(), s, context).temporalFreshWeight,
                  0.6f);
  context.temporal.still = true;
  // The mean of each pixel's refreshes (one every 16 frames), down to the still weight.
  const float weights[] = {1.0f, 0.5f, 1.0f / 3.0f, 0.25f, 0.2f, 0.2f};
  for (std::uint32_t round = 0; round < 6; ++round) {
    context.temporal.temporalIndex = round * 16 + 7;
    EXPECT_FLOAT_EQ(clouds::detail::buildUniforms(groundCamera(), s, context).temporalFreshWeight,
                    weights[round])
        << "round " << round;
  }
}

TEST(TemporalState, AFrameIsStillOnlyWhenNothingMoved) {
  // Still: the passes read each pixel's history in place instead of reprojecting it.
  const clouds::Settings s;  // wind 10 m/s
  clouds::FrameInputs in = groundCamera();
  TemporalState state;
  EXPECT_FALSE(run(state, in, s).still) << "first frame: no history to read";
  EXPECT_TRUE(run(state, in, s).still);
  clouds::FrameInputs moved = in;
  moved.cameraPosition.x += 0.01;
  EXPECT_FALSE(run(state, moved, s).still) << "the camera moved";
  EXPECT_TRUE(run(state, moved, s).still);
  clouds::FrameInputs later = moved;
  later.timeSeconds += 1.0 / 30.0;
  EXPECT_FALSE(run(state, later, s).still) << "the clouds drifted with the wind";
  clouds::Settings calm = s;
  calm.windSpeedMetresPerSecond = 0.0f;
  EXPECT_FALSE(run(state, later, calm).still) << "the noise went back to where it was at 0 s";
  later.timeSeconds += 1.0 / 30.0;
  EXPECT_TRUE(run(state, later, calm).still) << "time passed, but nothing drifts";
  clouds::FrameInputs turned = later;
  turned.view = glm::rotate(in.view, 0.01f, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_FALSE(run(state, turned, calm).still) << "the view turned";
}

TEST(TemporalState, TheHistoryDriftsAsFarAsTheHostsWindCarriedTheClouds) {
  // A host whose wind changes passes the integral of its wind (clouds/weather.h): the history
  // drifts by its change, whatever the settings' wind and the time say.
  const clouds::Settings s;  // wind 10 m/s along +x
  clouds::FrameInputs in = groundCamera();
  in.windDisplacementMetres = glm::dvec2(100.0, 0.0);
  TemporalState state;
  run(state, in, s);
  in.timeSeconds += 1.0;
  in.windDisplacementMetres = glm::dvec2(103.0, 4.0);
  const TemporalFrame frame = run(state, in, s);
  EXPECT_TRUE(frame.useHistory) << frame.resetReason;
  EXPECT_EQ(frame.windDrift, glm::dvec2(3.0, 4.0));
  // Time passes, the displacement stays: nothing drifted, whatever the wind's speed.
  in.timeSeconds += 1.0;
  const TemporalFrame calm = run(state, in, s);
  EXPECT_EQ(calm.windDrift, glm::dvec2(0.0));
  EXPECT_TRUE(calm.still);
  // Without a displacement, the settings' wind times the time: at 3 s, 30 m along +x (a jump
  // back from (103, 4) m, within the reset distance), then 5 m more in half a second.
  clouds::FrameInputs legacy = in;
  legacy.windDisplacementMetres.reset();
  legacy.timeSeconds += 1.0;
  EXPECT_EQ(run(state, legacy, s).windDrift, glm::dvec2(30.0 - 103.0, -4.0));
  legacy.timeSeconds += 0.5;
  EXPECT_EQ(run(state, legacy, s).windDrift, glm::dvec2(5.0, 0.0));
}

// A look that eases is marched ahead of itself by the frames the history lags it: at High
// (4 x 4 tiles, fresh weight 0.6) 0.4 / 0.6 x 16 + 7.5 = 18.2 frames of its change since the
// history's frame; the wind is not led (the reprojection follows it); nothing is led without a
// change, after a reset, with the lead off, or without temporal upsampling (Medium).
TEST(TemporalState, AnEasingLookIsMarchedAheadOfItsHistory) {
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  TemporalState state;
  run(state, groundCamera(), high, 3);
  clouds::Settings eased = high;
  eased.coverage += 0.002f;
  eased.windSpeedMetresPerSecond += 0.05f;
  const TemporalFrame frame = state.plan(groundCamera(), eased, kTrace);
  ASSERT_TRUE(frame.useHistory) << frame.resetReason;
  EXPECT_TRUE(frame.cloudsChanging);
  EXPECT_NEAR(frame.lookLeadFrames, 0.4f / 0.6f * 16.0f + 7.5f, 1e-4f);
  const clouds::Settings marched = state.marchedSettings(eased, frame);
  EXPECT_NEAR(marched.coverage, eased.coverage + frame.lookLeadFrames * 0.002f, 1e-5f);
  EXPECT_EQ(marched.windSpeedMetresPerSecond, eased.windSpeedMetresPerSecond);
  EXPECT_EQ(state.marchedSettings(high, state.plan(groundCamera(), high, kTrace)).coverage,
            high.coverage)
      << "nothing changed";
  clouds::Settings jumped = high;
  jumped.coverage += 0.2f;
  EXPECT_EQ(state.marchedSettings(jumped, state.plan(groundCamera(), jumped, kTrace)).coverage,
            jumped.coverage)
      << "a change that drops the history is not led";
  state.leadTheLook(false);
  EXPECT_EQ(state.marchedSettings(eased, state.plan(groundCamera(), eased, kTrace)).coverage,
            eased.coverage);

  const clouds::Settings medium = clouds::settingsFor(clouds::Quality::Medium);
  ASSERT_FALSE(clouds::upsamplesTemporally(medium));
  TemporalState spatial;
  run(spatial, groundCamera(), medium, 3);
  clouds::Settings easedMedium = medium;
  easedMedium.coverage += 0.002f;
  const TemporalFrame unled = spatial.plan(groundCamera(), easedMedium, kTrace);
  EXPECT_TRUE(unled.cloudsChanging);
  EXPECT_EQ(unled.lookLeadFrames, 0.0f);
  EXPECT_EQ(spatial.marchedSettings(easedMedium, unled).coverage, easedMedium.coverage);
}

TEST(TemporalState, ThePreviousCameraIsTheOneTheHistoryWasMadeWith) {
  // The host passes only this frame's camera: the history remembers its own.
  const clouds::Settings s;
  TemporalState state;
  clouds::FrameInputs first = groundCamera();
  first.projection = glm::perspective(1.0f, 1.7f, 0.5f, 1000.0f);
  const TemporalFrame none = run(state, first, s);
  EXPECT_EQ(none.previousView, first.view) << "no history: this frame's camera";
  clouds::FrameInputs second = first;
  second.view = glm::rotate(first.view, 0.02f, glm::vec3(0.0f, 1.0f, 0.0f));
  second.projection = glm::perspective(1.1f, 1.7f, 0.5f, 1000.0f);
  second.cameraPosition.x += 25.0;
  const TemporalFrame frame = state.plan(second, s, kTrace);
  EXPECT_EQ(frame.previousView, first.view);
  EXPECT_EQ(frame.previousProjection, first.projection);
  EXPECT_EQ(frame.cameraDelta, glm::dvec3(25.0, 0.0, 0.0));
  // A cleared sky (nothing marched) forgets the history, and says why.
  state.forget("after a clear sky");
  const TemporalFrame after = state.plan(second, s, kTrace);
  EXPECT_FALSE(after.useHistory);
  EXPECT_EQ(std::string(after.resetReason), "after a clear sky");
}

TEST(TemporalState, AResizeOfTheOutputAloneDropsTheHistory) {
  // 160 and 159 pixels both trace 80 at half resolution: the output history would not fit.
  const clouds::Settings s = clouds::settingsFor(clouds::Quality::High);
  TemporalState state;
  clouds::FrameInputs in = groundCamera();
  in.renderExtent = {160, 90};
  state.commit(state.plan(in, s, {80, 45}), in, s, {80, 45});
  in.renderExtent = {159, 90};
  const TemporalFrame frame = state.plan(in, s, {80, 45});
  EXPECT_FALSE(frame.useHistory);
  EXPECT_EQ(std::string(frame.resetReason), "resize");
}

TEST(TemporalState, EachReasonToDropTheHistoryIsDetected) {
  struct Case {
    const char* reason;
    void (*change)(clouds::FrameInputs&, VkExtent2D&);
  };
  const Case cases[] = {
      {"camera cut", [](clouds::FrameInputs& in, VkExtent2D&) { in.reset = true; }},
      {"resize", [](clouds::FrameInputs&, VkExtent2D& trace) { trace.width += 2; }},
      {"camera jump", [](clouds::FrameInputs& in, VkExtent2D&) { in.cameraPosition.x += 5000.0; }},
      {"camera turn",
       [](clouds::FrameInputs& in, VkExtent2D&) {
         in.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(1.0f, 0.2f, 0.0f), glm::vec3(0, 1, 0));
       }},
      {"relighting",
       [](clouds::FrameInputs& in, VkExtent2D&) {
         in.sunDirection = glm::normalize(glm::vec3(-0.3f, 0.8f, -0.5f));
       }},
      {"relighting",  // a lightning flash: the illuminance triples for a frame
       [](clouds::FrameInputs& in, VkExtent2D&) { in.sunIlluminance *= 3.0f; }},
      {"wind jump",  // the host's wind displacement 5 km on in a frame: other clouds
       [](clouds::FrameInputs& in, VkExtent2D&) {
         in.windDisplacementMetres = {5000.0, 0.0};
       }},
  };
  const clouds::Settings s;
  for (const Case& c : cases) {
    TemporalState state;
    const TemporalFrame before = run(state, groundCamera(), s, 5);
    ASSERT_TRUE(before.useHistory);
    clouds::FrameInputs in = groundCamera();
    VkExtent2D trace = kTrace;
    c.change(in, trace);
    const TemporalFrame after = state.plan(in, s, trace);
    EXPECT_FALSE(after.useHistory) << c.reason;
    EXPECT_EQ(std::string(after.resetReason), c.reason);
    EXPECT_LE(after.tileSize, 2u) << c.reason;
  }
}

TEST(TemporalState, NewSettingsOrANewWeatherMapDropTheHistory) {
  const clouds::Settings s;
  {
    TemporalState state;
    run(state, groundCamera(), s, 3);
    clouds::Settings denser = s;
    denser.coverage += 0.1f;
    EXPECT_EQ(std::string(state.plan(groundCamera(), denser, kTrace).resetReason),
              "settings changed");
    clouds::Settings nudged = s;
    nudged.coverage *= 1.001f;  // an animated slider's step: keep reprojecting
    EXPECT_TRUE(state.plan(groundCamera(), nudged, kTrace).useHistory);
    clouds::Settings fewerSteps = s;  // a march precision knob: a preset's rung
    fewerSteps.lightSteps -= 1;
    fewerSteps.viewStepMetres *= 2.0f;
    EXPECT_TRUE(state.plan(groundCamera(), fewerSteps, kTrace).useHistory);
    clouds::Settings noDetail = s;  // other clouds
    noDetail.detail = !s.detail;
    EXPECT_FALSE(state.plan(groundCamera(), noDetail, kTrace).useHistory);
    clouds::Settings otherBlend = s;
    otherBlend.temporalFreshWeight = 0.3f;  // temporal knobs are not the look
    EXPECT_TRUE(state.plan(groundCamera(), otherBlend, kTrace).useHistory);
  }
  {
    TemporalState state;
    run(state, groundCamera(), s, 3);
    clouds::FrameInputs painted = groundCamera();
    painted.weatherView = reinterpret_cast<VkImageView>(std::uintptr_t{0x1234});
    EXPECT_EQ(std::string(state.plan(painted, s, kTrace).resetReason), "weather map changed");
  }
}

// A painting blended into another over seconds moves the map a little each frame: the history
// is kept (and the frame is not still), also when the blend ends with the second painting
// alone; one that moves more than 1% of the map in a frame drops it.
TEST(TemporalState, APaintedMapBlendedIntoAnotherKeepsTheHistory) {
  const clouds::Settings s;
  const auto first = reinterpret_cast<VkImageView>(std::uintptr_t{0x1234});
  const auto second = reinterpret_cast<VkImageView>(std::uintptr_t{0x5678});
  clouds::FrameInputs in = groundCamera();
  in.weatherView = first;
  TemporalState state;
  run(state, in, s, 3);
  in.weatherBlendView = second;
  for (int frame = 1; frame <= 200; ++frame) {
    in.weatherBlend = float(frame) / 200.0f;  // 0.5% a frame
    const TemporalFrame planned = state.plan(in, s, kTrace);
    ASSERT_TRUE(planned.useHistory) << "at " << in.weatherBlend << ": " << planned.resetReason;
    EXPECT_FALSE(planned.still);
    state.commit(planned, in, s, kTrace);
  }
  clouds::FrameInputs after = in;  // the second painting alone: the same map
  after.weatherView = second;
  after.weatherBlendView = VK_NULL_HANDLE;
  after.weatherBlend = 0.0f;
  const TemporalFrame ended = state.plan(after, s, kTrace);
  EXPECT_TRUE(ended.useHistory) << ended.resetReason;
  EXPECT_FALSE(ended.cloudsChanging);
  state.commit(ended, after, s, kTrace);
  clouds::FrameInputs jump = after;  // 5% in one frame
  jump.weatherBlendView = first;
  jump.weatherBlend = 0.05f;
  EXPECT_EQ(std::string(state.plan(jump, s, kTrace).resetReason), "weather map changed");
}

TEST(PaintedWeather, TheChangeIsTheShareOfTheMapThatMoved) {
  using clouds::detail::PaintedWeather;
  using clouds::detail::paintedWeatherChange;
  const auto a = reinterpret_cast<VkImageView>(std::uintptr_t{0x10});
  const auto b = reinterpret_cast<VkImageView>(std::uintptr_t{0x20});
  const auto c = reinterpret_cast<VkImageView>(std::uintptr_t{0x30});
  const PaintedWeather procedural{};
  const PaintedWeather onlyA{a, VK_NULL_HANDLE, 0.0f};
  EXPECT_EQ(paintedWeatherChange(onlyA, onlyA), 0.0f);
  EXPECT_EQ(paintedWeatherChange(procedural, onlyA), 1.0f);
  EXPECT_EQ(paintedWeatherChange(onlyA, PaintedWeather{b, VK_NULL_HANDLE, 0.0f}), 1.0f);
  EXPECT_FLOAT_EQ(paintedWeatherChange(onlyA, PaintedWeather{a, b, 0.3f}), 0.3f);
  EXPECT_FLOAT_EQ(paintedWeatherChange(PaintedWeather{a, b, 0.3f}, PaintedWeather{a, b, 0.35f}),
                  0.05f);
  EXPECT_EQ(paintedWeatherChange(PaintedWeather{a, b, 1.0f}, PaintedWeather{b, VK_NULL_HANDLE, 0}),
            0.0f);
  EXPECT_EQ(paintedWeatherChange(PaintedWeather{a, a, 0.7f}, onlyA), 0.0f);
  EXPECT_FLOAT_EQ(paintedWeatherChange(PaintedWeather{a, b, 0.5f}, PaintedWeather{a, c, 0.5f}),
                  0.5f);
}

TEST(TemporalState, SmallMovesKeepTheHistory) {
  TemporalState state;
  const clouds::Settings s;
  run(state, groundCamera(), s, 3);
  clouds::FrameInputs in = groundCamera();
  in.cameraPosition.x += 100.0;  // 100 m in a frame: 6 km/s at 60 fps, still reprojectable
  in.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.1f, 0.2f, -1.0f), glm::vec3(0, 1, 0));
  in.sunDirection = glm::normalize(in.sunDirection + glm::vec3(0.005f, 0.0f, 0.0f));
  const TemporalFrame frame = state.plan(in, s, kTrace);
  EXPECT_TRUE(frame.useHistory) << frame.resetReason;
  EXPECT_EQ(frame.cameraDelta.x, 100.0);
}

TEST(TemporalState, ACutRestartsTheSequenceButTheLayerDoesNot) {
  const clouds::Settings s;
  TemporalState state;
  run(state, groundCamera(), s, 7);
  clouds::FrameInputs cut = groundCamera();
  cut.reset = true;
  EXPECT_EQ(run(state, cut, s).temporalIndex, 0u) << "after a cut: as a fresh renderer";
  clouds::FrameInputs inside = groundCamera();
  inside.cameraPosition.y = 2500.0;
  const TemporalFrame a = run(state, inside, s);
  clouds::FrameInputs flying = inside;
  flying.cameraPosition.z -= 20.0;
  const TemporalFrame b = run(state, flying, s);
  EXPECT_TRUE(a.insideLayer);
  EXPECT_EQ(b.temporalIndex, a.temporalIndex + 1) << "inside the layer the jitter still moves";
  EXPECT_NE(a.phase, b.phase) << "and the 2 x 2 tiles are refreshed in turn";
}

TEST(TemporalState, ReuseOffNeverReadsTheHistoryButMovesTheJitter) {
  clouds::Settings s;
  s.temporalReuse = false;
  TemporalState state;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const TemporalFrame frame = run(state, groundCamera(), s);
    EXPECT_FALSE(frame.useHistory);
    EXPECT_EQ(frame.temporalIndex, i) << "successive frames can be averaged";
  }
  clouds::FrameInputs cut = groundCamera();
  cut.reset = true;
  EXPECT_EQ(run(state, cut, s).temporalIndex, 0u);
  s = clouds::Settings{};
  s.updateInterval = 1;
  TemporalState full;
  EXPECT_EQ(run(full, groundCamera(), s, 3).tileSize, 1u) << "updateInterval 1: every pixel";
}

}  // namespace
