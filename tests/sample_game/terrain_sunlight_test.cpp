// The terrain sunlight map's refresh schedule: every row is refreshed within the stated number
// of frames, each exactly once per cycle, and the whole map at once when it must be.
#include <gtest/gtest.h>

#include <vector>

#include "render/terrain_sunlight.h"

namespace {

using sample::TerrainSunlightSchedule;

// How many times each row is made by `frames` calls, none of them a remake.
std::vector<int> rowsMade(TerrainSunlightSchedule& schedule, std::uint32_t rows, int frames) {
  std::vector<int> made(rows, 0);
  for (int f = 0; f < frames; ++f) {
    const TerrainSunlightSchedule::Rows r = schedule.next(false);
    EXPECT_LE(r.first + r.count, rows);
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) ++made[i];
  }
  return made;
}

TEST(TerrainSunlightSchedule, TheFirstFrameMakesTheWholeMap) {
  TerrainSunlightSchedule schedule(512, 16);
  const TerrainSunlightSchedule::Rows first = schedule.next(false);
  EXPECT_EQ(first.first, 0u);
  EXPECT_EQ(first.count, 512u);
}

TEST(TerrainSunlightSchedule, BandsCoverEveryRowOncePerCycle) {
  for (const std::uint32_t rows : {512u, 500u}) {
    TerrainSunlightSchedule schedule(rows, 16);
    schedule.next(false);  // the whole map
    const std::vector<int> once = rowsMade(schedule, rows, 16);
    for (std::uint32_t i = 0; i < rows; ++i) EXPECT_EQ(once[i], 1) << rows << " rows, row " << i;
    // And again in the next cycle, in the same order.
    const std::vector<int> twice = rowsMade(schedule, rows, 16);
    EXPECT_EQ(twice, once) << rows;
  }
}

TEST(TerrainSunlightSchedule, FewerRowsThanFramesAreAllRefreshedWithinTheCycle) {
  TerrainSunlightSchedule schedule(7, 16);
  schedule.next(false);
  const std::vector<int> made = rowsMade(schedule, 7, 16);
  for (std::uint32_t i = 0; i < 7; ++i) EXPECT_GE(made[i], 1) << "row " << i;
}

TEST(TerrainSunlightSchedule, AFrameRefreshesOnlyItsBand) {
  TerrainSunlightSchedule schedule(512, 16);
  schedule.next(false);
  const TerrainSunlightSchedule::Rows band = schedule.next(false);
  EXPECT_EQ(band.first, 0u);
  EXPECT_EQ(band.count, 32u);
  EXPECT_EQ(schedule.next(false).first, 32u);
}

TEST(TerrainSunlightSchedule, AShadowMapRemadeWholeRemakesTheWholeMapAndRestartsTheBands) {
  TerrainSunlightSchedule schedule(512, 16);
  schedule.next(false);
  schedule.next(false);
  schedule.next(false);
  const TerrainSunlightSchedule::Rows cut = schedule.next(true);
  EXPECT_EQ(cut.first, 0u);
  EXPECT_EQ(cut.count, 512u);
  EXPECT_EQ(schedule.next(false).first, 0u);
}

}  // namespace
