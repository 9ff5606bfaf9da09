#pragma once
// The scene's values a player tunes while flying: the settings panel's sliders and a script's
// "set" events go through this one table. Each entry names its scene JSON path and range and
// writes both the live world and the scene as it will be saved (LiveScene), so that a saved
// scene loads back to the very frames the player saw.
#include <filesystem>
#include <span>
#include <string_view>

#include "engine/ecs/world.h"
#include "scene/scene_description.h"

namespace sample {

struct LiveScene;

struct LiveSetting {
  const char* name;   // its scene JSON path, e.g. "clouds.coverage"
  const char* label;  // the panel's
  double min;         // the slider's range (within what the scene file accepts)
  double max;
  // The scene has what it tunes (an effect's switch: the scene was loaded with the effect, so
  // its pipelines and passes exist and turning it back on costs no hitch).
  bool (*available)(const LiveScene& live);
  double (*get)(const SceneDescription& scene);
  // Writes `value` (within [min, max]) into the world's components and into `scene`.
  void (*set)(engine::ecs::World& world, SceneDescription& scene, double value);
  bool isSwitch = false;  // on (1) or off (0): the panel shows a checkbox
};

std::span<const LiveSetting> liveSettings();
const LiveSetting* findLiveSetting(std::string_view name);

// Context singleton: the scene as loaded with the player's changes, what a save writes, and
// where (--save-scene, else "edited_scene.json").
struct LiveScene {
  SceneDescription scene;
  std::filesystem::path saveTo;
  std::string lastSave;      // what the last save said (the path written, or why it failed)
  std::string reloadStatus;  // what the last hot reload did, or why the file did not load
  std::string lastRefusal;   // the last value the panel could not take, and why
  // The scene as it loaded: what the world was built with (the effects a switch may turn back
  // on without building anything).
  SceneDescription loaded;
};

// Applies `value` to the setting named `name`. Throws engine::Error naming it when there is no
// such setting, the scene has nothing it tunes, or the value is out of its range.
void applyLiveSetting(engine::ecs::World& world, std::string_view name, double value);

// Folds into LiveScene's scene what the world changed on its own: the clock, the camera's
// cloud preset, its knobs and its frame budget (none when it has none; the governor and the
// number keys change them). The panel calls it before it shows the values.
void syncLiveScene(engine::ecs::World& world);
// Where a saved scene starts its flight: where the scene did, or where the camera is now (its
// position, heading, pitch and airspeed; the roll levelled, as a scene's start has none).
enum class SavedStart { SceneStart, Here };
// The scene to save: LiveScene's, synchronised (syncLiveScene()).
SceneDescription sceneToSave(engine::ecs::World& world, SavedStart start = SavedStart::SceneStart);
// Writes sceneToSave() to LiveScene::saveTo and records the outcome in LiveScene::lastSave.
// Returns false (nothing thrown) when it cannot be written.
bool saveLiveScene(engine::ecs::World& world, SavedStart start = SavedStart::SceneStart);

}  // namespace sample
