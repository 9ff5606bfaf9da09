// Boundaries and messages agree: every numeric Settings field's range, as validateSettings()
// checks it (setting_ranges.h), is the range clouds.h documents for it ("// [lo, hi]"); a
// value at each bound is accepted and one just outside is refused by a message naming the
// field and the range; the cross-field rule on the layer's thickness holds at its bound.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <string>

#include "clouds/clouds.h"
#include "setting_ranges.h"
#include "settings_declaration.h"

namespace {

using clouds::detail::SettingRange;

// "name = default;  // [lo, hi] ..." in clouds.h's Settings struct: name -> (lo, hi).
std::map<std::string, std::pair<double, double>> documentedRanges() {
  const std::string settings = test::settingsDeclaration();
  std::map<std::string, std::pair<double, double>> ranges;
  // A declaration at the start of its line (a comment's "a = b" is not one).
  const std::regex line(R"(\n\s*[\w:]+ (\w+) = [^;\n]*;[ \t]*// \[([-0-9.e]+), ([-0-9.e]+)\])");
  for (auto it = std::sregex_iterator(settings.begin(), settings.end(), line);
       it != std::sregex_iterator(); ++it) {
    ranges[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3])};
  }
  return ranges;
}

// The field as the type it has stores `value` (floats: the nearest float).
double asStored(const SettingRange& r, double value) {
  clouds::Settings s;
  r.set(s, value);
  return r.get(s);
}

TEST(SettingRanges, TheCheckedRangesAreTheDocumentedOnes) {
  const auto documented = documentedRanges();
  ASSERT_GT(documented.size(), 50u) << "the header's ranges were not found";
  std::size_t matched = 0;
  for (const SettingRange& r : clouds::detail::settingRanges()) {
    const std::string field = r.field;
    const auto it = documented.find(field);
    if (it == documented.end()) {
      // Documented otherwise: the layer's top (above its bottom) and the wind's direction.
      EXPECT_TRUE(field == "layerTopMetres" || field.rfind("windDirection.", 0) == 0)
          << field << " has no \"[lo, hi]\" in clouds.h";
      continue;
    }
    EXPECT_EQ(r.lo, asStored(r, it->second.first)) << field;
    EXPECT_EQ(r.hi, asStored(r, it->second.second)) << field;
    ++matched;
  }
  EXPECT_EQ(matched, documented.size()) << "a documented range is not checked";
}

TEST(SettingRanges, BothBoundsPassAndJustOutsideNamesTheField) {
  for (const SettingRange& r : clouds::detail::settingRanges()) {
    const std::string field = r.field;
    if (field == "layerTopMetres" || field == "layerBottomMetres") continue;  // below
    for (const double bound : {r.lo, r.hi}) {
      clouds::Settings s;
      r.set(s, bound);
      const std::string error = clouds::validateSettings(s);
      EXPECT_EQ(error.find("Settings." + field + " ="), std::string::npos)
          << field << " = " << bound << " refused: " << error;
    }
    const double step = r.integer ? 1.0 : std::max(std::abs(r.hi - r.lo) * 1e-3, 1e-6);
    for (const double outside : {r.lo - step, r.hi + step}) {
      if (r.integer && outside < 0.0) continue;  // an unsigned field cannot hold it
      clouds::Settings s;
      r.set(s, outside);
      const std::string error = clouds::validateSettings(s);
      EXPECT_EQ(error.rfind("Settings." + field + " = ", 0), 0u)
          << field << " = " << outside << ": got '" << error << "'";
      EXPECT_NE(error.find("must be in ["), std::string::npos) << error;
    }
    clouds::Settings s;
    r.set(s, std::numeric_limits<double>::quiet_NaN());
    if (!r.integer) {
      EXPECT_EQ(clouds::validateSettings(s).rfind("Settings." + field + " = ", 0), 0u)
          << field << " = NaN";
    }
  }
}

TEST(SettingRanges, TheLayerMayBeExactlyOneMetreThick) {
  clouds::Settings s;
  s.layerBottomMetres = 1500.0f;
  s.layerTopMetres = 1501.0f;
  EXPECT_EQ(clouds::validateSettings(s), "") << "1 m is \"at least 1 m\"";
  s.layerTopMetres = 1500.5f;
  const std::string error = clouds::validateSettings(s);
  EXPECT_EQ(error.rfind("Settings.layerTopMetres = ", 0), 0u) << error;
  EXPECT_NE(error.find("by at least 1 m"), std::string::npos) << error;
  // Both of the base's bounds, with a top 1 m above it.
  for (const float bottom : {0.0f, 20000.0f}) {
    s.layerBottomMetres = bottom;
    s.layerTopMetres = bottom + 1.0f;
    EXPECT_EQ(clouds::validateSettings(s), "") << "bottom " << bottom;
  }
}

}  // namespace
