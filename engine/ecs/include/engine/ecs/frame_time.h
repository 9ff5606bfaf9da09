#pragma once
// Frame timing, kept as a World context singleton and set by whoever drives the frame loop.
#include <cstdint>

namespace engine::ecs {

/// Time of the frame being run. The Scheduler does not own time: the caller (the app's main
/// loop, or a test with a fixed step) writes this into world.ctx() before each runFrame(), so
/// real-time and deterministic fixed-step runs go through the same systems.
struct FrameTime {
  double deltaSeconds = 0.0;     // time step of this frame, seconds, >= 0
  double elapsedSeconds = 0.0;   // sum of all steps up to and including this frame, seconds
  std::uint64_t frameIndex = 0;  // 0 for the first frame

  /// The frame after this one, with a step of `dt` seconds.
  constexpr FrameTime next(double dt) const noexcept {
    return FrameTime{dt, elapsedSeconds + dt, frameIndex + 1};
  }
};

/// How long the previous frame took on the wall clock, start to start (what a player sees as
/// the frame rate: the GPU's work, the CPU's and the present together). Set by a frame loop that
/// measures it, beside FrameTime; systems that adapt to it (a quality governor) read it.
struct WallFrameTime {
  double milliseconds = 0.0;     // the frame `frameIndex` took
  std::uint64_t frameIndex = 0;  // the frame measured
  bool measured = false;         // false until a frame has been measured
};

}  // namespace engine::ecs
