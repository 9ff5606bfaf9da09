// The shadow map's cascade bookkeeping without a GPU: the turn order, which events remake a
// cascade at once, whole-texel placement, turns spread over frames in slices of rows, and the
// wind's drift in the lookup parameters.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include "cloud_shadow_march.h"
#include "shadow_cascades.h"
#include "wind_displacement.h"

namespace {

using clouds::detail::cascadeForTurn;
using clouds::detail::ShadowCascades;
using clouds::detail::windDisplacementOf;

clouds::FrameInputs camera() {
  clouds::FrameInputs in;
  in.cameraPosition = {1000.0, 300.0, -2000.0};
  in.sunDirection = glm::normalize(glm::vec3(0.3f, 0.6f, -0.5f));
  in.timeSeconds = 10.0;
  return in;
}

std::uint32_t madeMask(const clouds::detail::ShadowPlan& plan) {
  std::uint32_t mask = 0;
  for (const auto& job : plan.jobs) mask |= 1u << job.cascade;
  return mask;
}

// Plans and commits a frame; returns the cascades it made.
std::uint32_t frame(ShadowCascades& cascades, const clouds::FrameInputs& in,
                    const clouds::Settings& s) {
  const clouds::detail::ShadowPlan plan = cascades.plan(in, s);
  cascades.commit(plan, in, s);
  return madeMask(plan);
}

TEST(ShadowCascades, TheFinestTakesEveryOtherTurn) {
  const std::uint32_t four[] = {0, 1, 0, 2, 0, 3, 0, 1};
  for (std::uint64_t t = 0; t < 8; ++t) EXPECT_EQ(cascadeForTurn(t, 4), four[t]);
  for (std::uint64_t t = 0; t < 4; ++t) EXPECT_EQ(cascadeForTurn(t, 1), 0u);
  for (std::uint64_t t = 0; t < 4; ++t) EXPECT_EQ(cascadeForTurn(t, 2), t % 2);
}

TEST(ShadowCascades, AFirstFrameMakesAllThenOnePerFrame) {
  ShadowCascades cascades;
  clouds::Settings s;
  clouds::FrameInputs in = camera();
  EXPECT_EQ(frame(cascades, in, s), 0xFu);
  const std::uint32_t expected[] = {1, 2, 1, 4, 1, 8, 1, 2};
  for (std::uint32_t e : expected) {
    in.timeSeconds += 1.0 / 30.0;
    EXPECT_EQ(frame(cascades, in, s), e);
  }
  s.shadowCascadesPerFrame = 4;
  in.timeSeconds += 1.0 / 30.0;
  EXPECT_EQ(frame(cascades, in, s), 0xFu) << "four per frame: all of them";
}

TEST(ShadowCascades, CutsJumpsTurnsAndNewSettingsRemakeEverything) {
  clouds::Settings s;
  auto settled = [&](ShadowCascades& c, clouds::FrameInputs& in) {
    frame(c, in, s);
    in.timeSeconds += 0.03;
    frame(c, in, s);  // one cascade: settled
    in.timeSeconds += 0.03;
  };
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.reset = true;
    EXPECT_EQ(frame(c, in, s), 0xFu) << "camera cut";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.cameraPosition.x += 50000.0;
    EXPECT_EQ(frame(c, in, s) & 0x7u, 0x7u) << "a 50 km jump leaves the three finest behind";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.sunDirection = glm::normalize(glm::vec3(-0.3f, 0.6f, -0.5f));
    EXPECT_EQ(frame(c, in, s), 0xFu) << "the sun turned";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    clouds::Settings denser = s;
    denser.coverage = 0.8f;
    EXPECT_EQ(frame(c, in, denser), 0xFu) << "new settings";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.terrain.heightView = reinterpret_cast<VkImageView>(std::uintptr_t{0x1000});
    in.terrain.sizeMetres = {40000.0, 40000.0};
    in.terrain.maxAltitudeMetres = 2000.0f;
    EXPECT_EQ(frame(c, in, s), 0xFu) << "a terrain came";
    in.timeSeconds += 0.03;
    const clouds::detail::ShadowPlan still = c.plan(in, s);
    ASSERT_EQ(still.jobs.size(), 1u) << "the same terrain";
    EXPECT_TRUE(still.jobs[0].keepTerrain) << "the same rays over the same terrain";
    c.commit(still, in, s);
    in.cameraPosition.x += 3000.0;  // beyond a quarter of the finest cascade: remade, moved
    const clouds::detail::ShadowPlan moved = c.plan(in, s);
    ASSERT_FALSE(moved.jobs.empty());
    EXPECT_FALSE(moved.jobs[0].keepTerrain) << "the rays moved";
    c.commit(moved, in, s);
    in.terrain.maxAltitudeMetres = 2500.0f;
    EXPECT_EQ(frame(c, in, s), 0xFu) << "the terrain changed";
    in.terrain = {};
    EXPECT_EQ(frame(c, in, s), 0xFu) << "the terrain went";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.timeSeconds -= 5.0;
    EXPECT_EQ(frame(c, in, s), 0xFu) << "time went back";
  }
  {
    ShadowCascades c;
    clouds::FrameInputs in = camera();
    settled(c, in);
    in.cameraPosition.x += 30.0;
    EXPECT_EQ(std::popcount(frame(c, in, s)), 1) << "a small move only takes its turn";
  }
}

