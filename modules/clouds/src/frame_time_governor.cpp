#include "clouds/frame_time_governor.h"

#include <algorithm>
#include <cmath>

namespace clouds {

namespace {

constexpr double kMaxTargetMilliseconds = 1e5;
// Backoff doubles with each failed climb in a row, up to 2^4 = 16 times the first wait.
constexpr std::uint32_t kMaxBackoffDoublings = 4;

// The value below which a fraction `q` of `values` lies (nearest rank; q = 0.5: the median).
double quantile(std::vector<double> values, double q) {
  const auto rank = std::min(values.size() - 1, std::size_t(q * double(values.size())));
  const auto at = values.begin() + std::ptrdiff_t(rank);
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

bool validTarget(double milliseconds) {
  return std::isfinite(milliseconds) && milliseconds > 0.0 &&
         milliseconds <= kMaxTargetMilliseconds;
}

}  // namespace

std::string validateFrameTimeGovernorConfig(const FrameTimeGovernorConfig& c) {
  const auto field = [](const char* name, const std::string& why) {
    return std::string("FrameTimeGovernorConfig.") + name + ": " + why;
  };
  if (!validTarget(c.targetMilliseconds))
    return field("targetMilliseconds",
                 "must be in (0, 1e5] ms, got " + std::to_string(c.targetMilliseconds));
  if (c.nominalRungCosts.empty()) return field("nominalRungCosts", "the ladder has no rung");
  for (std::size_t i = 0; i < c.nominalRungCosts.size(); ++i) {
    const double cost = c.nominalRungCosts[i];
    if (!std::isfinite(cost) || cost <= 0.0)
      return field("nominalRungCosts",
                   "rung " + std::to_string(i) + " must cost a finite amount > 0");
    if (i > 0 && cost <= c.nominalRungCosts[i - 1])
      return field("nominalRungCosts", "rung " + std::to_string(i) +
                                           " must cost more than the one below (cheapest first)");
  }
  const std::size_t top = c.nominalRungCosts.size() - 1;
  if (c.ceilingRung && *c.ceilingRung > top)
    return field("ceilingRung", "must be a rung of the ladder (0.." + std::to_string(top) + ")");
  if (c.floorRung > c.ceilingRung.value_or(top))
    return field("floorRung", "must not be above the ceiling");
  if (c.windowFrames < 3 || c.windowFrames > 1000)
    return field("windowFrames", "must be in [3, 1000]");
  if (c.settleFrames > 1000) return field("settleFrames", "must be in [0, 1000]");
  if (c.minimumFramesBetweenChanges > 1000000 ||
      c.minimumFramesBetweenChanges < c.windowFrames + c.settleFrames)
    return field("minimumFramesBetweenChanges",
                 "must be in [windowFrames + settleFrames, 1e6]: a change is judged on a full "
                 "window of settled frames");
  if (!(c.descendMargin >= 0.0 && c.descendMargin <= 1.0))
    return field("descendMargin", "must be in [0, 1]");
  if (!(c.climbMargin >= 0.0 && c.climbMargin <= 0.9))
    return field("climbMargin", "must be in [0, 0.9]");
  if (c.backoffFrames > 1000000) return field("backoffFrames", "must be in [0, 1e6]");
  if (!(c.judgedQuantile >= 0.5 && c.judgedQuantile <= 0.99))
    return field("judgedQuantile", "must be in [0.5, 0.99]");
  return {};
}

std::optional<FrameTimeGovernor> FrameTimeGovernor::create(const FrameTimeGovernorConfig& config,
                                                           std::string* error) {
  std::string problem = validateFrameTimeGovernorConfig(config);
  if (!problem.empty()) {
    if (error != nullptr) *error = std::move(problem);
    return std::nullopt;
  }
  return FrameTimeGovernor(config);
}

FrameTimeGovernor::FrameTimeGovernor(const FrameTimeGovernorConfig& config)
    : config_(config),
      rungs_(config.nominalRungCosts.size()),
      learnedRatios_(config.nominalRungCosts.size(), 0.0) {
  rung_ = std::clamp(config.startRung, config.floorRung, ceiling());
  window_.reserve(config.windowFrames);
}

std::size_t FrameTimeGovernor::ceiling() const {
  return config_.ceilingRung.value_or(config_.nominalRungCosts.size() - 1);
}

bool FrameTimeGovernor::setTargetMilliseconds(double milliseconds) {
  if (!validTarget(milliseconds)) return false;
  config_.targetMilliseconds = milliseconds;
  return true;
}

std::size_t FrameTimeGovernor::observe(double milliseconds) {
  if (!std::isfinite(milliseconds) || milliseconds <= 0.0) {
    ++ignored_;
    return rung_;
  }
  ++frame_;
  const std::uint64_t sinceChange = frame_ - lastChangeFrame_;
  if (sinceChange <= config_.settleFrames) return rung_;
  // A sliding window of the newest settled frames at this rung.
  if (window_.size() == config_.windowFrames) window_.erase(window_.begin());
  window_.push_back(milliseconds);
  if (window_.size() == config_.windowFrames &&
      sinceChange >= config_.minimumFramesBetweenChanges) {
    judge();
  }
  return rung_;
}

double FrameTimeGovernor::costRatioAbove(std::size_t r) const {
  if (learnedRatios_[r] > 0.0) return learnedRatios_[r];
  return config_.nominalRungCosts[r + 1] / config_.nominalRungCosts[r];
}

void FrameTimeGovernor::learnRatio(double judged) {
  // Only from the rung just left, judged just before the move: judgements further apart in time
  // may have seen different scenes.
  if (!arrivedFrom_ || rungs_[*arrivedFrom_].judgedMilliseconds <= 0.0) return;
  const std::size_t from = *arrivedFrom_;
  if (from + 1 == rung_) learnedRatios_[from] = judged / rungs_[from].judgedMilliseconds;
  if (rung_ + 1 == from) learnedRatios_[rung_] = rungs_[from].judgedMilliseconds / judged;
}

void FrameTimeGovernor::judge() {
  const double m = quantile(window_, config_.judgedQuantile);
  lastJudged_ = m;
  if (arrivedFrom_) learnRatio(m);
  arrivedFrom_.reset();
  RungRecord& here = rungs_[rung_];
  here.judgedMilliseconds = m;
  const double target = config_.targetMilliseconds;

  if (m > target * (1.0 + config_.descendMargin) && rung_ > config_.floorRung) {
    if (climbedIntoThisRung_) {
      // The climb did not hold: wait before trying this rung again, longer each time.
      here.failedClimbs = std::min(here.failedClimbs + 1, kMaxBackoffDoublings + 1);
      here.climbAllowedAtFrame =
          frame_ + (std::uint64_t(config_.backoffFrames) << (here.failedClimbs - 1));
    }
    // As many rungs down as the cost ratios say it takes to fit (at least one).
    std::size_t to = rung_ - 1;
    double predicted = m / std::max(costRatioAbove(to), 1.0);
    while (to > config_.floorRung && predicted > target * (1.0 + config_.descendMargin)) {
      --to;
      predicted /= std::max(costRatioAbove(to), 1.0);
    }
    reason_ = Reason::OverTarget;
    moveTo(to);
    return;
  }
  if (climbedIntoThisRung_) {
    here.failedClimbs = 0;  // the climb held
    climbedIntoThisRung_ = false;
  }
  if (rung_ < ceiling() && m * costRatioAbove(rung_) <= target * (1.0 - config_.climbMargin)) {
    if (frame_ < rungs_[rung_ + 1].climbAllowedAtFrame) {
      reason_ = Reason::BackingOff;
      return;
    }
    reason_ = Reason::RoomAbove;
    moveTo(rung_ + 1);
    climbedIntoThisRung_ = true;
    return;
  }
  reason_ = Reason::Holding;
}

void FrameTimeGovernor::moveTo(std::size_t rung) {
  arrivedFrom_ = rung_;
  rung_ = rung;
  lastChangeFrame_ = frame_;
  window_.clear();
  climbedIntoThisRung_ = false;
  ++changes_;
}

const char* governorReasonName(FrameTimeGovernor::Reason reason) {
  switch (reason) {
    case FrameTimeGovernor::Reason::Starting:
      return "starting";
    case FrameTimeGovernor::Reason::Holding:
      return "holding";
    case FrameTimeGovernor::Reason::OverTarget:
      return "over target";
    case FrameTimeGovernor::Reason::RoomAbove:
      return "room above";
    case FrameTimeGovernor::Reason::BackingOff:
      return "backing off";
  }
  return "unknown";
}

const PresetLadder& presetLadder() {
  // modules/clouds/docs/benchmark/results.md, "Presets": the static views' mean at 640x360.
  static const PresetLadder kLadder{{Quality::Low, Quality::Medium, Quality::High, Quality::Ultra},
                                    {3.5, 7.0, 16.6, 41.9}};
  return kLadder;
}

}  // namespace clouds
