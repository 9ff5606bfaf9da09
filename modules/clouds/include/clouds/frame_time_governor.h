#pragma once
// A frame-time governor: which rung of a quality ladder holds a time budget, judged from the
// times the host measures (its GPU timestamps of the clouds' passes, or of its whole frame).
// Plain CPU code; optional: nothing else in the module uses it.
//
//   auto governor = FrameTimeGovernor::create(config, &error);   // once
//   governor->observe(milliseconds);   // each frame, with what the rung it rendered took
//   settingsFor(ladder[governor->rung()], look);                  // the next frame's settings
//
// How it decides, from a quantile of the last `windowFrames` frames at the current rung (the
// median by default; a higher `judgedQuantile` holds the slow frames to the target too):
//   - over the target by more than `descendMargin`: down, as many rungs as the known cost
//     ratios say it takes to fit (a scene that suddenly costs twice as much steps down at once);
//   - the rung above predicted under the target by `climbMargin` or more: up one rung. The
//     prediction is this quantile times the two rungs' cost ratio as last measured across a
//     change between them (the ladder's nominal ratio until then), so it follows the scene;
//   - a climb that has to come back down at its first judgement is not tried again for
//     `backoffFrames`, doubled with each failure in a row (up to 16 times);
//   - changes are at least `minimumFramesBetweenChanges` frames apart, and the first
//     `settleFrames` after one are not judged (a new rung's first frames build its history).
// So at a steady load it never changes faster than the minimum period, and a rung whose cost
// straddles the target costs at most one failed climb per backoff.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"

namespace clouds {

struct FrameTimeGovernorConfig {
  double targetMilliseconds = 33.3;  // (0, 1e5]: the time to hold
  // The ladder's nominal costs, cheapest rung first, strictly increasing, all > 0 (any unit: only
  // ratios count), at least one rung. They predict a climb until both rungs have been measured.
  std::vector<double> nominalRungCosts;
  std::size_t floorRung = 0;                       // the lowest rung it may choose
  std::optional<std::size_t> ceilingRung;          // the highest (none: the ladder's top)
  std::size_t startRung = 0;                       // clamped to [floor, ceiling]
  std::uint32_t windowFrames = 24;                 // [3, 1000]: frames judged together
  std::uint32_t settleFrames = 4;                  // [0, 1000]: frames after a change not judged
  std::uint32_t minimumFramesBetweenChanges = 60;  // [1, 1e6], >= windowFrames + settleFrames
  double descendMargin = 0.05;  // [0, 1]: down when judged > target * (1 + margin)
  double climbMargin = 0.1;     // [0, 0.9]: up when predicted <= target * (1 - margin)
  // [0.5, 0.99]: the quantile of the window that is judged. 0.5 (the median) holds the typical
  // frame; 0.9 holds nine frames in ten, for a timing source as noisy as a CPU rasteriser's
  // wall clock, whose median can sit under the target while one frame in five runs over it.
  double judgedQuantile = 0.5;
  std::uint32_t backoffFrames = 240;  // [0, 1e6]: the first wait after a failed climb
};

// "" when every field is in range, else the first field that is not, named and explained.
std::string validateFrameTimeGovernorConfig(const FrameTimeGovernorConfig& config);

class FrameTimeGovernor {
 public:
  // Why the last judgement chose what it did (for HUDs and logs).
  enum class Reason : std::uint8_t {
    Starting,    // no judgement yet
    Holding,     // within the target, no room above (or at the ceiling)
    OverTarget,  // stepped down
    RoomAbove,   // stepped up
    BackingOff,  // room above, but the last climb there failed: waiting
  };

  // Empty (and `error` filled) when the configuration is out of range.
  static std::optional<FrameTimeGovernor> create(const FrameTimeGovernorConfig& config,
                                                 std::string* error);

  // One frame's time at rung(), in milliseconds. Returns the rung for the next frame. Times that
  // are not finite and positive are counted in ignoredSamples() and change nothing.
  std::size_t observe(double milliseconds);

  std::size_t rung() const { return rung_; }
  Reason reason() const { return reason_; }
  // The window's judgedQuantile the last judgement saw (0 before the first).
  double lastJudgedMilliseconds() const { return lastJudged_; }
  std::uint64_t framesObserved() const { return frame_; }
  std::uint64_t changes() const { return changes_; }
  std::uint64_t ignoredSamples() const { return ignored_; }
  const FrameTimeGovernorConfig& config() const { return config_; }

  // A new target (e.g. from a settings panel), judged from the next full window on. False (and
  // nothing changed) when it is not in (0, 1e5].
  bool setTargetMilliseconds(double milliseconds);

 private:
  explicit FrameTimeGovernor(const FrameTimeGovernorConfig& config);
  void judge();
  void moveTo(std::size_t rung);
  std::size_t ceiling() const;
  // Cost of rung r + 1 over rung r: as last measured, else nominal.
  double costRatioAbove(std::size_t r) const;
  // Learns the cost ratio between the current rung, whose first judged time is `judged`, and
  // the neighbour it came from.
  void learnRatio(double judged);

  struct RungRecord {
    double judgedMilliseconds = 0.0;        // its last judgement's (0: never judged)
    std::uint32_t failedClimbs = 0;         // failed climbs to this rung in a row
    std::uint64_t climbAllowedAtFrame = 0;  // backoff: no climb to this rung before it
  };

  FrameTimeGovernorConfig config_;
  std::vector<RungRecord> rungs_;
  std::vector<double> learnedRatios_;  // measured cost of rung r + 1 over rung r (0: not yet)
  std::vector<double> window_;         // times at the current rung since it was chosen and settled
  std::size_t rung_ = 0;
  std::uint64_t frame_ = 0;
  std::uint64_t lastChangeFrame_ = 0;
  std::uint64_t changes_ = 0;
  std::uint64_t ignored_ = 0;
  double lastJudged_ = 0.0;
  std::optional<std::size_t> arrivedFrom_;  // the rung left, until this one's first judgement
  bool climbedIntoThisRung_ = false;  // the current rung was reached by a climb not yet judged
  Reason reason_ = Reason::Starting;
};

const char* governorReasonName(FrameTimeGovernor::Reason reason);

// The module's presets as a governor's ladder, cheapest first (Reference, the converged ground
// truth, is no rung), with nominal costs: the committed benchmark's medians over its static
// views (640x360, lavapipe). Only their ratios count; the governor measures the real ones.
struct PresetLadder {
  std::vector<Quality> presets;
  std::vector<double> nominalMilliseconds;
};
const PresetLadder& presetLadder();  // made once

}  // namespace clouds
