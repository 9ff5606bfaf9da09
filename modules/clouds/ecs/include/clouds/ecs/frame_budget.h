#pragma once
// A camera's frame budget: on a camera entity beside its CloudQuality, a frame-time governor
// (clouds/frame_time_governor.h) picks the preset along clouds::presetLadder() that holds the
// frame's time at the target: its GPU time (engine::render::GpuFrameTime, which the renderer
// publishes) or its wall-clock time (engine::ecs::WallFrameTime, which the frame loop
// publishes). The clouds' feature prepares every preset between the floor and the ceiling ahead,
// so a change builds no pipeline mid-flight. Removing the component hands the preset back to
// whoever sets it (the sample's number keys); adding it again starts a new governor from the
// camera's preset.
#include <cstdint>
#include <span>
#include <string>

#include "clouds/clouds.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"

namespace clouds::ecs {

// Which time a frame budget holds.
enum class FrameTimeSource : std::uint8_t {
  GpuFrame,   // the frame graph's timestamped GPU time
  WallFrame,  // the frame loop's start-to-start time: what the player sees
};

struct CloudFrameBudget {
  double targetMilliseconds = 1000.0 / 30.0;         // (0, 1e5]: time per frame
  clouds::Quality floor = clouds::Quality::Low;      // the cheapest preset it may choose
  clouds::Quality ceiling = clouds::Quality::Ultra;  // the dearest (Reference is no rung)
  FrameTimeSource source = FrameTimeSource::GpuFrame;
  double judgedQuantile = 0.5;  // [0.5, 0.99]: FrameTimeGovernorConfig::judgedQuantile
};

// Context singleton the governing system keeps up to date, for HUDs and logs.
struct CloudGovernorStatus {
  bool active = false;                               // a camera has a budget and its governor runs
  clouds::Quality preset = clouds::Quality::Medium;  // its choice
  double targetMilliseconds = 0.0;
  double judgedMilliseconds = 0.0;  // what its last judgement saw (0 before the first)
  const char* reason = "";          // governorReasonName() of its last judgement
  std::uint64_t changes = 0;        // preset changes so far
  std::string error;                // a budget it refused, the field named (then it does not run)
};

// Adds the "cloud frame budget" system (PreRender): feeds each newly measured frame's time
// (of the budget's source) to the governor of the camera with a CloudFrameBudget and sets its
// CloudQuality.
void installFrameBudget(engine::ecs::World& world, engine::ecs::Scheduler& scheduler);

// The presets the budgeted camera may switch between, cheapest first (a view of
// clouds::presetLadder(): nothing is allocated, as it is asked every frame); empty without a
// budget (or with one the governor refuses).
std::span<const clouds::Quality> governedPresets(engine::ecs::World& world);

}  // namespace clouds::ecs
