#pragma once
// When to generate the procedural weather map, so that its regeneration never stalls a frame.
//
// The map is a pure function of its period's key (floor(time / weatherUpdateSeconds)).
// Generating all of it costs ~50 ms on lavapipe, a hitch once per period if done in the frame
// the period starts. Instead the next period's map is generated into a spare image a few rows
// per frame while the current one is in use, and the two are swapped when its period begins;
// rows still missing then (too few frames in the period, or a jump in time) are generated in
// that frame. Either way a frame's map is identical to one generated at once.
#include <cstdint>
#include <optional>

namespace clouds::detail {

// What one frame does to the weather maps, in this order.
struct WeatherWork {
  std::int64_t key = 0;        // the period whose map the rows belong to
  std::uint32_t firstRow = 0;  // rows [firstRow, endRow) of the spare map are generated
  std::uint32_t endRow = 0;    //   (none when equal)
  bool swap = false;           // then the spare map becomes the current one

  bool generates() const { return endRow > firstRow; }
};

class WeatherSchedule {
 public:
  // `rows` of the map; `rowsPerFrame` generated ahead per frame (both multiples of the
  // shader's workgroup height).
  WeatherSchedule(std::uint32_t rows, std::uint32_t rowsPerFrame);

  // The work of a frame whose weather period is `key`; `prefetch` when the next period's map
  // may be prepared (false when every frame is its own period).
  WeatherWork plan(std::int64_t key, bool prefetch);

  // The maps were overwritten (a painted map): the next procedural frame starts afresh.
  void forget();

  // What a map depends on besides its period: the period length and the evolution rate. A
  // change forgets everything, so no map is ever made of rows from two recipes.
  void useRecipe(double periodSeconds, double evolutionPerSecond);

 private:
  std::uint32_t rows_;
  std::uint32_t rowsPerFrame_;
  std::optional<std::int64_t> current_;  // period of the current map
  std::optional<std::int64_t> spare_;    // period the spare map is being generated for
  std::uint32_t spareRows_ = 0;          // rows of the spare map generated so far
  double periodSeconds_ = -1.0;          // the recipe of both maps
  double evolutionPerSecond_ = -1.0;
};

}  // namespace clouds::detail
