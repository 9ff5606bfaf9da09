#include "weather_schedule.h"

#include <algorithm>

namespace clouds::detail {

WeatherSchedule::WeatherSchedule(std::uint32_t rows, std::uint32_t rowsPerFrame)
    : rows_(rows), rowsPerFrame_(std::max(rowsPerFrame, 1u)) {}

WeatherWork WeatherSchedule::plan(std::int64_t key, bool prefetch) {
  WeatherWork work;
  if (current_ != key) {
    // This period's map is due now: finish it in the spare map (from scratch unless it was
    // being prepared) and make it current. The old current map becomes the spare.
    if (spare_ != key) {
      spare_ = key;
      spareRows_ = 0;
    }
    work = {key, spareRows_, rows_, true};
    current_ = key;
    spare_.reset();
    spareRows_ = 0;
    return work;
  }
  if (!prefetch) return work;
  const std::int64_t next = key + 1;
  if (spare_ != next) {
    spare_ = next;
    spareRows_ = 0;
  }
  const std::uint32_t end = std::min(rows_, spareRows_ + rowsPerFrame_);
  work = {next, spareRows_, end, false};
  spareRows_ = end;
  return work;
}

void WeatherSchedule::forget() {
  current_.reset();
  spare_.reset();
  spareRows_ = 0;
}

void WeatherSchedule::useRecipe(double periodSeconds, double evolutionPerSecond) {
  if (periodSeconds == periodSeconds_ && evolutionPerSecond == evolutionPerSecond_) return;
  periodSeconds_ = periodSeconds;
  evolutionPerSecond_ = evolutionPerSecond;
  forget();
}

}  // namespace clouds::detail
