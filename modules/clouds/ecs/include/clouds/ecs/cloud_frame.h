#pragma once
// The one place the clouds module's per-frame inputs are made: from the world (the camera and
// its CloudQuality, the sun and what the air lets through of it, the sky light, the cloud
// layer, the frame time) and what the
// renderer provides for the frame (command buffer, size, depth). They only read the world
// (it is non-const because views create missing storages), and need no GPU to be tested.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "clouds/weather.h"
#include "engine/ecs/world.h"

namespace clouds::ecs {

// What the renderer hands the clouds' pass for this frame.
struct HostFrame {
  VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
  VkExtent2D extent{0, 0};
  VkImageView depthView = VK_NULL_HANDLE;  // none when the scene has no geometry
  VkImageLayout depthLayout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
  VkImageView weatherView = VK_NULL_HANDLE;  // the layer's painted weather map, if it has one
  // A second painted map weatherView blends towards, by weatherBlend in [0, 1] (none: no blend).
  VkImageView weatherBlendView = VK_NULL_HANDLE;
  float weatherBlend = 0.0f;
  // What a feature that draws the sky provides (contracts/ecs/frame_entries.h), if one does:
  // the sky's radiance for the clouds' ambient, and the haze for their radiance. Both GENERAL.
  VkImageView skyRadianceView = VK_NULL_HANDLE;
  VkImageView aerialPerspectiveView = VK_NULL_HANDLE;
  std::uint32_t aerialPerspectiveSlices = 0;
  float aerialPerspectiveRangeMetres = 0.0f;
  // The haze's scattering at the ground and Mie asymmetry (god rays weigh its Mie share).
  glm::vec3 hazeRayleighPerMetre{0.0f};
  glm::vec3 hazeMiePerMetre{0.0f};
  float hazeMiePhaseG = 0.8f;
  std::uint64_t frameIndex = 0;
};

// The weather now: the CloudWeather's state at FrameTime's clock, if the layer has one.
std::optional<clouds::WeatherState> currentWeather(engine::ecs::World& world);
// The CloudWeather's regions at FrameTime's clock, each with its look now (none without one).
std::vector<clouds::WeatherRegion> currentWeatherRegions(engine::ecs::World& world);
// Where the CloudWeather's timeline is at FrameTime's clock, when its keys paint weather maps
// (CloudWeather::keyWeatherMaps): the key whose map shows and the one it blends into.
std::optional<clouds::WeatherPhase> paintedWeatherPhase(engine::ecs::World& world);

// The settings the camera renders the layer with: the layer's look under the camera's
// CloudQuality preset and knobs, or the layer's settings as they are without one.
clouds::Settings cloudSettings(engine::ecs::World& world);
// The settings the layer's look takes under `preset` (what cloudSettings() gives a camera
// with that CloudQuality): for preparing a preset before a camera switches to it.
clouds::Settings cloudSettingsFor(engine::ecs::World& world, clouds::Quality preset);

// Flashes that may glow at once in a scene with a storm (Settings::lightningFlashes).
inline constexpr std::uint32_t kLightningFlashes = 8;

// The flashes of the strikes in progress (ActiveLightning) at this frame's time, at their
// return strokes' brightness, the brightest `capacity` of them.
std::vector<clouds::LightningFlash> lightningFlashes(engine::ecs::World& world,
                                                     std::uint32_t capacity);

// Bolt pieces that may be drawn at once in a scene with a storm (Settings::
// lightningBoltSegments): two bolts.
inline constexpr std::uint32_t kLightningBoltSegments = 128;

// The bolts of the ground discharges in progress (ActiveLightning) at this frame's time, at
// their return strokes' brightness: whole bolts, oldest first, as many as `capacity` pieces
// hold.
std::vector<clouds::LightningBoltSegment> lightningBolts(engine::ecs::World& world,
                                                         std::uint32_t capacity);

// The hero clouds this frame draws: the entities with a clouds::HeroCloud, the `capacity`
// nearest to `cameraPosition` (world metres), nearest first. An entity that also has a
// clouds::HeroCloudLifecycle lives it on FrameTime's clock; while its life leaves it empty
// (not yet grown, or dissipated) it is not drawn. One whose lifecycle is out of range
// (validateHeroCloudLifecycle()) is not drawn either; `problem`, when given and empty, receives
// the first such message.
std::vector<clouds::HeroCloud> heroClouds(engine::ecs::World& world,
                                          const glm::dvec3& cameraPosition, std::uint32_t capacity,
                                          std::string* problem = nullptr);

// This frame's inputs. The module remembers the previous camera itself. The sun reaching the
// clouds is the Sun through the world's SunTransmittance at the layer's middle altitude (the
// atmosphere's, when the scene has one: sunset clouds are lit by the sun its air reddens); their
// ambient is the sky's radiance when the host provides it, else the SkyLight singleton; the
// terrain is the TerrainHeightfield singleton, when the scene publishes one.
clouds::FrameInputs cloudFrameInputs(engine::ecs::World& world, const HostFrame& host);

}  // namespace clouds::ecs
