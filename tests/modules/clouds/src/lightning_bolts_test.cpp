// Lightning bolts onto the screen, without a GPU (lightning_bolts.h): a piece straight ahead
// lands on the screen's centre and one to the right on the right half (the shaders' pixels, y
// down); pieces behind the camera are dropped and pieces through its plane cut at the near
// distance; pieces off screen are dropped and long ones cut to the screen; the bounds hold
// every piece with its width.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "lightning_bolts.h"

namespace {

constexpr VkExtent2D kExtent{200, 100};

clouds::FrameInputs looking() {
  clouds::FrameInputs in;
  in.renderExtent = kExtent;
  in.cameraPosition = {100.0, 500.0, 200.0};
  in.view = glm::mat4(1.0f);  // looks along -z
  in.projection = glm::perspective(glm::radians(60.0f), 2.0f, 0.5f, 1e5f);
  in.projection[1][1] *= -1.0f;  // Vulkan's y down
  return in;
}

clouds::LightningBoltSegment piece(glm::dvec3 from, glm::dvec3 to) {
  clouds::LightningBoltSegment p;
  p.fromMetres = from;
  p.toMetres = to;
  p.radiance = glm::vec3(5.0f);
  p.widthMetres = 2.0f;
  return p;
}

std::vector<clouds::LightningBoltSegment> bolts;

clouds::detail::ProjectedBolts project(clouds::FrameInputs in,
                                       std::vector<clouds::LightningBoltSegment> pieces) {
  bolts = std::move(pieces);
  in.lightningBolts = bolts;
  return clouds::detail::projectBolts(in);
}

TEST(LightningBolts, AheadIsTheCentreAndUpIsUp) {
  const clouds::FrameInputs in = looking();
  const glm::dvec3 eye = in.cameraPosition;
  // A vertical piece 1 km ahead, from 100 m above the eye to 100 m below.
  const auto out =
      project(in, {piece(eye + glm::dvec3(0, 100, -1000), eye + glm::dvec3(0, -100, -1000))});
  ASSERT_EQ(out.header.count.x, 1u);
  const glm::vec4 ends = out.segments[0];
  EXPECT_NEAR(ends.x, 100.0f, 1e-3f);
  EXPECT_NEAR(ends.z, 100.0f, 1e-3f);
  EXPECT_LT(ends.y, 50.0f) << "the upper end is higher on screen (y down)";
  EXPECT_GT(ends.w, 50.0f);
  EXPECT_NEAR(ends.y + ends.w, 100.0f, 1e-3f) << "symmetric about the centre row";
  // 1 / clip w at both ends: 1 km along the view axis.
  EXPECT_NEAR(out.segments[1].x, 1e-3f, 1e-8f);
  EXPECT_NEAR(out.segments[1].y, 1e-3f, 1e-8f);
  EXPECT_EQ(out.segments[1].z, 2.0f) << "the width in metres";
  EXPECT_EQ(glm::vec3(out.segments[2]), glm::vec3(5.0f));
  // The focal length (px): 50 rows over tan(30 degrees).
  EXPECT_NEAR(out.header.clipWRow.w, 50.0f / std::tan(glm::radians(30.0f)), 1e-3f);
  // To the right of the eye: the right half.
  const auto right =
      project(in, {piece(eye + glm::dvec3(300, 0, -1000), eye + glm::dvec3(300, -50, -1000))});
  ASSERT_EQ(right.header.count.x, 1u);
  EXPECT_GT(right.segments[0].x, 100.0f);
}

TEST(LightningBolts, BehindTheCameraIsDroppedAndThroughItIsCut) {
  const clouds::FrameInputs in = looking();
  const glm::dvec3 eye = in.cameraPosition;
  EXPECT_EQ(project(in, {piece(eye + glm::dvec3(0, 0, 100), eye + glm::dvec3(0, -50, 300))})
                .header.count.x,
            0u);
  // From 100 m behind to 100 m ahead, 10 m below the eye: cut where it is 1 m ahead.
  const auto cut =
      project(in, {piece(eye + glm::dvec3(0, -10, 100), eye + glm::dvec3(0, -10, -100))});
  ASSERT_EQ(cut.header.count.x, 1u);
  const glm::vec4 along = cut.segments[1];
  EXPECT_LE(std::max(along.x, along.y), 1.0f + 1e-4f) << "no end nearer than 1 m";
  for (const glm::vec4& v : cut.segments) {
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(v[c]));
  }
}

