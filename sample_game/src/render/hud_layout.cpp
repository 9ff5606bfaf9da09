#include "render/hud_layout.h"

#include <imgui.h>

#include <cmath>
#include <optional>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/ecs/frame_time.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"
#include "render/settings_panel.h"

namespace sample {

using namespace engine;

namespace {

// "Medium (governed to 33 ms)", or the preset alone when it is fixed.
void cloudPresetText(ecs::World& world, const clouds::ecs::CloudQuality& quality, char* out,
                     std::size_t size) {
  const auto* governor = world.ctx().tryGet<clouds::ecs::CloudGovernorStatus>();
  if (governor != nullptr && governor->active) {
    std::snprintf(out, size, "%s (governed to %.0f ms)", clouds::qualityName(quality.preset),
                  governor->targetMilliseconds);
  } else {
    std::snprintf(out, size, "%s", clouds::qualityName(quality.preset));
  }
}

void fullText(ecs::World& world, std::span<const gfx::TimedScope> gpuTimings) {
  double gpuTotal = 0.0;
  for (const auto& scope : gpuTimings) gpuTotal += scope.milliseconds;
  ImGui::Text("GPU %.1f ms", gpuTotal);
  for (const auto& scope : gpuTimings) {
    ImGui::Text("  %-16s %6.2f ms", scope.name, scope.milliseconds);
  }
  world.view<const render::Camera, const Aircraft>().each(
      [&](const render::Camera& camera, const Aircraft& aircraft) {
        ImGui::Text("speed %.0f m/s  altitude %.0f m", aircraft.speedMetresPerSecond,
                    camera.position.y);
      });
  if (const auto* status = world.ctx().tryGet<clouds::ecs::CloudStatus>()) {
    const clouds::FrameReport& report = status->report;
    ImGui::Text("clouds: trace %ux%u, 1 in %u px/frame, %s", report.traceExtent.width,
                report.traceExtent.height, report.tileSize * report.tileSize,
                report.historyUsed ? "reprojected" : report.resetReason);
    ImGui::Text("clouds GPU memory %.1f MiB%s", double(status->memory.totalBytes()) / 1048576.0,
                status->lastError.empty() ? "" : "  (error: see the log)");
  }
  if (const auto* governor = world.ctx().tryGet<clouds::ecs::CloudGovernorStatus>();
      governor != nullptr && governor->active) {
    ImGui::Text("governor: %s, judged %.1f ms, %llu changes", governor->reason,
                governor->judgedMilliseconds, static_cast<unsigned long long>(governor->changes));
  }
  // The weather's state now (and each region's, with how much of it holds at the camera).
  const auto* time = world.ctx().tryGet<ecs::FrameTime>();
  const double now = time ? time->elapsedSeconds : 0.0;
  const auto showPhase = [&](const std::string& label, const clouds::WeatherTimeline& timeline,
                             const std::vector<std::string>& names, const char* suffix) {
    const clouds::WeatherPhase phase = timeline.phaseAt(now);
    const auto name = [&](std::size_t key) {
      return key < names.size() ? names[key].c_str() : "?";
    };
    if (phase.from == phase.to) {
      ImGui::Text("%s: %s%s", label.c_str(), name(phase.from), suffix);
    } else {
      ImGui::Text("%s: %s -> %s (%.0f%%)%s", label.c_str(), name(phase.from), name(phase.to),
                  100.0 * double(phase.blend), suffix);
    }
  };
  std::optional<glm::dvec3> camera;
  world.view<const render::Camera>().each([&](const render::Camera& c) { camera = c.position; });
  world.view<const clouds::ecs::CloudWeather>().each([&](const clouds::ecs::CloudWeather& w) {
    showPhase("weather", w.timeline, w.keyNames, "");
    for (const clouds::ecs::RegionalWeather& r : w.regions) {
      char here[32] = "";
      if (camera) {
        std::snprintf(here, sizeof(here), ", %.0f%% here",
                      100.0 * double(clouds::weatherRegionStrength(
                                  r.place, glm::dvec2(camera->x, camera->z))));
      }
      showPhase("  " + r.name, r.timeline, r.keyNames, here);
    }
  });
  world.view<const TimeOfDay>().each([&](const TimeOfDay& t) {
    const int minutes = int(std::fmod(t.hours, 24.0) * 60.0);
    ImGui::Text("time of day %02d:%02d%s", minutes / 60, minutes % 60,
                t.hoursPerSecond > 0.0 ? " (running)" : "");
  });
  ImGui::Separator();
  ImGui::TextUnformatted("W/S throttle   Shift boost   Up/Down pitch   Left/Right roll");
  ImGui::TextUnformatted("A/D yaw   M mouse look   [ ] time of day   T run time");
  ImGui::TextUnformatted("1-5 cloud quality (Low .. Reference)   G governor on/off");
  ImGui::TextUnformatted("F2 settings panel   F12 screenshot   F1 less   Esc quit");
}

}  // namespace

glm::vec2 layOutHud(ecs::World& world, std::span<const gfx::TimedScope> gpuTimings,
                    double frameSeconds, bool full) {
  ImGui::SetNextWindowPos(ImVec2(6, 6));
  ImGui::Begin("hud", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings);
  const double fps = frameSeconds > 0.0 ? 1.0 / frameSeconds : 0.0;
  char clouds[64] = "";
  world.view<const clouds::ecs::CloudQuality>().each([&](const clouds::ecs::CloudQuality& q) {
    cloudPresetText(world, q, clouds, sizeof(clouds));
  });
  ImGui::Text("%.0f fps %.1f ms%s%s   F1 %s", fps, frameSeconds * 1000.0,
              clouds[0] != '\0' ? "   clouds " : "", clouds, full ? "less" : "help");
  if (full) fullText(world, gpuTimings);
  const ImVec2 size = ImGui::GetWindowSize();
  ImGui::End();
  return {size.x, size.y};
}

ImGuiContext* createLayoutContext(VkExtent2D extent) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGui::SetCurrentContext(context);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0;
  int height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  io.DisplaySize = ImVec2(float(extent.width), float(extent.height));
  io.DeltaTime = 1.0f / 60.0f;
  return context;
}

glm::vec2 measureHud(ecs::World& world, std::span<const gfx::TimedScope> gpuTimings,
                     VkExtent2D extent, bool full, bool panel) {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGuiContext* context = createLayoutContext(extent);
  // An auto-resizing window takes its size from its contents a frame late: lay it out twice.
  glm::vec2 size{0.0f};
  for (int frame = 0; frame < 2; ++frame) {
    ImGui::NewFrame();
    size = layOutHud(world, gpuTimings, 1.0 / 30.0, full);
    if (panel) size = layOutSettingsPanel(world, extent, true);
    ImGui::Render();
  }
  ImGui::DestroyContext(context);
  ImGui::SetCurrentContext(previous);
  return size;
}

}  // namespace sample
