#pragma once
// Deterministic headless runs: a JSON script of frame-indexed events. Each frame the script
// drives the very InputState the window would fill (key presses and releases, mouse motion)
// and sends the same ECS events the game uses for camera teleports, time of day, captures and
// exit. Format (assets_src/scripts/*.json, tests/sample_game/scripts/*.json):
//   {"events": [
//     {"frame": 0, "camera": {"position": [0, 800, 0], "yawDegrees": 0, "pitchDegrees": 5}},
//     {"frame": 0, "timeOfDayHours": 15.5},
//     {"frame": 1, "press": ["W", "Up"]},  {"frame": 9, "release": ["Up"]},
//     {"frame": 4, "mouse": [12, -3, 0]},  ([dx, dy, scroll] in pixels; scroll is not used yet)
//     {"frame": 5, "cursor": [420, 80, 1]},  (the free cursor [x, y] in pixels, button down 1/0)
//     {"frame": 12, "capture": "ground_view"},
//     {"frame": 10, "lightning": {"energy": 1.0, "kind": "ground"}},  (a storm's scene only)
//     {"frame": 0, "set": {"clouds.coverage": 0.7, "sun.timeOfDayHours": 9}},  (live_settings.h)
//     {"frame": 13, "exit": true}]}
// Every event has "frame" and exactly one action.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "clouds/ecs/lightning.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"
#include "game/game_components.h"

namespace sample {

struct ScriptEvent {
  std::uint64_t frame = 0;
  std::optional<SetCameraPose> camera;
  std::optional<double> timeOfDayHours;
  std::vector<engine::platform::Key> press;
  std::vector<engine::platform::Key> release;
  std::optional<glm::dvec2> mouse;
  std::optional<glm::dvec3> cursor;  // x, y (pixels), left button down (1) or up (0)
  std::optional<std::string> capture;
  std::optional<clouds::ecs::TriggerLightning> lightning;
  std::vector<std::pair<std::string, double>> set;  // live settings (live_settings.h), by name
  bool exit = false;
};

class InputScript {
 public:
  // Throws engine::Error "<file>: events[i].<field>: <reason>" for malformed scripts.
  static InputScript load(const std::filesystem::path& file);

  // Applies this frame's events: keys and mouse into `input` (which persists across frames,
  // like a keyboard), everything else as events into `world`.
  void apply(std::uint64_t frame, engine::platform::InputState& input,
             engine::ecs::World& world) const;
  // The frame of the last event (a run needs at least this many frames + 1).
  std::uint64_t lastFrame() const;
  const std::vector<ScriptEvent>& events() const { return events_; }

 private:
  std::vector<ScriptEvent> events_;  // sorted by frame, stable
};

}  // namespace sample
