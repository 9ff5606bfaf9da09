#include "clouds/ecs/frame_budget.h"

#include <algorithm>
#include <memory>
#include <optional>

#include "clouds/ecs/cloud_components.h"
#include "clouds/frame_time_governor.h"
#include "engine/core/log.h"
#include "engine/ecs/frame_time.h"
#include "engine/render/gpu_frame_time.h"
#include "engine/render/scene_components.h"

namespace clouds::ecs {

namespace {

// The budget's floor and ceiling as rungs of the preset ladder, or why they are not.
struct BudgetRungs {
  std::size_t floor = 0;
  std::size_t ceiling = 0;
  std::string error;
};

BudgetRungs rungsOf(const CloudFrameBudget& budget, const clouds::PresetLadder& ladder) {
  const auto rungOf = [&](clouds::Quality preset) -> std::optional<std::size_t> {
    const auto it = std::find(ladder.presets.begin(), ladder.presets.end(), preset);
    if (it == ladder.presets.end()) return std::nullopt;
    return std::size_t(it - ladder.presets.begin());
  };
  BudgetRungs rungs;
  const auto floor = rungOf(budget.floor);
  const auto ceiling = rungOf(budget.ceiling);
  if (!floor || !ceiling) {
    rungs.error = std::string("CloudFrameBudget.") + (!floor ? "floor" : "ceiling") + ": " +
                  clouds::qualityName(!floor ? budget.floor : budget.ceiling) +
                  " is no rung of the preset ladder (Low, Medium, High, Ultra)";
    return rungs;
  }
  rungs.floor = *floor;
  rungs.ceiling = *ceiling;
  return rungs;
}

// The budgeted camera's budget and quality (the first camera with both), if any.
struct Budgeted {
  const CloudFrameBudget* budget = nullptr;
  CloudQuality* quality = nullptr;
};

Budgeted budgetedCamera(engine::ecs::World& world) {
  Budgeted found;
  world.view<const engine::render::Camera, const CloudFrameBudget, CloudQuality>().each(
      [&](const engine::render::Camera&, const CloudFrameBudget& budget, CloudQuality& quality) {
        if (found.budget == nullptr) found = Budgeted{&budget, &quality};
      });
  return found;
}

// The newest measured frame of a budget's source, if one has been measured.
struct MeasuredFrame {
  double milliseconds = 0.0;
  std::uint64_t index = 0;
};

std::optional<MeasuredFrame> latestFrame(engine::ecs::World& world, FrameTimeSource source) {
  if (source == FrameTimeSource::WallFrame) {
    const auto* wall = world.ctx().tryGet<engine::ecs::WallFrameTime>();
    if (wall == nullptr || !wall->measured) return std::nullopt;
    return MeasuredFrame{wall->milliseconds, wall->frameIndex};
  }
  const auto* gpu = world.ctx().tryGet<engine::render::GpuFrameTime>();
  if (gpu == nullptr || !gpu->measured) return std::nullopt;
  return MeasuredFrame{gpu->milliseconds, gpu->frameIndex};
}

// What the system keeps between frames: the governor, and what it was made for.
struct GovernorState {
  const clouds::PresetLadder& ladder = clouds::presetLadder();
  std::optional<clouds::FrameTimeGovernor> governor;
  clouds::Quality floor{};
  clouds::Quality ceiling{};
  double judgedQuantile = 0.5;
  FrameTimeSource source = FrameTimeSource::GpuFrame;
  std::optional<std::uint64_t> lastMeasuredFrame;
  std::string refused;  // the budget last refused (logged once)

  void govern(engine::ecs::World& world) {
    auto& status = world.ctx().get<CloudGovernorStatus>();
    const Budgeted camera = budgetedCamera(world);
    if (camera.budget == nullptr) {
      governor.reset();
      status = CloudGovernorStatus{};
      return;
    }
    const CloudFrameBudget& budget = *camera.budget;
    // A new range, quantile or clock: the frames judged so far are another budget's.
    if (!governor || budget.floor != floor || budget.ceiling != ceiling ||
        budget.judgedQuantile != judgedQuantile || budget.source != source) {
      if (!start(budget, camera.quality->preset, status)) return;
    }
    if (budget.targetMilliseconds != governor->config().targetMilliseconds &&
        !governor->setTargetMilliseconds(budget.targetMilliseconds)) {
      refuse("CloudFrameBudget.targetMilliseconds: must be in (0, 1e5] ms", status);
      return;
    }
    if (const std::optional<MeasuredFrame> time = latestFrame(world, budget.source);
        time && lastMeasuredFrame != time->index) {
      governor->observe(time->milliseconds);
      lastMeasuredFrame = time->index;
    }
    // The ladder's rungs are the presets as they are: hand-tuned knobs are a fixed preset's.
    camera.quality->preset = ladder.presets[governor->rung()];
    camera.quality->knobs = {};
    status.active = true;
    status.preset = camera.quality->preset;
    status.targetMilliseconds = governor->config().targetMilliseconds;
    status.judgedMilliseconds = governor->lastJudgedMilliseconds();
    status.reason = clouds::governorReasonName(governor->reason());
    status.changes = governor->changes();
    status.error.clear();
  }

  bool start(const CloudFrameBudget& budget, clouds::Quality current, CloudGovernorStatus& status) {
    governor.reset();
    const BudgetRungs rungs = rungsOf(budget, ladder);
    if (!rungs.error.empty()) {
      refuse(rungs.error, status);
      return false;
    }
    clouds::FrameTimeGovernorConfig config;
    config.targetMilliseconds = budget.targetMilliseconds;
    config.nominalRungCosts = ladder.nominalMilliseconds;
    config.floorRung = rungs.floor;
    config.ceilingRung = rungs.ceiling;
    config.judgedQuantile = budget.judgedQuantile;
    // From the camera's preset (the Reference, no rung, from the top).
    const auto it = std::find(ladder.presets.begin(), ladder.presets.end(), current);
    config.startRung = it != ladder.presets.end() ? std::size_t(it - ladder.presets.begin())
                                                  : ladder.presets.size() - 1;
    std::string error;
    governor = clouds::FrameTimeGovernor::create(config, &error);
    if (!governor) {
      refuse(error, status);
      return false;
    }
    floor = budget.floor;
    ceiling = budget.ceiling;
    judgedQuantile = budget.judgedQuantile;
    source = budget.source;
    lastMeasuredFrame.reset();  // the two clocks count frames differently
    return true;
  }

  void refuse(const std::string& error, CloudGovernorStatus& status) {
    governor.reset();
    status = CloudGovernorStatus{};
    status.error = error;
    if (error != refused) engine::log::error("cloud frame budget refused: " + error);
    refused = error;
  }
};

}  // namespace

void installFrameBudget(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  world.ctx().emplaceOrReplace<CloudGovernorStatus>();
  scheduler.add(
      engine::ecs::Phase::PreRender, "cloud frame budget",
      [state = std::make_shared<GovernorState>()](engine::ecs::World& w) { state->govern(w); });
}

std::span<const clouds::Quality> governedPresets(engine::ecs::World& world) {
  const Budgeted camera = budgetedCamera(world);
  if (camera.budget == nullptr) return {};
  const clouds::PresetLadder& ladder = clouds::presetLadder();
  const BudgetRungs rungs = rungsOf(*camera.budget, ladder);
  if (!rungs.error.empty() || rungs.floor > rungs.ceiling) return {};
  return std::span(ladder.presets).subspan(rungs.floor, rungs.ceiling - rungs.floor + 1);
}

}  // namespace clouds::ecs
