#include "render/settings_panel.h"

#include <imgui.h>

#include <array>
#include <string>
#include <string_view>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "game/cloud_quality_controls.h"
#include "game/live_settings.h"

namespace sample {
namespace {

using engine::ecs::World;

constexpr float kPanelWidth = 250.0f;  // px

// The live settings under a header per scene section ("clouds", "lightning", "sun",
// "exposure", the cloud preset's knobs), effects as switches, closed until opened: a smaller panel
// costs less to draw (on a CPU device, per pixel).
void liveSliders(World& world, bool allOpen) {
  auto& live = world.ctx().get<LiveScene>();
  std::string_view section;
  bool open = false;
  for (const LiveSetting& setting : liveSettings()) {
    if (!setting.available(live)) continue;
    const std::string_view name = setting.name;
    const std::string_view group = name.substr(0, name.find('.'));
    if (group != section) {
      section = group;
      // The camera's entries are its cloud preset's knobs (live_settings.cpp).
      const std::string header = group == "camera" ? "cloud preset's knobs" : std::string(group);
      open = ImGui::CollapsingHeader(header.c_str(), allOpen ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    }
    if (!open) continue;
    float value = float(setting.get(live.scene));
    bool changed = false;
    if (setting.isSwitch) {
      bool on = value >= 0.5f;
      changed = ImGui::Checkbox(setting.label, &on);
      value = on ? 1.0f : 0.0f;
    } else {
      changed = ImGui::SliderFloat(setting.label, &value, float(setting.min), float(setting.max));
    }
    if (changed) {
      try {
        applyLiveSetting(world, setting.name, double(value));
        live.lastRefusal.clear();
      } catch (const engine::Error& error) {
        live.lastRefusal = error.what();
      }
    }
  }
}

void qualityControls(World& world) {
  static constexpr std::array<clouds::Quality, 5> kPresets = {
      clouds::Quality::Low, clouds::Quality::Medium, clouds::Quality::High, clouds::Quality::Ultra,
      clouds::Quality::Reference};
  world.view<clouds::ecs::CloudQuality>().each(
      [&](engine::ecs::Entity camera, clouds::ecs::CloudQuality& quality) {
        auto* budget = world.tryGet<clouds::ecs::CloudFrameBudget>(camera);
        bool governed = budget != nullptr;
        if (ImGui::Checkbox("governor", &governed)) {
          if (governed) {
            world.emplace<clouds::ecs::CloudFrameBudget>(
                camera, playerFrameBudget(clouds::ecs::CloudFrameBudget{}.targetMilliseconds));
          } else {
            world.remove<clouds::ecs::CloudFrameBudget>(camera);
          }
          return;  // the budget changed under `budget`: the next frame shows it
        }
        if (budget != nullptr) {
          float target = float(budget->targetMilliseconds);
          if (ImGui::SliderFloat("target (ms)", &target, 5.0f, 200.0f)) {
            budget->targetMilliseconds = double(target);
          }
        }
        if (ImGui::BeginCombo("clouds", clouds::qualityName(quality.preset))) {
          for (clouds::Quality preset : kPresets) {
            if (ImGui::Selectable(clouds::qualityName(preset), preset == quality.preset)) {
              quality = clouds::ecs::CloudQuality{preset};          // as it is, no knobs tuned
              world.remove<clouds::ecs::CloudFrameBudget>(camera);  // a fixed preset
            }
          }
          ImGui::EndCombo();
        }
      });
}

}  // namespace

glm::vec2 layOutSettingsPanel(World& world, VkExtent2D extent, bool allOpen) {
  constexpr float kMargin = 6.0f;  // px
  ImGui::SetNextWindowPos(ImVec2(float(extent.width) - kPanelWidth - kMargin, kSettingsPanelTop),
                          ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(kPanelWidth, 0.0f),
      ImVec2(kPanelWidth, float(extent.height) - kSettingsPanelTop - kMargin));
  ImGui::Begin("settings (F2)", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(kPanelWidth * 0.5f);
  syncLiveScene(world);  // the sliders show what the governor and the keys changed too
  qualityControls(world);
  ImGui::Separator();
  liveSliders(world, allOpen);
  ImGui::Separator();
  auto& live = world.ctx().get<LiveScene>();
  if (ImGui::Button("save scene")) saveLiveScene(world);
  ImGui::SameLine();
  if (ImGui::Button("from here")) saveLiveScene(world, SavedStart::Here);
  ImGui::Text("to %s", live.saveTo.filename().string().c_str());
  if (!live.lastSave.empty()) ImGui::TextWrapped("%s", live.lastSave.c_str());
  if (!live.lastRefusal.empty()) ImGui::TextWrapped("%s", live.lastRefusal.c_str());
  if (!live.reloadStatus.empty()) ImGui::TextWrapped("%s", live.reloadStatus.c_str());
  ImGui::PopItemWidth();
  const ImVec2 size = ImGui::GetWindowSize();
  ImGui::End();
  return {size.x, size.y};
}

}  // namespace sample
