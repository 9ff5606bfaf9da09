#include "engine/platform/input.h"

namespace engine::platform {
namespace {

constexpr const char* kNames[] = {
    "W",     "A",     "S",         "D",           "Q",   "E",      "R",     "F",  "T",    "G",
    "H",     "P",     "C",         "V",           "B",   "N",      "M",     "Up", "Down", "Left",
    "Right", "Space", "LeftShift", "LeftControl", "Tab", "Escape", "Enter", "1",  "2",    "3",
    "4",     "5",     "6",         "7",           "8",   "9",      "0",     "-",  "=",    "[",
    "]",     "F1",    "F2",        "F3",          "F4",  "F5",     "F12",
};
static_assert(std::size(kNames) == static_cast<std::size_t>(Key::Count),
              "every key needs a script name");

}  // namespace

bool keyFromName(std::string_view name, Key& key) {
  for (std::size_t i = 0; i < std::size(kNames); ++i) {
    if (name == kNames[i]) {
      key = static_cast<Key>(i);
      return true;
    }
  }
  return false;
}

const char* keyName(Key key) {
  const auto i = static_cast<std::size_t>(key);
  return i < std::size(kNames) ? kNames[i] : "?";
}

}  // namespace engine::platform
