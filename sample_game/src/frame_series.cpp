#include "frame_series.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "engine/ecs/frame_time.h"
#include "engine/render/exposure.h"
#include "engine/render/gpu_frame_time.h"
#include "game/exposure_control.h"

namespace sample {

FrameSeries::FrameSeries(const std::filesystem::path& file) : out_(file) {
  if (!out_) throw engine::Error(file.string() + ": cannot write the frame series");
  out_ << "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms,clouds_history,ev100,"
          "metered_ev100\n";
}

void FrameSeries::afterFrame(std::uint64_t frame, double wallMilliseconds,
                             engine::ecs::World& world) {
  const auto* gpu = world.ctx().tryGet<engine::render::GpuFrameTime>();
  const char* preset = "";
  world.view<const clouds::ecs::CloudQuality>().each(
      [&](const clouds::ecs::CloudQuality& q) { preset = clouds::qualityName(q.preset); });
  const auto* governor = world.ctx().tryGet<clouds::ecs::CloudGovernorStatus>();
  const bool governed = governor != nullptr && governor->active;
  // The clouds' history this frame: "reprojected", or why it was not (commas made safe).
  std::string history = "none";
  if (const auto* clouds = world.ctx().tryGet<clouds::ecs::CloudStatus>()) {
    history = clouds->report.historyUsed ? "reprojected" : clouds->report.resetReason;
    std::replace(history.begin(), history.end(), ',', ';');
  }
  char row[192];
  std::snprintf(row, sizeof(row), "%llu,%.4f,%.3f,%.3f,%s,%s,%.3f,",
                static_cast<unsigned long long>(frame),
                world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds, wallMilliseconds,
                gpu != nullptr && gpu->measured ? gpu->milliseconds : 0.0, preset,
                governed ? governor->reason : "off", governed ? governor->targetMilliseconds : 0.0);
  // The exposure the frame was shown with and what the meter read (exposure_control.h).
  const float ev100 = world.ctx().get<engine::render::Exposure>().ev100;
  char exposure[48];
  std::snprintf(exposure, sizeof(exposure), ",%.4f,%.4f\n", ev100, meteredEv100(world));
  out_ << row << history << exposure;
}

}  // namespace sample
