#include "game/input_script.h"

#include <algorithm>

#include "engine/core/error.h"
#include "engine/core/json_reader.h"
#include "game/live_settings.h"

namespace sample {

using engine::JsonReader;

namespace {

std::vector<engine::platform::Key> readKeys(const JsonReader& r, const std::string& field) {
  std::vector<engine::platform::Key> keys;
  for (const std::string& name : r.strings(field)) {
    engine::platform::Key key{};
    if (!engine::platform::keyFromName(name, key)) r.fail(field, "unknown key \"" + name + "\"");
    keys.push_back(key);
  }
  return keys;
}

}  // namespace

InputScript InputScript::load(const std::filesystem::path& file) {
  const nlohmann::json json = JsonReader::parseFile(file);
  const JsonReader root(json, file.string());
  InputScript script;
  for (const JsonReader& e : root.objects("events")) {
    ScriptEvent event;
    event.frame = static_cast<std::uint64_t>(e.integer("frame", 0, 10'000'000));
    int actions = 0;
    if (e.has("camera")) {
      const JsonReader c = e.object("camera");
      SetCameraPose pose;
      pose.position = c.vec3("position", -1e7, 1e7);
      pose.yawDegrees = c.number("yawDegrees", -360.0, 360.0, 0.0);
      pose.pitchDegrees = c.number("pitchDegrees", -89.9, 89.9, 0.0);
      pose.rollDegrees = c.number("rollDegrees", -180.0, 180.0, 0.0);
      if (c.has("speedMetresPerSecond")) {
        pose.speedMetresPerSecond = c.number("speedMetresPerSecond", 0.0, 1000.0);
      }
      c.finish();
      event.camera = pose;
      ++actions;
    }
    if (e.has("timeOfDayHours")) {
      event.timeOfDayHours = e.number("timeOfDayHours", 0.0, 24.0);
      ++actions;
    }
    if (e.has("press")) {
      event.press = readKeys(e, "press");
      ++actions;
    }
    if (e.has("release")) {
      event.release = readKeys(e, "release");
      ++actions;
    }
    if (e.has("mouse")) {
      const glm::dvec3 m = e.vec3("mouse", -1e4, 1e4);  // [dx, dy, scroll]
      event.mouse = glm::dvec2(m.x, m.y);
      ++actions;
    }
    if (e.has("cursor")) {
      // [x, y, left button down (0 or 1)]: the free cursor, as a player drives the panel.
      const glm::dvec3 c = e.vec3("cursor", -1.0, 1e5);
      if (c.z != 0.0 && c.z != 1.0) e.fail("cursor", "the button (third value) must be 0 or 1");
      event.cursor = c;
      ++actions;
    }
    if (e.has("lightning")) {
      const JsonReader l = e.object("lightning");
      clouds::ecs::TriggerLightning strike;
      strike.energy = float(l.number("energy", 0.0, 1e3, 1.0));
      strike.kind = l.choice("kind", {"intraCloud", "ground"}, "intraCloud") == "ground"
                        ? clouds::ecs::StrikeKind::Ground
                        : clouds::ecs::StrikeKind::IntraCloud;
      l.finish();
      event.lightning = strike;
      ++actions;
    }
    if (e.has("set")) {
      const JsonReader values = e.object("set");
      for (const std::string& name : values.keys()) {
        const LiveSetting* setting = findLiveSetting(name);
        if (setting == nullptr) values.fail(name, "no such live setting (live_settings.h)");
        event.set.emplace_back(name, values.number(name, setting->min, setting->max));
      }
      values.finish();
      ++actions;
    }
    if (e.has("capture")) {
      event.capture = e.string("capture");
      const std::string& name = *event.capture;
      const bool safe = !name.empty() && name.find_first_not_of(
                                             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                             "0123456789_-") == std::string::npos;
      if (!safe) e.fail("capture", "must be a file stem of letters, digits, '_' and '-'");
      ++actions;
    }
    if (e.has("exit")) {
      event.exit = e.boolean("exit", false);
      ++actions;
    }
    if (actions != 1)
      e.fail("", "needs exactly one action besides \"frame\", found " + std::to_string(actions));
    e.finish();
    script.events_.push_back(std::move(event));
  }
  root.finish();
  std::stable_sort(script.events_.begin(), script.events_.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  return script;
}

void InputScript::apply(std::uint64_t frame, engine::platform::InputState& input,
                        engine::ecs::World& world) const {
  for (const ScriptEvent& e : events_) {
    if (e.frame != frame) continue;
    for (engine::platform::Key key : e.press) input.press(key);
    for (engine::platform::Key key : e.release) input.release(key);
    if (e.mouse) {
      input.mouseDeltaX += e.mouse->x;
      input.mouseDeltaY += e.mouse->y;
      input.mouseCaptured = true;
    }
    if (e.cursor) {
      input.cursorX = e.cursor->x;
      input.cursorY = e.cursor->y;
      input.leftButtonDown = e.cursor->z != 0.0;
      input.mouseCaptured = false;
    }
    if (e.camera) world.events<SetCameraPose>().send(*e.camera);
    if (e.timeOfDayHours) world.events<SetTimeOfDay>().send(SetTimeOfDay{*e.timeOfDayHours});
    if (e.capture) world.events<CaptureFrame>().send(CaptureFrame{*e.capture});
    if (e.lightning) world.events<clouds::ecs::TriggerLightning>().send(*e.lightning);
    for (const auto& [name, value] : e.set) applyLiveSetting(world, name, value);
    if (e.exit) world.ctx().get<ExitRequest>().requested = true;
  }
}

std::uint64_t InputScript::lastFrame() const {
  return events_.empty() ? 0 : events_.back().frame;
}

}  // namespace sample