// A frame's completed cascades: those made whole and the one whose last slice it made.
std::uint32_t completedMask(const clouds::detail::ShadowPlan& plan) {
  std::uint32_t mask = madeMask(plan);
  if (plan.slice && plan.slice->last) mask |= 1u << plan.slice->job.cascade;
  return mask;
}

clouds::Settings sliced(std::uint32_t framesPerCascade) {
  clouds::Settings s;
  s.shadowFramesPerCascade = framesPerCascade;
  return s;
}

TEST(ShadowCascades, ATurnSpreadOverFramesMakesEveryRowOnce) {
  for (const std::uint32_t resolution : {128u, 100u, 17u}) {
    for (const std::uint32_t frames : {2u, 3u, 8u}) {
      ShadowCascades cascades;
      clouds::Settings s = sliced(frames);
      s.shadowMapResolution = resolution;
      clouds::FrameInputs in = camera();
      clouds::detail::ShadowPlan plan = cascades.plan(in, s);
      EXPECT_EQ(madeMask(plan), 0xFu) << "the first frame makes every cascade whole";
      EXPECT_FALSE(plan.slice.has_value());
      cascades.commit(plan, in, s);
      // Four turns: 0, 1, 0, 2; each a run of slices covering the rows in order, then done.
      for (const std::uint32_t cascade : {0u, 1u, 0u, 2u}) {
        std::uint32_t row = 0;
        std::uint32_t slices = 0;
        bool done = false;
        while (!done) {
          in.timeSeconds += 1.0 / 30.0;
          plan = cascades.plan(in, s);
          ASSERT_TRUE(plan.jobs.empty());
          ASSERT_TRUE(plan.slice.has_value());
          const clouds::detail::CascadeSlice& slice = *plan.slice;
          EXPECT_EQ(slice.job.cascade, cascade);
          EXPECT_EQ(slice.first, row == 0);
          EXPECT_EQ(slice.firstRow, row);
          EXPECT_GT(slice.rowCount, 0u);
          row += slice.rowCount;
          done = slice.last;
          EXPECT_EQ(completedMask(plan), done ? 1u << cascade : 0u);
          cascades.commit(plan, in, s);
          ++slices;
        }
        EXPECT_EQ(row, resolution) << resolution << " rows over " << frames << " frames";
        EXPECT_LE(slices, frames);
        EXPECT_GE(2 * slices, std::min(frames, resolution)) << "slices of even size";
      }
    }
  }
}

