#include "setting_effects.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace clouds::detail {
namespace {

bool differByOnePercent(float x, float y) {
  return std::abs(x - y) > 0.01f * std::max(std::abs(x), std::abs(y)) + 1e-6f;
}
bool differByOnePercent(const glm::vec2& x, const glm::vec2& y) {
  return differByOnePercent(x.x, y.x) || differByOnePercent(x.y, y.y);
}
// Counts, switches and choices: any change is a change.
template <typename T>
bool differByOnePercent(const T& x, const T& y) {
  return !(x == y);
}

template <auto Field>
bool looksDifferent(const Settings& a, const Settings& b) {
  return differByOnePercent(a.*Field, b.*Field);
}
template <auto Field>
bool differs(const Settings& a, const Settings& b) {
  return !(a.*Field == b.*Field);
}

template <auto Field>
constexpr SettingEffect row(const char* name, std::uint8_t effects, const char* whyKept) {
  return {name, effects, &looksDifferent<Field>, &differs<Field>, whyKept};
}

// One row; the field's name is written once.
#define CLOUDS_SETTING(name, effects, whyKept) row<&Settings::name>(#name, effects, whyKept)

constexpr std::uint8_t kLook = kResetsHistory;
constexpr std::uint8_t kShadow = kRemakesShadows;
constexpr const char* kNoReason = "";  // rows that reset something need no reason

constexpr SettingEffect kEffects[] = {
    // The layer and its weather.
    CLOUDS_SETTING(layerBottomMetres, kLook | kShadow, kNoReason),
    CLOUDS_SETTING(layerTopMetres, kLook | kShadow, kNoReason),
    CLOUDS_SETTING(planetRadiusMetres, kLook, kNoReason),
    CLOUDS_SETTING(coverage, kLook, kNoReason),
    CLOUDS_SETTING(cloudType, kLook, kNoReason),
    CLOUDS_SETTING(typeVariation, kLook, kNoReason),
    CLOUDS_SETTING(densityVariation, kLook, kNoReason),
    CLOUDS_SETTING(weatherTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(weatherEvolutionPerSecond, kKeepsState,
                   "the weather evolves slowly either way: the history follows it"),
    CLOUDS_SETTING(weatherUpdateSeconds, kKeepsState,
                   "a new period's map blends in over the period: the history follows it"),
    // Density and shape.
    CLOUDS_SETTING(densityMultiplier, kLook, kNoReason),
    CLOUDS_SETTING(extinctionPerMetre, kLook, kNoReason),
    CLOUDS_SETTING(anvilBias, kLook, kNoReason),
    CLOUDS_SETTING(shapeTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(detailTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(detailErosion, kLook, kNoReason),
    CLOUDS_SETTING(detailDistanceMetres, kLook, kNoReason),
    CLOUDS_SETTING(curlTileMetres, kLook, kNoReason),
    CLOUDS_SETTING(curlStrengthMetres, kLook, kNoReason),
    CLOUDS_SETTING(windDirection, kLook, kNoReason),
    CLOUDS_SETTING(windSpeedMetresPerSecond, kLook, kNoReason),
    CLOUDS_SETTING(skewMetres, kLook, kNoReason),
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
    // The march: what a sample of the history was made with.
    CLOUDS_SETTING(maxViewSteps, kLook, kNoReason),
    CLOUDS_SETTING(viewStepMetres, kLook, kNoReason),
    CLOUDS_SETTING(viewStepGrowth, kLook, kNoReason),
    CLOUDS_SETTING(lightSteps, kLook, kNoReason),
    CLOUDS_SETTING(lightConeMetres, kLook, kNoReason),
    CLOUDS_SETTING(lightConeSpread, kLook, kNoReason),
    CLOUDS_SETTING(maxDistanceMetres, kLook, kNoReason),
    CLOUDS_SETTING(transmittanceCutoff, kLook, kNoReason),
    CLOUDS_SETTING(cheapSampling, kLook, kNoReason),
    CLOUDS_SETTING(coarseStepFactor, kLook, kNoReason),
    CLOUDS_SETTING(emptySamplesToCoarse, kLook, kNoReason),
    CLOUDS_SETTING(detail, kLook, kNoReason),
    CLOUDS_SETTING(noiseLevelOfDetail, kLook, kNoReason),
    CLOUDS_SETTING(noiseTexelsPerPixel, kLook, kNoReason),
    CLOUDS_SETTING(lightEveryOtherStep, kLook, kNoReason),
    CLOUDS_SETTING(jitter, kLook, kNoReason),
    CLOUDS_SETTING(emptySpaceSkipping, kLook, kNoReason),
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
    // What the far history holds: the clouds beyond it.
    CLOUDS_SETTING(nearFieldMetres, kLook, kNoReason),
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
    CLOUDS_SETTING(shadowSteps, kShadow, kNoReason),
    CLOUDS_SETTING(shadowCascadesPerFrame, kKeepsState,
                   "the cascades' refresh schedule: the next turn follows it"),
    CLOUDS_SETTING(shadowFramesPerCascade, kKeepsState,
                   "the cascades' refresh schedule: the next turn follows it"),
    CLOUDS_SETTING(terrainShadowSteps, kShadow, kNoReason),
    // God rays and lightning: made anew every frame.
    CLOUDS_SETTING(godRaySamples, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayLength, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayDecay, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(godRayGlowStrength, kKeepsState, "the god-ray mask is made anew every frame"),
    CLOUDS_SETTING(lightningFlashes, kKeepsState,
                   "a capacity: the flashes are this frame's inputs, glowing anew each frame"),
    CLOUDS_SETTING(lightningBoltSegments, kKeepsState,
                   "a capacity: the bolts are drawn anew every frame"),
};

#undef CLOUDS_SETTING

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

}  // namespace clouds::detail
