#include <gtest/gtest.h>

#include "clouds/clouds.h"

namespace {

TEST(CloudSettings, DefaultsAndReferenceAreValid) {
  EXPECT_EQ(clouds::validateSettings(clouds::Settings{}), "");
  EXPECT_EQ(clouds::validateSettings(clouds::referenceSettings(clouds::Settings{})), "");
}

TEST(CloudSettings, ReferenceIsMoreAccurateOnEveryCostKnob) {
  const clouds::Settings base;
  const clouds::Settings ref = clouds::referenceSettings(base);
  EXPECT_LT(ref.viewStepMetres, base.viewStepMetres);
  EXPECT_LE(ref.viewStepGrowth, base.viewStepGrowth);
  EXPECT_GT(ref.maxViewSteps, base.maxViewSteps);
  EXPECT_GT(ref.lightSteps, base.lightSteps);
  EXPECT_FALSE(ref.cheapSampling);
  EXPECT_LT(ref.transmittanceCutoff, base.transmittanceCutoff);
}

TEST(CloudSettings, OutOfRangeValuesNameTheField) {
  struct Case {
    const char* field;
    void (*apply)(clouds::Settings&);
  };
  const Case cases[] = {
      {"coverage", [](clouds::Settings& s) { s.coverage = 1.5f; }},
      {"layerTopMetres", [](clouds::Settings& s) { s.layerTopMetres = s.layerBottomMetres; }},
      {"densityMultiplier", [](clouds::Settings& s) { s.densityMultiplier = -1.0f; }},
      {"maxViewSteps", [](clouds::Settings& s) { s.maxViewSteps = 0; }},
      {"lightSteps", [](clouds::Settings& s) { s.lightSteps = 65; }},
      {"viewStepMetres", [](clouds::Settings& s) { s.viewStepMetres = std::nanf(""); }},
      {"windDirection", [](clouds::Settings& s) { s.windDirection = {0.0f, 0.0f}; }},
      {"phaseForwardG", [](clouds::Settings& s) { s.phaseForwardG = 3.0f; }},
      {"jitter", [](clouds::Settings& s) { s.jitter = static_cast<clouds::Jitter>(7); }},
  };
  for (const Case& c : cases) {
    clouds::Settings s;
    c.apply(s);
    const std::string error = clouds::validateSettings(s);
    EXPECT_NE(error.find(std::string("Settings.") + c.field), std::string::npos)
        << c.field << ": got '" << error << "'";
  }
}

}  // namespace