// Every slice makes what the first slice's frame would have made: its placement and camera,
// even when the camera moved since; receivers see the new cascade (its placement and time)
// only once it is done.
TEST(ShadowCascades, SlicesKeepTheirFirstFramesPlacementUntilDone) {
  ShadowCascades cascades;
  const clouds::Settings s = sliced(2);
  clouds::FrameInputs in = camera();
  frame(cascades, in, s);
  // Two whole turns (0 and 1) settle the map; then move 4 texels of the finest cascade.
  for (int i = 0; i < 4; ++i) {
    in.timeSeconds += 1.0 / 30.0;
    frame(cascades, in, s);
  }
  in.cameraPosition.x += 320.0;
  in.timeSeconds += 1.0 / 30.0;
  const clouds::ShadowMapParameters before =
      cascades.parameters(in.cameraPosition, windDisplacementOf(in, s), s);
  const clouds::detail::ShadowPlan first = cascades.plan(in, s);
  ASSERT_TRUE(first.slice && first.slice->first && first.slice->job.cascade == 0u);
  cascades.commit(first, in, s);
  EXPECT_EQ(cascades.parameters(in.cameraPosition, windDisplacementOf(in, s), s).cascade[0],
            before.cascade[0])
      << "half a cascade is not seen";

  clouds::FrameInputs later = in;
  later.cameraPosition.z += 200.0;
  later.timeSeconds += 1.0 / 30.0;
  const clouds::detail::ShadowPlan last = cascades.plan(later, s);
  ASSERT_TRUE(last.slice && last.slice->last);
  EXPECT_EQ(last.slice->cameraPosition, in.cameraPosition);
  EXPECT_EQ(last.slice->job.cornerTexel, first.slice->job.cornerTexel);
  cascades.commit(last, later, s);
  // Now made at the first slice's placement and time: the lookup at the first slice's camera
  // and time is the one a whole make then would give.
  ShadowCascades whole;
  clouds::Settings once = s;
  once.shadowFramesPerCascade = 1;
  once.shadowCascadesPerFrame = 4;
  frame(whole, in, once);
  const auto made = cascades.parameters(in.cameraPosition, windDisplacementOf(in, s), s);
  const auto expected = whole.parameters(in.cameraPosition, windDisplacementOf(in, once), once);
  for (int row = 0; row < 3; ++row) EXPECT_EQ(made.cascade[row], expected.cascade[row]);
  EXPECT_NE(made.cascade[0], before.cascade[0]) << "the finest cascade moved with the camera";
}

TEST(ShadowCascades, ARemakeAtOnceAbandonsTheCascadeInTheMaking) {
  ShadowCascades cascades;
  clouds::Settings s = sliced(4);
  clouds::FrameInputs in = camera();
  frame(cascades, in, s);
  in.timeSeconds += 1.0 / 30.0;
  frame(cascades, in, s);  // the first slice of cascade 0
  in.timeSeconds += 1.0 / 30.0;
  in.reset = true;
  const clouds::detail::ShadowPlan cut = cascades.plan(in, s);
  EXPECT_EQ(madeMask(cut), 0xFu);
  EXPECT_TRUE(cut.abandonSlices);
  EXPECT_FALSE(cut.slice.has_value());
  cascades.commit(cut, in, s);
  in.reset = false;
  in.timeSeconds += 1.0 / 30.0;
  const clouds::detail::ShadowPlan next = cascades.plan(in, s);
  ASSERT_TRUE(next.slice.has_value());
  EXPECT_TRUE(next.slice->first) << "a new cascade is begun, not the abandoned one continued";
  EXPECT_EQ(next.slice->firstRow, 0u);
  cascades.commit(next, in, s);
  // A change of the number of frames per cascade begins the turn again.
  s.shadowFramesPerCascade = 2;
  in.timeSeconds += 1.0 / 30.0;
  const clouds::detail::ShadowPlan changed = cascades.plan(in, s);
  ASSERT_TRUE(changed.slice.has_value());
  EXPECT_TRUE(changed.slice->first);
  EXPECT_EQ(changed.slice->rowCount, s.shadowMapResolution / 2);
}

