#pragma once
// Scene hot-reload: "scene hot reload" (Input) looks at the scene file every
// kHotReloadCheckFrames frames and, when it has changed, reads it again. A file that does not
// load is reported (LiveScene::reloadStatus, the settings panel and the log) and the running
// scene kept. One that loads is applied where it changed and can be while flying: the cloud
// layer's look (the whole layer, over what the panel changed in it), the sun and its clock,
// the exposure, the fog, the water's level, colour and clarity, the camera's cloud preset and
// frame budget. Anything else (terrain, atmosphere, storm, hero clouds, the camera's start,
// shadows, god rays or water switched) waits for a restart, and the status says so.
#include <cstdint>
#include <filesystem>
#include <string>

#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "scene/scene_description.h"

namespace sample {

inline constexpr std::uint64_t kHotReloadCheckFrames = 10;

// Watches `scene.file` (as the command line left it: the file itself is read again).
void installSceneHotReload(engine::ecs::Scheduler& scheduler, const SceneDescription& scene);

// Applies what the scene file changed from `before` to `next` to the world and the running
// scene (LiveScene's), as far as it can be live; what the player changed elsewhere stays.
// Returns the status ("applied", or "applied; ... at restart").
std::string applyReloadedScene(engine::ecs::World& world, const SceneDescription& before,
                               const SceneDescription& next);

}  // namespace sample
