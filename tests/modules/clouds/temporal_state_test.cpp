// The temporal reconstruction's per-frame decisions, without a GPU: when last frame's result
// may be reprojected and why not, the refresh order inside a tile, the history ping-pong.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>

#include "temporal_state.h"

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
  EXPECT_NE(second.writeHistory, second.readHistory);
}

TEST(TemporalState, TilePhasesVisitEveryPixelOfTheTileInBayerOrder) {
  for (std::uint32_t k : {1u, 2u, 4u}) {
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
      {"inside the layer",
       [](clouds::FrameInputs& in, VkExtent2D&) { in.cameraPosition.y = 2500.0; }},
      {"inside the layer",  // near the base counts: the margin
       [](clouds::FrameInputs& in, VkExtent2D&) { in.cameraPosition.y = 1460.0; }},
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
    clouds::Settings fewerSteps = s;
    fewerSteps.lightSteps -= 1;
    EXPECT_FALSE(state.plan(groundCamera(), fewerSteps, kTrace).useHistory);
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
  const TemporalFrame b = run(state, inside, s);
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
