#pragma once
// Every frame's times and the clouds' preset (--frame-series FILE): one CSV row a frame of the
// wall time since the last frame, the latest completed frame's GPU time, the preset the camera
// rendered with, when a frame budget governs it, why and to what target (0 when not), and
// whether the clouds kept their history that frame ("reprojected", or the module's reason), and
// the exposure (EV100) the frame was shown with and what the meter read. What a governed flight
// and the exposure's steadiness are measured by.
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "engine/ecs/world.h"

namespace sample {

class FrameSeries {
 public:
  // Throws engine::Error naming the file when it cannot be written.
  explicit FrameSeries(const std::filesystem::path& file);
  // Call after each frame with its wall time (ms since the previous frame started).
  void afterFrame(std::uint64_t frame, double wallMilliseconds, engine::ecs::World& world);

 private:
  std::ofstream out_;
};

}  // namespace sample