TEST(ShadowCascades, CascadesLieOnWholeTexelsAroundTheCamera) {
  ShadowCascades cascades;
  clouds::Settings s;
  clouds::FrameInputs in = camera();
  const auto plan = cascades.plan(in, s);
  ASSERT_EQ(plan.jobs.size(), 4u);
  for (const auto& job : plan.jobs) {
    const double side = clouds::detail::cascadeSideMetres(s, job.cascade);
    EXPECT_DOUBLE_EQ(job.texelMetres, side / s.shadowMapResolution);
    // The camera (below the cloud base) is within a texel of the middle.
    const double u = glm::dot(in.cameraPosition, job.basis.u) / job.texelMetres;
    const double v = glm::dot(in.cameraPosition, job.basis.v) / job.texelMetres;
    EXPECT_NEAR(u - double(job.cornerTexel.x), s.shadowMapResolution / 2.0, 1.0);
    EXPECT_NEAR(v - double(job.cornerTexel.y), s.shadowMapResolution / 2.0, 1.0);
    // The rays go towards the sun, across an orthonormal frame.
    EXPECT_NEAR(glm::dot(job.basis.light, glm::dvec3(in.sunDirection)), 1.0, 1e-6);
    EXPECT_NEAR(glm::dot(job.basis.u, job.basis.light), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(job.basis.v, job.basis.light), 0.0, 1e-9);
  }
  // A move of a fraction of a texel keeps every cascade where it was.
  clouds::FrameInputs moved = in;
  moved.cameraPosition += glm::dvec3(0.3, 0.0, 0.2);
  const auto again = cascades.plan(moved, s);
  int same = 0;
  for (std::size_t i = 0; i < 4; ++i) same += again.jobs[i].cornerTexel == plan.jobs[i].cornerTexel;
  EXPECT_GE(same, 3);
}

TEST(ShadowCascades, ALowSunIsRaisedToTheMapsMinimum) {
  const auto basis = clouds::detail::shadowBasis({1.0f, -0.2f, 0.0f});
  EXPECT_NEAR(basis.light.y, clouds::shader::kShadowMinSunSine, 1e-6);
  EXPECT_GT(basis.light.x, 0.99);
  const auto zenith = clouds::detail::shadowBasis({0.0f, 1.0f, 0.0f});
  EXPECT_NEAR(glm::length(zenith.u), 1.0, 1e-9);
  EXPECT_NEAR(glm::dot(zenith.u, zenith.light), 0.0, 1e-9);
}

TEST(ShadowCascades, ParametersCarryTheWindsDriftSinceACascadeWasMade) {
  ShadowCascades cascades;
  clouds::Settings s;
  s.windDirection = {1.0f, 0.0f};
  s.windSpeedMetresPerSecond = 20.0f;
  clouds::FrameInputs in = camera();
  frame(cascades, in, s);
  // The clouds carried 200 m and then 240 m along +x since time 0, when the map was made.
  const clouds::ShadowMapParameters now = cascades.parameters(in.cameraPosition, {200.0, 0.0}, s);
  const clouds::ShadowMapParameters later = cascades.parameters(in.cameraPosition, {240.0, 0.0}, s);
  for (int c = 0; c < 4; ++c) {
    const glm::vec4 u = now.cascade[3 * c];
    // 40 m of drift along +x, seen along U.
    EXPECT_NEAR(later.cascade[3 * c].w - u.w, 40.0f * u.x, 1e-2f);
  }
  EXPECT_EQ(now.info.x, 4.0f);
  EXPECT_EQ(now.info.y, float(s.shadowMapResolution));
  EXPECT_EQ(now.info.z, 300.0f);
}

}  // namespace
