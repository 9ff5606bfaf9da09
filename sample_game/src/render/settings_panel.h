#pragma once
// The settings panel (F2, mouse-driven): the scene's live settings (live_settings.h) as
// sliders, the cloud quality preset, the frame-time governor and its target, and a button that
// saves the scene as the player made it. Laid out in the HUD's ImGui frame, and not at all
// while closed.
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "engine/ecs/world.h"

namespace sample {

// Where the panel's top lies (px): below the HUD's line.
inline constexpr float kSettingsPanelTop = 44.0f;

// Lays the panel out along the right edge of a window of `extent`, from kSettingsPanelTop down
// (scrolling when it is taller than the window); returns its size in pixels. Its sections
// start closed, or open with `allOpen`.
glm::vec2 layOutSettingsPanel(engine::ecs::World& world, VkExtent2D extent, bool allOpen = false);

}  // namespace sample
