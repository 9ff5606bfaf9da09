// The weather schedule: the next period's map is prepared a band of rows per frame, the
// frame a period starts swaps it in (finishing what is missing), and no frame ever uses a
// map with rows from another period.
#include <gtest/gtest.h>

#include <vector>

#include "weather_schedule.h"

namespace {

using clouds::detail::WeatherSchedule;
using clouds::detail::WeatherWork;

constexpr std::uint32_t kRows = 512;
constexpr std::uint32_t kRowsPerFrame = 32;

// The frame's work makes the rest of `key`'s map, from `firstRow`, and swaps it in.
void expectSwapIn(const WeatherWork& w, std::int64_t key, std::uint32_t firstRow) {
  EXPECT_TRUE(w.swap);
  EXPECT_EQ(w.key, key);
  EXPECT_EQ(w.firstRow, firstRow);
  EXPECT_EQ(w.endRow, kRows);
}

TEST(WeatherSchedule, TheFirstFrameGeneratesTheWholeMapAndSwapsItIn) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  expectSwapIn(schedule.plan(7, true), 7, 0u);
}

TEST(WeatherSchedule, TheNextPeriodIsPreparedABandPerFrameThenSwappedInForFree) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  schedule.plan(0, true);
  std::uint32_t expectedFirst = 0;
  for (int frame = 0; frame < 20; ++frame) {  // 16 bands, then nothing left to do
    const WeatherWork w = schedule.plan(0, true);
    EXPECT_FALSE(w.swap);
    if (expectedFirst < kRows) {
      EXPECT_EQ(w.key, 1);
      EXPECT_EQ(w.firstRow, expectedFirst);
      EXPECT_EQ(w.endRow, expectedFirst + kRowsPerFrame);
      expectedFirst += kRowsPerFrame;
    } else {
      EXPECT_FALSE(w.generates()) << "frame " << frame;
    }
  }
  const WeatherWork swap = schedule.plan(1, true);
  EXPECT_TRUE(swap.swap);
  EXPECT_EQ(swap.key, 1);
  EXPECT_FALSE(swap.generates());  // all of it was ready
  // And the period after that starts preparing on the next frame.
  const WeatherWork next = schedule.plan(1, true);
  EXPECT_EQ(next.key, 2);
  EXPECT_EQ(next.firstRow, 0u);
}

TEST(WeatherSchedule, AShortPeriodFinishesTheMissingRowsWhenItStarts) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  schedule.plan(0, true);
  schedule.plan(0, true);  // rows [0, 32) of period 1
  schedule.plan(0, true);  // rows [32, 64)
  const WeatherWork w = schedule.plan(1, true);
  expectSwapIn(w, 1, 64u);
}

TEST(WeatherSchedule, AJumpInTimeDiscardsThePreparedRows) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  schedule.plan(0, true);
  schedule.plan(0, true);            // rows of period 1
  for (std::int64_t key : {5, 3}) {  // forwards past the prepared period, then backwards
    const WeatherWork w = schedule.plan(key, true);
    expectSwapIn(w, key, 0u);
  }
}

TEST(WeatherSchedule, WithoutPrefetchEveryNewKeyIsGeneratedWholeAndNothingAhead) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  for (std::int64_t frame = 0; frame < 3; ++frame) {
    const WeatherWork w = schedule.plan(frame, false);
    expectSwapIn(w, frame, 0u);
  }
  EXPECT_FALSE(schedule.plan(2, false).generates());  // same key again: nothing to do
}

TEST(WeatherSchedule, ForgettingRegeneratesTheCurrentPeriod) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  schedule.plan(4, true);
  schedule.plan(4, true);
  schedule.forget();  // a painted map overwrote the current one
  const WeatherWork w = schedule.plan(4, true);
  expectSwapIn(w, 4, 0u);
}

TEST(WeatherSchedule, ANewRecipeDiscardsThePreparedRows) {
  WeatherSchedule schedule(kRows, kRowsPerFrame);
  schedule.useRecipe(1.0, 0.0005);
  schedule.plan(5, true);
  schedule.plan(5, true);           // rows [0, 32) of period 6 with the old recipe
  schedule.useRecipe(1.0, 0.0005);  // unchanged: nothing forgotten
  EXPECT_FALSE(schedule.plan(5, true).swap);
  schedule.useRecipe(1.1, 0.0005);  // a new period length: period 5 means another time now
  const WeatherWork w = schedule.plan(5, true);
  expectSwapIn(w, 5, 0u);
  schedule.useRecipe(1.1, 0.002);  // a new evolution rate
  EXPECT_TRUE(schedule.plan(5, true).swap);
}

}  // namespace
