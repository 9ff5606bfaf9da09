#pragma once
// What a change of each Settings field does to the module's state, as one table with a row for
// every field: whether it makes the clouds look different (the temporal history is dropped and
// the shadow map's cascades remade), whether it changes how the shadow map is made (its
// cascades remade), or neither, and then why not. The temporal state and the shadow cascades
// ask the table; the module's tests hold it to clouds.h (every declared field has exactly one
// row) and to the behaviour (a change of a field resets what its row says, and nothing else),
// so a new field that nobody classified fails the suite instead of silently keeping a stale
// history.
#include <cstdint>
#include <span>

#include "clouds/clouds.h"

namespace clouds::detail {

// Bits of SettingEffect::effects.
inline constexpr std::uint8_t kKeepsState = 0;
// The clouds look different: the history is dropped. Floats compare with a 1% tolerance (a
// host easing a value over frames keeps its history): 1% of the value, or for a weather
// state's fields of their natural size where that is larger (0.01 of coverage), and the wind's
// direction 0.01 rad; everything else exactly.
inline constexpr std::uint8_t kResetsHistory = 1;
// The shadow map is made differently: its cascades are remade (any change at all).
inline constexpr std::uint8_t kRemakesShadows = 2;

struct SettingEffect {
  const char* field;  // as clouds.h names it
  std::uint8_t effects;
  // Whether two settings differ in this field enough to reset the history (kResetsHistory's
  // tolerance), and at all.
  bool (*looksDifferent)(const Settings&, const Settings&);
  bool (*differs)(const Settings&, const Settings&);
  // For a field that keeps the state: why it may (what else takes care of a change).
  const char* whyKept;
};

std::span<const SettingEffect> settingEffects();

// Any field whose row has `effect` changed (kResetsHistory: beyond its tolerance).
bool settingsDifferIn(std::uint8_t effect, const Settings& a, const Settings& b);
// Any field whose row has `effect` changed at all (kResetsHistory: within its tolerance too).
bool settingsChangedIn(std::uint8_t effect, const Settings& a, const Settings& b);

}  // namespace clouds::detail
