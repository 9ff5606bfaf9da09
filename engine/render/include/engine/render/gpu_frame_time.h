#pragma once
// Context singleton the renderer keeps up to date: the GPU time of its latest completed frame,
// for systems that adapt to it (a quality governor) and for HUDs.
#include <cstdint>

namespace engine::render {

struct GpuFrameTime {
  double milliseconds = 0.0;     // the sum of the frame graph's passes' timestamped times
  std::uint64_t frameIndex = 0;  // the frame measured
  bool measured = false;         // false until the first frame has completed
};

}  // namespace engine::render
