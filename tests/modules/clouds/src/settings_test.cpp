#include <gtest/gtest.h>

#include <array>

#include "clouds/clouds.h"

namespace {

using clouds::Quality;
constexpr std::array kPresets = {Quality::Low, Quality::Medium, Quality::High, Quality::Ultra,
                                 Quality::Reference};

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
  EXPECT_TRUE(base.lightEveryOtherStep);
  EXPECT_FALSE(ref.lightEveryOtherStep);
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
      {"windDirection",
       [](clouds::Settings& s) {
         s.windDirection = {0.0f, 0.0f};
       }},
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

TEST(CloudPresets, EveryPresetIsValidAndNamed) {
  for (Quality q : kPresets) {
    EXPECT_EQ(clouds::validateSettings(clouds::settingsFor(q)), "") << clouds::qualityName(q);
    Quality parsed{};
    ASSERT_TRUE(clouds::parseQuality(clouds::qualityName(q), &parsed)) << clouds::qualityName(q);
    EXPECT_EQ(parsed, q);
  }
  Quality parsed = Quality::Low;
  EXPECT_TRUE(clouds::parseQuality("ultra", &parsed));  // case-insensitive
  EXPECT_EQ(parsed, Quality::Ultra);
  EXPECT_FALSE(clouds::parseQuality("extreme", &parsed));
  EXPECT_FALSE(clouds::parseQuality("", &parsed));
}

TEST(CloudPresets, TheFunctionsOutputs) {
  // The documented table (modules/clouds/README.md, "Quality presets").
  struct Row {
    Quality quality;
    float traceScale;
    std::uint32_t updateInterval, maxViewSteps;
    float viewStepMetres;
    std::uint32_t lightSteps;
    bool temporalReuse, emptySpaceSkipping, cheapSampling, upsamplesTemporally;
  };
  const Row rows[] = {
      {Quality::Low, 0.25f, 16, 64, 120.0f, 3, true, false, true, false},
      {Quality::Medium, 0.5f, 16, 64, 90.0f, 4, true, false, true, false},
      {Quality::High, 0.5f, 16, 168, 35.0f, 4, true, false, true, true},
      {Quality::Ultra, 0.5f, 4, 224, 30.0f, 10, true, false, true, true},
      {Quality::Reference, 1.0f, 1, 8192, 12.0f, 24, false, false, false, false},
  };
  for (const Row& r : rows) {
    const clouds::Settings s = clouds::settingsFor(r.quality);
    SCOPED_TRACE(clouds::qualityName(r.quality));
    EXPECT_EQ(s.traceScale, r.traceScale);
    EXPECT_EQ(s.updateInterval, r.updateInterval);
    EXPECT_EQ(s.maxViewSteps, r.maxViewSteps);
    EXPECT_EQ(s.viewStepMetres, r.viewStepMetres);
    EXPECT_EQ(s.lightSteps, r.lightSteps);
    EXPECT_EQ(s.temporalReuse, r.temporalReuse);
    EXPECT_EQ(s.emptySpaceSkipping, r.emptySpaceSkipping);
    EXPECT_EQ(s.cheapSampling, r.cheapSampling);
    EXPECT_EQ(clouds::upsamplesTemporally(s), r.upsamplesTemporally);
  }
}

TEST(CloudPresets, EachPresetSpendsAtLeastAsMuchAsTheOneBelowOnEveryKnob) {
  for (std::size_t i = 1; i < kPresets.size(); ++i) {
    const clouds::Settings lo = clouds::settingsFor(kPresets[i - 1]);
    const clouds::Settings hi = clouds::settingsFor(kPresets[i]);
    SCOPED_TRACE(clouds::qualityName(kPresets[i]));
    EXPECT_GE(hi.traceScale, lo.traceScale);
    EXPECT_LE(hi.updateInterval, lo.updateInterval);
    EXPECT_GE(hi.maxViewSteps, lo.maxViewSteps);
    EXPECT_LE(hi.viewStepMetres, lo.viewStepMetres);
    EXPECT_LE(hi.viewStepGrowth, lo.viewStepGrowth);
    EXPECT_GE(hi.lightSteps, lo.lightSteps);
    EXPECT_GE(hi.multipleScatteringOctaves, lo.multipleScatteringOctaves);
    EXPECT_GE(hi.detailDistanceMetres, lo.detailDistanceMetres);
    EXPECT_LE(hi.transmittanceCutoff, lo.transmittanceCutoff);
  }
}

TEST(CloudPresets, PresetsKeepTheLookOfTheBase) {
  clouds::Settings base;
  base.coverage = 0.83f;
  base.cloudType = 0.2f;
  base.windSpeedMetresPerSecond = 31.0f;
  base.phaseForwardG = 0.6f;
  base.layerBottomMetres = 900.0f;
  for (Quality q : kPresets) {
    const clouds::Settings s = clouds::settingsFor(q, base);
    SCOPED_TRACE(clouds::qualityName(q));
    EXPECT_EQ(s.coverage, base.coverage);
    EXPECT_EQ(s.cloudType, base.cloudType);
    EXPECT_EQ(s.windSpeedMetresPerSecond, base.windSpeedMetresPerSecond);
    EXPECT_EQ(s.phaseForwardG, base.phaseForwardG);
    EXPECT_EQ(s.layerBottomMetres, base.layerBottomMetres);
  }
  // Pure: the same input gives the same output; Reference is referenceSettings().
  EXPECT_EQ(clouds::settingsFor(Quality::High, base).maxViewSteps,
            clouds::settingsFor(Quality::High, base).maxViewSteps);
  EXPECT_EQ(clouds::settingsFor(Quality::Reference, base).lightSteps,
            clouds::referenceSettings(base).lightSteps);
}

TEST(CloudSettings, TemporalKnobsAreChecked) {
  clouds::Settings s;
  s.traceScale = 0.3f;
  EXPECT_NE(clouds::validateSettings(s).find("Settings.traceScale"), std::string::npos);
  s = {};
  s.updateInterval = 8;
  EXPECT_NE(clouds::validateSettings(s).find("Settings.updateInterval"), std::string::npos);
  s = {};
  s.updateInterval = 64;  // 8 x 8 tiles
  EXPECT_EQ(clouds::validateSettings(s), "");
  s = {};
  s.temporalFreshWeight = 0.0f;
  EXPECT_NE(clouds::validateSettings(s).find("Settings.temporalFreshWeight"), std::string::npos);
  s = {};
  s.upsamplingMaxSamples = 0;
  EXPECT_NE(clouds::validateSettings(s).find("Settings.upsamplingMaxSamples"), std::string::npos);
  s.upsamplingMaxSamples = 16;  // the count lives in 4 bits of the output history
  EXPECT_NE(clouds::validateSettings(s).find("Settings.upsamplingMaxSamples"), std::string::npos);
  s = clouds::settingsFor(clouds::Quality::High);
  s.edgeRays = 3;  // a tile's trace pixel has three output pixels besides its ray's
  EXPECT_NE(clouds::validateSettings(s).find("Settings.edgeRays"), std::string::npos);
}

}  // namespace
