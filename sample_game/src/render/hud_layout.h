#pragma once
// What the HUD says and how much of the window it takes. By default one line in a corner:
// the frame rate, the clouds' preset (and the governor's target when it picks it) and the help
// key; F1 adds the controls, every pass's GPU time and the flight's numbers.
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>
#include <span>

#include "engine/ecs/world.h"
#include "engine/gfx/gpu_timer.h"

struct ImGuiContext;

namespace sample {

// Lays the HUD's window out in the current ImGui frame; returns its size in pixels.
// `frameSeconds`: the smoothed wall time of a frame (0: not known yet).
glm::vec2 layOutHud(engine::ecs::World& world, std::span<const engine::gfx::TimedScope> gpuTimings,
                    double frameSeconds, bool full);

// A current ImGui context to lay the HUD out in without a GPU (its font atlas built, the
// display `extent`); the previous one is the caller's to restore, this one to destroy.
ImGuiContext* createLayoutContext(VkExtent2D extent);

// The size the HUD takes in a window of `extent`, laid out in an ImGui context of its own
// (for tests; no GPU). `panel`: the settings panel's size instead.
glm::vec2 measureHud(engine::ecs::World& world, std::span<const engine::gfx::TimedScope> gpuTimings,
                     VkExtent2D extent, bool full, bool panel = false);

}  // namespace sample
