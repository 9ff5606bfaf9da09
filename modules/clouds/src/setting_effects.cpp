#include "setting_effects.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace clouds::detail {
namespace {

// A float differs by more than 1% of the larger of the two values, or of `scale`, the field's
// natural size, where that is larger: a weather field easing out of 0 (anvilBias from 0 to 1)
// then keeps the history as one easing between large values does.
bool differByOnePercent(float x, float y, float scale) {
  return std::abs(x - y) > 0.01f * std::max({std::abs(x), std::abs(y), scale}) + 1e-6f;
}
// A direction (any length) turned by more than 1% of a radian.
bool differByOnePercent(const glm::vec2& x, const glm::vec2& y, float) {
  const float lx = glm::length(x);
  const float ly = glm::length(y);
  if (!(lx > 0.0f && ly > 0.0f)) return !(x == y);
  const float cosine = std::clamp(glm::dot(x / lx, y / ly), -1.0f, 1.0f);
  return std::acos(cosine) > 0.01f;
}
// Counts, switches and choices: any change is a change.
template <typename T>
bool differByOnePercent(const T& x, const T& y, float) {
  return !(x == y);
}

template <auto Field, int Scale>
bool looksDifferent(const Settings& a, const Settings& b) {
  return differByOnePercent(a.*Field, b.*Field, static_cast<float>(Scale));
}
template <auto Field>
bool differs(const Settings& a, const Settings& b) {
  return !(a.*Field == b.*Field);
}

template <auto Field, int Scale = 0>
constexpr SettingEffect row(const char* name, std::uint8_t effects, const char* whyKept) {
  return {name, effects, &looksDifferent<Field, Scale>, &differs<Field>, whyKept};
}

// One row; the field's name is written once.
#define CLOUDS_SETTING(name, effects, whyKept) row<&Settings::name>(#name, effects, whyKept)
// A row whose floats' 1% is at least 1% of `scale`, a whole number in the field's unit (a
// weather state's field: clouds/weather.h).
#define CLOUDS_WEATHER_SETTING(name, effects, scale) \
  row<&Settings::name, scale>(#name, effects, kNoReason)

constexpr std::uint8_t kLook = kResetsHistory;
constexpr std::uint8_t kShadow = kRemakesShadows;
constexpr const char* kNoReason = "";  // rows that reset something need no reason
constexpr const char* kSamePrecisionKnob =
    "a march precision knob: the history estimates the same clouds; the refresh replaces it";

constexpr SettingEffect kEffects[] = {
    // The layer and its weather.
    CLOUDS_SETTING(layerBottomMetres, kLook | kShadow, kNoReason),
    CLOUDS_SETTING(layerTopMetres, kLook | kShadow, kNoReason),
    CLOUDS_SETTING(planetRadiusMetres, kLook, kNoReason),
    CLOUDS_WEATHER_SETTING(coverage, kLook, 1),
    CLOUDS_WEATHER_SETTING(cloudType, kLook, 1),
    CLOUDS_SETTING(typeVariation, kLook, kNoReason),
    CLOUDS_SETTING(densityVariation, kLook, kNoReason),
    CLOUDS_SETTING(weatherTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(weatherEvolutionPerSecond, kKeepsState,
                   "the weather evolves slowly either way: the history follows it"),
    CLOUDS_SETTING(weatherUpdateSeconds, kKeepsState,
                   "a new period's map blends in over the period: the history follows it"),
    // Density and shape.
    CLOUDS_WEATHER_SETTING(densityMultiplier, kLook, 1),
    CLOUDS_SETTING(extinctionPerMetre, kLook, kNoReason),
    CLOUDS_WEATHER_SETTING(anvilBias, kLook, 1),
    CLOUDS_SETTING(shapeTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(detailTileMetres, kLook, kNoReason),
    CLOUDS_WEATHER_SETTING(detailErosion, kLook, 1),
    CLOUDS_SETTING(detailDistanceMetres, kLook, kNoReason),
    CLOUDS_SETTING(curlTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(curlStrengthMetres, kLook, kNoReason),
    CLOUDS_WEATHER_SETTING(windDirection, kLook, 0),
    CLOUDS_WEATHER_SETTING(windSpeedMetresPerSecond, kLook, 10),
    CLOUDS_WEATHER_SETTING(skewMetres, kLook, 100),
    CLOUDS_WEATHER_SETTING(windShearDegrees, kLook, 60),
    // Lighting.
    CLOUDS_SETTING(albedo, kLook, kNoReason),
    CLOUDS_SETTING(phaseForwardG, kLook, kNoReason),
    CLOUDS_SETTING(phaseBackwardG, kLook, kNoReason),
    CLOUDS_SETTING(phaseBackwardWeight, kLook, kNoReason),
    CLOUDS_SETTING(silverIntensity, kLook, kNoReason),
    CLOUDS_SETTING(silverSpread, kLook, kNoReason),
    CLOUDS_SETTING(multipleScattering, kLook, kNoReason),
    CLOUDS_SETTING(multipleScatteringOctaves, kLook, kNoReason),
    CLOUDS_SETTING(msExtinctionScale, kLook, kNoReason),
    CLOUDS_SETTING(msContribution, kLook, kNoReason),
    CLOUDS_SETTING(msEccentricityScale, kLook, kNoReason),
    CLOUDS_SETTING(inScatterStrength, kLook, kNoReason),
    CLOUDS_SETTING(inScatterCoreProfile, kLook, kNoReason),
    CLOUDS_SETTING(ambientOcclusionStrength, kLook, kNoReason),
    CLOUDS_SETTING(ambientStrength, kLook, kNoReason),
    CLOUDS_SETTING(sunStrength, kLook, kNoReason),
    // The march: what a sample of the history was made with. Its precision knobs (the
    // presets' rungs) keep the history: the old samples estimate the same clouds a little
    // more or less closely, and the refresh cycle replaces them within updateInterval frames,
    // so a governor moving between presets causes no rebuild (a rebuild marches 4 to 16 times
    // a frame's rays: a hitch). What changes the clouds themselves resets it.
    CLOUDS_SETTING(maxViewSteps, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(viewStepMetres, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(viewStepGrowth, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(lightSteps, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(lightConeMetres, kLook, kNoReason),
    CLOUDS_SETTING(lightConeSpread, kLook, kNoReason),
    CLOUDS_SETTING(maxDistanceMetres, kLook, kNoReason),
    CLOUDS_SETTING(transmittanceCutoff, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(cheapSampling, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(coarseStepFactor, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(emptySamplesToCoarse, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(detail, kLook, kNoReason),
    CLOUDS_SETTING(noiseLevelOfDetail, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(noiseTexelsPerPixel, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(lightEveryOtherStep, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(jitter, kLook, kNoReason),
    CLOUDS_SETTING(emptySpaceSkipping, kKeepsState, kSamePrecisionKnob),
    CLOUDS_SETTING(heroLight, kLook, kNoReason),
    CLOUDS_SETTING(heroDetail, kLook, kNoReason),
    // Temporal reconstruction: its own knobs apply to the next blend.
    CLOUDS_SETTING(traceScale, kKeepsState, "a new trace extent resets the history as a resize"),
    CLOUDS_SETTING(updateInterval, kKeepsState,
                   "the tile size and refresh order follow it from the next frame"),
    CLOUDS_SETTING(temporalReuse, kKeepsState, "the temporal plan checks it every frame"),
    CLOUDS_SETTING(temporalFreshWeight, kKeepsState, "a blend weight: applies to the next blend"),
    CLOUDS_SETTING(temporalStillFreshWeight, kKeepsState,
                   "a blend weight: applies to the next blend"),
    CLOUDS_SETTING(temporalUpsampling, kKeepsState,
                   "the plan decides every frame, using the output's history once it is written"),
    CLOUDS_SETTING(upsamplingMaxSamples, kKeepsState, "a blend limit: applies to the next blend"),
    CLOUDS_SETTING(edgeRays, kKeepsState, "extra rays for the next frame's silhouettes"),
    CLOUDS_SETTING(historyClampMargin, kKeepsState, "a blend limit: applies to the next blend"),
    CLOUDS_SETTING(historyClampSpreadPixels, kKeepsState,
                   "a blend limit: applies to the next blend"),
    CLOUDS_SETTING(insideLayerMarginMetres, kKeepsState, "a rule of the reset decision itself"),
    CLOUDS_SETTING(movingInsideUpdateInterval, kKeepsState,
                   "the tile size and refresh order follow it from the next frame"),
    // What the far history holds while the split is on: the clouds beyond it. Away from the
    // clouds it is off whatever the distance, so a preset with another split keeps the history.
    CLOUDS_SETTING(nearFieldMetres, kKeepsState,
                   "the temporal plan resets when the split comes, goes or moves while on"),
    CLOUDS_SETTING(historyResetDistanceMetres, kKeepsState, "a rule of the reset decision itself"),
    CLOUDS_SETTING(historyResetAngleDegrees, kKeepsState, "a rule of the reset decision itself"),
    CLOUDS_SETTING(relightResetDegrees, kKeepsState, "a rule of the reset decision itself"),
    CLOUDS_SETTING(relightResetRatio, kKeepsState, "a rule of the reset decision itself"),
    CLOUDS_SETTING(depthOutput, kKeepsState, "an output the host reads, not an input of history"),
    // The shadow map.
    CLOUDS_SETTING(shadowCascades, kShadow, kNoReason),
    CLOUDS_SETTING(shadowMapResolution, kShadow, kNoReason),
    CLOUDS_SETTING(shadowNearSideMetres, kShadow, kNoReason),
    CLOUDS_SETTING(shadowCascadeRatio, kShadow, kNoReason),
    CLOUDS_SETTING(shadowSteps, kKeepsState,
                   "a precision knob: each cascade's next turn marches with it (a remake of all "
                   "at once is a hitch)"),
    CLOUDS_SETTING(shadowCascadesPerFrame, kKeepsState,
                   "the cascades' refresh schedule: the next turn follows it"),
    CLOUDS_SETTING(shadowFramesPerCascade, kKeepsState,
                   "the cascades' refresh schedule: the next turn follows it"),
    CLOUDS_SETTING(terrainShadowSteps, kKeepsState,
                   "a precision knob: each cascade's next turn marches with it (a remake of all "
                   "at once is a hitch)"),
    CLOUDS_SETTING(cloudShadowsOnClouds, kKeepsState,
                   "a march precision knob: the light cone's integral carried to the sun; the "
                   "refresh replaces the history's light"),
    // God rays and lightning: made anew every frame.
    CLOUDS_SETTING(godRaySamples, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayLength, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayDecay, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayGlowStrength, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(lightningFlashes, kKeepsState,
                   "a capacity: the flashes are this frame's inputs, glowing anew each frame"),
    CLOUDS_SETTING(lightningBoltSegments, kKeepsState,
                   "a capacity: the bolts are drawn anew every frame"),
    CLOUDS_SETTING(weatherRegions, kKeepsState,
                   "a capacity: the regions are this frame's inputs (a change of them is "
                   "weighed apart)"),
    CLOUDS_SETTING(superstorms, kKeepsState,
                   "a capacity: the storm is one of this frame's regions"),
    CLOUDS_SETTING(vortexReprojection, kKeepsState, "how the history is found, not what it holds"),
    CLOUDS_SETTING(skyLight, kKeepsState,
                   "an output beside the view's: its own map, refreshed a part every frame"),
};

#undef CLOUDS_SETTING
#undef CLOUDS_WEATHER_SETTING

}  // namespace

std::span<const SettingEffect> settingEffects() {
  return kEffects;
}

bool settingsDifferIn(std::uint8_t effect, const Settings& a, const Settings& b) {
  // Resetting the history tolerates small steps; remaking the shadows does not.
  return std::any_of(std::begin(kEffects), std::end(kEffects), [&](const SettingEffect& row) {
    if ((row.effects & effect) == 0) return false;
    return effect == kResetsHistory ? row.looksDifferent(a, b) : row.differs(a, b);
  });
}

bool settingsChangedIn(std::uint8_t effect, const Settings& a, const Settings& b) {
  return std::any_of(std::begin(kEffects), std::end(kEffects), [&](const SettingEffect& row) {
    return (row.effects & effect) != 0 && row.differs(a, b);
  });
}

}  // namespace clouds::detail
