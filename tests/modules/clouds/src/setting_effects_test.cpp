// The table of what each Settings field's change does (setting_effects.h), held to clouds.h and
// to the behaviour: every field the header declares has exactly one row, a row that keeps the
// state says why, and changing a numeric field resets the history and remakes the shadow map
// exactly when its row says so.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "setting_effects.h"
#include "setting_ranges.h"
#include "settings_declaration.h"
#include "temporal_state.h"

namespace {

using namespace clouds::detail;

// Every field clouds.h's Settings struct declares, in order.
std::vector<std::string> declaredFields() {
  const std::string settings = test::settingsDeclaration();
  // A declaration at the start of its line, with "= value" or "{value}" (a comment's "a = b"
  // is not one).
  const std::regex line(R"(\n\s*[\w:]+ (\w+)(?: = [^;\n]*|\{[^;\n]*\})?;)");
  std::vector<std::string> fields;
  for (auto it = std::sregex_iterator(settings.begin(), settings.end(), line);
       it != std::sregex_iterator(); ++it) {
    fields.push_back((*it)[1]);
  }
  return fields;
}

TEST(SettingEffects, EveryDeclaredFieldHasExactlyOneRow) {
  const std::vector<std::string> declared = declaredFields();
  ASSERT_GT(declared.size(), 80u) << "the header's fields were not found";
  std::map<std::string, int> rows;
  for (const SettingEffect& row : settingEffects()) ++rows[row.field];
  for (const std::string& field : declared) {
    EXPECT_EQ(rows[field], 1) << "Settings::" << field
                              << " needs one row in modules/clouds/src/setting_effects.cpp: does "
                                 "a change of it reset the history, remake the shadow map, or "
                                 "neither (and why)?";
  }
  const std::set<std::string> known(declared.begin(), declared.end());
  for (const auto& [field, count] : rows) {
    EXPECT_TRUE(known.count(field)) << field << " has a row but clouds.h declares no such field";
  }
}

TEST(SettingEffects, AFieldThatKeepsTheStateSaysWhy) {
  for (const SettingEffect& row : settingEffects()) {
    if (row.effects == kKeepsState) {
      EXPECT_GT(std::string(row.whyKept).size(), 10u) << row.field;
    } else {
      EXPECT_EQ(std::string(row.whyKept), "") << row.field << " resets something: no reason";
    }
  }
}

// A value of `range`'s field other than `from`, inside its range and more than 1% away.
double anotherValue(const SettingRange& range, double from) {
  const double up = from == 0.0 ? 1.0 : from * 1.5;
  if (up <= range.hi && up != from) return range.integer ? std::max(from + 1.0, up) : up;
  const double down = from * 0.5;
  return range.integer ? std::min(from - 1.0, down) : down;
}

TEST(SettingEffects, ChangingANumericFieldResetsWhatItsRowSays) {
  std::map<std::string, std::uint8_t> effects;
  for (const SettingEffect& row : settingEffects()) effects[row.field] = row.effects;
  std::size_t checked = 0;
  for (const clouds::Quality preset : {clouds::Quality::Low, clouds::Quality::High}) {
    clouds::Settings base = clouds::settingsFor(preset);
    base.windDirection = {1.0f, 1.0f};  // so that a change of one component turns it
    for (const SettingRange& range : settingRanges()) {
      const std::string field = range.field;
      const auto row = effects.find(field.substr(0, field.find('.')));  // windDirection.x
      ASSERT_NE(row, effects.end()) << field;
      clouds::Settings changed = base;
      const double value = anotherValue(range, range.get(base));
      if (value < range.lo || value > range.hi) continue;  // a field pinned to one value
      range.set(changed, value);
      ASSERT_NE(range.get(changed), range.get(base)) << field;
      EXPECT_EQ(cloudsLookDifferent(base, changed), (row->second & kResetsHistory) != 0)
          << field << " changed from " << range.get(base) << " to " << value;
      EXPECT_EQ(settingsDifferIn(kRemakesShadows, base, changed),
                (row->second & kRemakesShadows) != 0)
          << field << " changed from " << range.get(base) << " to " << value;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
}

// Small steps (a host easing a value) keep the history; the shadow map is exact.
TEST(SettingEffects, AStepUnderOnePercentKeepsTheHistory) {
  const clouds::Settings base;
  clouds::Settings eased = base;
  eased.coverage *= 1.005f;
  eased.layerBottomMetres *= 1.005f;
  EXPECT_FALSE(cloudsLookDifferent(base, eased));
  EXPECT_TRUE(settingsDifferIn(kRemakesShadows, base, eased)) << "the layer moved: remade";
  eased.coverage *= 1.02f;
  EXPECT_TRUE(cloudsLookDifferent(base, eased));
}

// A weather state's field easing out of 0 (a storm's anvils growing) keeps the history as one
// easing between large values does: its 1% is of its natural size (0.01 of a [0, 1] field).
// The wind's direction is a direction: turning it counts, its length does not.
TEST(SettingEffects, AWeatherFieldEasedOutOfZeroKeepsTheHistory) {
  clouds::Settings base;
  base.anvilBias = 0.0f;
  clouds::Settings eased = base;
  eased.anvilBias = 0.005f;
  EXPECT_FALSE(cloudsLookDifferent(base, eased));
  eased.anvilBias = 0.02f;
  EXPECT_TRUE(cloudsLookDifferent(base, eased));
  eased = base;
  eased.layerBottomMetres = 1.0f;  // not a weather field: 1% of its value, as before
  base.layerBottomMetres = 0.0f;
  EXPECT_TRUE(cloudsLookDifferent(base, eased));
  const auto turned = [&](float degrees) {
    clouds::Settings t = base;
    const float r = glm::radians(degrees);
    t.windDirection = {std::cos(r), std::sin(r)};
    return t;
  };
  base.windDirection = {1.0f, 0.0f};
  EXPECT_FALSE(cloudsLookDifferent(base, turned(0.5f)));
  EXPECT_TRUE(cloudsLookDifferent(base, turned(1.0f)));
  clouds::Settings longer = base;
  longer.windDirection = {3.0f, 0.0f};
  EXPECT_FALSE(cloudsLookDifferent(base, longer)) << "the same direction";
}

TEST(SettingEffects, SwitchesAndChoicesResetOnAnyChange) {
  const clouds::Settings base;
  clouds::Settings flipped = base;
  flipped.detail = !base.detail;
  EXPECT_TRUE(cloudsLookDifferent(base, flipped));
  flipped = base;
  flipped.jitter = base.jitter == clouds::Jitter::BayerHalton ? clouds::Jitter::None
                                                              : clouds::Jitter::BayerHalton;
  EXPECT_TRUE(cloudsLookDifferent(base, flipped));
  flipped = base;
  flipped.depthOutput = !base.depthOutput;
  EXPECT_FALSE(cloudsLookDifferent(base, flipped)) << "an output, not a look";
}

}  // namespace
