#pragma once
// Keyboard and mouse state in engine terms (no GLFW types), filled by the window each frame
// or by a script in headless runs: both feed the same InputState into the game.
#include <array>
#include <cstdint>
#include <string_view>

namespace engine::platform {

enum class Key : std::uint8_t {
  W,
  A,
  S,
  D,
  Q,
  E,
  R,
  F,
  T,
  G,
  H,
  P,
  C,
  V,
  B,
  N,
  M,
  Up,
  Down,
  Left,
  Right,
  Space,
  LeftShift,
  LeftControl,
  Tab,
  Escape,
  Enter,
  Num1,
  Num2,
  Num3,
  Num4,
  Num5,
  Num6,
  Num7,
  Num8,
  Num9,
  Num0,
  Minus,
  Equal,
  LeftBracket,
  RightBracket,
  F1,
  F2,
  F3,
  F4,
  F5,
  F12,
  Count
};

// "W", "Up", "LeftShift", "F12", "1", "[" ... (the names scripts use). Returns false for names
// that are not keys.
bool keyFromName(std::string_view name, Key& key);
const char* keyName(Key key);

struct InputState {
  std::array<bool, static_cast<std::size_t>(Key::Count)> down{};
  std::array<bool, static_cast<std::size_t>(Key::Count)> pressed{};  // went down this frame
  double mouseDeltaX = 0.0;                                          // pixels moved this frame
  double mouseDeltaY = 0.0;
  double scrollY = 0.0;
  bool mouseCaptured = false;
  // The free cursor (not captured), in window pixels from the top left; -1 when unknown.
  double cursorX = -1.0;
  double cursorY = -1.0;
  bool leftButtonDown = false;

  bool isDown(Key key) const { return down[static_cast<std::size_t>(key)]; }
  bool wasPressed(Key key) const { return pressed[static_cast<std::size_t>(key)]; }
  void press(Key key) {
    if (!isDown(key)) pressed[static_cast<std::size_t>(key)] = true;
    down[static_cast<std::size_t>(key)] = true;
  }
  void release(Key key) { down[static_cast<std::size_t>(key)] = false; }
  // Clears per-frame edges and deltas; held keys stay down.
  void beginFrame() {
    pressed.fill(false);
    mouseDeltaX = mouseDeltaY = scrollY = 0.0;
  }
};

}  // namespace engine::platform