TEST(LightningBolts, OffScreenIsDroppedAndLongPiecesAreCutToTheScreen) {
  const clouds::FrameInputs in = looking();
  const glm::dvec3 eye = in.cameraPosition;
  // Far to the left, beyond the 120-degree-wide view.
  EXPECT_EQ(
      project(in, {piece(eye + glm::dvec3(-5000, 0, -1000), eye + glm::dvec3(-5000, -100, -1000))})
          .header.count.x,
      0u);
  // 1000 km across, 1 km ahead: cut to the screen and its margin.
  const auto wide =
      project(in, {piece(eye + glm::dvec3(-1e6, 0, -1000), eye + glm::dvec3(1e6, 0, -1000))});
  ASSERT_EQ(wide.header.count.x, 1u);
  const glm::vec4 ends = wide.segments[0];
  EXPECT_GT(std::min(ends.x, ends.z), -5.0f);
  EXPECT_LT(std::max(ends.x, ends.z), 205.0f);
  // The bounds hold both ends with their margin.
  EXPECT_LE(wide.header.bounds.x, std::min(ends.x, ends.z));
  EXPECT_GE(wide.header.bounds.z, std::max(ends.x, ends.z));
  EXPECT_LT(wide.header.bounds.y, ends.y);
  EXPECT_GT(wide.header.bounds.w, ends.y);
}

TEST(LightningBolts, NoBoltsNoPieces) {
  const auto none = project(looking(), {});
  EXPECT_EQ(none.header.count.x, 0u);
  EXPECT_TRUE(none.segments.empty());
}

// The pieces are binned: every pixel along a piece lies in a tile that lists it, and in a
// listed 8 x 8 block; the tiles start at a multiple of 8 px.
TEST(LightningBolts, EveryPieceIsInTheTilesAndBlocksItCrosses) {
  const clouds::FrameInputs in = looking();
  const glm::dvec3 eye = in.cameraPosition;
  const auto out =
      project(in, {piece(eye + glm::dvec3(-300, 200, -1000), eye + glm::dvec3(250, -150, -1000)),
                   piece(eye + glm::dvec3(100, 100, -800), eye + glm::dvec3(120, -300, -800))});
  ASSERT_EQ(out.header.count.x, 2u);
  const glm::vec2 origin(out.header.bounds);
  EXPECT_EQ(std::fmod(origin.x, 8.0f), 0.0f);
  EXPECT_EQ(std::fmod(origin.y, 8.0f), 0.0f);
  const float side = float(out.header.count.w);
  ASSERT_GE(side, 8.0f);
  ASSERT_FALSE(out.blocks.empty());
  for (std::uint32_t i = 0; i < 2; ++i) {
    const glm::vec4 ends = out.segments[3 * i];
    for (float t = 0.0f; t <= 1.0f; t += 0.01f) {
      const glm::vec2 p = glm::mix(glm::vec2(ends.x, ends.y), glm::vec2(ends.z, ends.w), t);
      if (p.x < 0.0f || p.y < 0.0f || p.x >= 200.0f || p.y >= 100.0f) continue;
      const glm::uvec2 tile((p - origin) / side);
      const glm::uvec2 range = out.tiles[tile.y * out.header.count.y + tile.x];
      bool listed = false;
      for (std::uint32_t k = 0; k < range.y; ++k) listed |= out.pieces[range.x + k] == i;
      EXPECT_TRUE(listed) << "piece " << i << " at t " << t;
      const glm::uvec2 block(p / 8.0f);
      EXPECT_NE(std::find(out.blocks.begin(), out.blocks.end(), block.x | block.y << 16),
                out.blocks.end())
          << "piece " << i << " at t " << t;
    }
  }
  // The words hold it all, in whole quads, where the header says.
  const std::vector<std::uint32_t> words = out.words();
  EXPECT_EQ(words.size() % 4, 0u);
  EXPECT_EQ(words[out.header.tiles.x], out.tiles[0].x);
  EXPECT_EQ(words[out.header.tiles.z], out.blocks[0]);
  EXPECT_EQ(out.header.tiles.w, out.blocks.size());
  EXPECT_LE(sizeof(out.header) + words.size() * 4, clouds::detail::boltBufferBytes(2));
}

}  // namespace
