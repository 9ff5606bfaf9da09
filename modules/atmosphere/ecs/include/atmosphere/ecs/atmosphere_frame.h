#pragma once
// The one place the atmosphere module's per-frame inputs are made: from the world (the camera
// and its AtmosphereQuality, the sun, the Atmosphere) and what the renderer provides for the
// frame (command buffer, size, frame number); and what the module measured, turned into the
// engine's SkyLight. They only read the world and need no GPU to be tested.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "atmosphere/atmosphere.h"
#include "engine/ecs/world.h"
#include "engine/render/scene_components.h"

namespace atmosphere::ecs {

// The parameters of the world's Atmosphere (Earth's when it has none).
atmosphere::Parameters atmosphereParameters(engine::ecs::World& world);

// The settings the camera renders the atmosphere with: its AtmosphereQuality preset, Medium
// without one.
atmosphere::Settings atmosphereSettings(engine::ecs::World& world);

// This frame's inputs.
atmosphere::FrameInputs atmosphereFrameInputs(engine::ecs::World& world, VkCommandBuffer cmd,
                                              VkExtent2D extent, std::uint64_t frameIndex);

// The engine's ambient sky light from the module's measurement: the zenith cap, the horizon
// band and the lower hemisphere.
engine::render::SkyLight skyLightFrom(const atmosphere::SkyLighting& measured);

}  // namespace atmosphere::ecs
