#pragma once
// The fixed phases a frame runs through, in order.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace engine::ecs {

/// Frame phases, run in declaration order by Scheduler::runFrame(). Systems pick the phase
/// that matches what they read and write, so ordering between features needs no explicit
/// dependencies.
enum class Phase : std::uint8_t {
  /// Poll the platform (window, keyboard, mouse, scripted input) and turn it into events and
  /// input state. Nothing here reads simulation state.
  Input,
  /// Game logic and simulation at the frame's time step: movement, camera, weather and
  /// time-of-day. The only phase that should change gameplay components.
  Simulate,
  /// Derive render data from the simulated state: matrices, culling, per-frame uniform
  /// contents, resource uploads. Reads simulation components, writes render-side data.
  PreRender,
  /// Record and submit GPU work for the frame (frame graph setup and execution).
  Render,
  /// After submission: present, frame statistics, debug output, end-of-frame bookkeeping.
  PostRender,
};

inline constexpr std::size_t kPhaseCount = 5;

/// Every phase in run order.
inline constexpr std::array<Phase, kPhaseCount> kAllPhases = {
    Phase::Input, Phase::Simulate, Phase::PreRender, Phase::Render, Phase::PostRender};

/// "Input", "Simulate", ... for logs and debug listings.
constexpr std::string_view phaseName(Phase phase) noexcept {
  switch (phase) {
    case Phase::Input:
      return "Input";
    case Phase::Simulate:
      return "Simulate";
    case Phase::PreRender:
      return "PreRender";
    case Phase::Render:
      return "Render";
    case Phase::PostRender:
      return "PostRender";
  }
  return "?";
}

}  // namespace engine::ecs
