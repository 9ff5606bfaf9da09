// Settings validation, the reference mode and the quality presets.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "setting_ranges.h"

namespace clouds {
namespace {

struct Checker {
  std::string error;

  void range(const char* field, double value, double lo, double hi) {
    if (!error.empty()) return;
    const bool finite = std::isfinite(value);
    if (!finite || value < lo || value > hi) {
      std::ostringstream out;
      out << "Settings." << field << " = " << value << ": must be in [" << lo << ", " << hi << "]";
      error = out.str();
    }
  }
  void require(bool condition, const std::string& message) {
    if (error.empty() && !condition) error = message;
  }
};

// A field's range entry: its bounds as the field's own type holds them (0.01 as a float is a
// little under 0.01: a float set to the documented bound must pass).
#define CLOUDS_FIELD_TYPE(field) std::remove_cvref_t<decltype(std::declval<Settings&>().field)>
#define CLOUDS_RANGE(field, lo, hi)                                                        \
  detail::SettingRange {                                                                   \
#field, static_cast<double>(static_cast<CLOUDS_FIELD_TYPE(field)>(lo)),                  \
        static_cast<double>(static_cast<CLOUDS_FIELD_TYPE(field)>(hi)),                      \
        [](const Settings& s) { return static_cast<double>(s.field); },                      \
        [](Settings& s, double v) { s.field = static_cast<CLOUDS_FIELD_TYPE(field)>(v); },   \
        std::is_integral_v<CLOUDS_FIELD_TYPE(field)> \
  }

}  // namespace

namespace detail {

std::span<const SettingRange> settingRanges() {
  static const SettingRange ranges[] = {
      CLOUDS_RANGE(layerBottomMetres, 0.0, 20000.0),
      CLOUDS_RANGE(layerTopMetres, 0.0, 30000.0),
      CLOUDS_RANGE(planetRadiusMetres, 1e5, 1e8),
      CLOUDS_RANGE(coverage, 0.0, 1.0),
      CLOUDS_RANGE(cloudType, 0.0, 1.0),
      CLOUDS_RANGE(typeVariation, 0.0, 2.0),
      CLOUDS_RANGE(densityVariation, 0.0, 1.0),
      CLOUDS_RANGE(weatherTileMetres, 1000.0, 1e7),
      CLOUDS_RANGE(weatherEvolutionPerSecond, 0.0, 1.0),
      CLOUDS_RANGE(weatherUpdateSeconds, 0.0, 3600.0),
      CLOUDS_RANGE(densityMultiplier, 0.0, 1e6),
      CLOUDS_RANGE(extinctionPerMetre, 0.0, 100.0),
      CLOUDS_RANGE(anvilBias, 0.0, 1.0),
      CLOUDS_RANGE(shapeTileMetres, 100.0, 1e7),
      CLOUDS_RANGE(detailTileMetres, 10.0, 1e6),
      CLOUDS_RANGE(detailErosion, 0.0, 1.0),
      CLOUDS_RANGE(detailDistanceMetres, 0.0, 1e7),
      CLOUDS_RANGE(noiseTexelsPerPixel, 1.0, 64.0),
      CLOUDS_RANGE(curlTileMetres, 100.0, 1e7),
      CLOUDS_RANGE(curlStrengthMetres, 0.0, 10000.0),
      CLOUDS_RANGE(windDirection.x, -1e6, 1e6),
      CLOUDS_RANGE(windDirection.y, -1e6, 1e6),
      CLOUDS_RANGE(windSpeedMetresPerSecond, 0.0, 500.0),
      CLOUDS_RANGE(skewMetres, 0.0, 20000.0),
      CLOUDS_RANGE(windShearDegrees, -180.0, 180.0),
      CLOUDS_RANGE(albedo, 0.0, 1.0),
      CLOUDS_RANGE(phaseForwardG, -1.0, 1.0),
      CLOUDS_RANGE(phaseBackwardG, -1.0, 1.0),
      CLOUDS_RANGE(phaseBackwardWeight, 0.0, 1.0),
      CLOUDS_RANGE(silverIntensity, 0.0, 10.0),
      CLOUDS_RANGE(silverSpread, 0.0, 0.99),
      CLOUDS_RANGE(multipleScatteringOctaves, 1, 8),
      CLOUDS_RANGE(msExtinctionScale, 0.0, 1.0),
      CLOUDS_RANGE(msContribution, 0.0, 1.0),
      CLOUDS_RANGE(msEccentricityScale, 0.0, 1.0),
      CLOUDS_RANGE(inScatterStrength, 0.0, 1.0),
      CLOUDS_RANGE(inScatterCoreProfile, 0.01, 1.0),
      CLOUDS_RANGE(ambientOcclusionStrength, 0.0, 1.0),
      CLOUDS_RANGE(ambientStrength, 0.0, 100.0),
      CLOUDS_RANGE(sunStrength, 0.0, 100.0),
      CLOUDS_RANGE(maxViewSteps, 1, 16384),
      CLOUDS_RANGE(viewStepMetres, 0.5, 10000.0),
      CLOUDS_RANGE(viewStepGrowth, 0.0, 1.0),
      CLOUDS_RANGE(lightSteps, 0, 64),
      CLOUDS_RANGE(lightConeMetres, 1.0, 100000.0),
      CLOUDS_RANGE(lightConeSpread, 0.0, 2.0),
      CLOUDS_RANGE(maxDistanceMetres, 100.0, 1e7),
      CLOUDS_RANGE(transmittanceCutoff, 0.0, 0.5),
      CLOUDS_RANGE(coarseStepFactor, 1.0, 16.0),
      CLOUDS_RANGE(emptySamplesToCoarse, 1, 1000),
      CLOUDS_RANGE(upsamplingMaxSamples, 1, 15),
      CLOUDS_RANGE(edgeRays, 0, shader::kMaxEdgeRaysPerTile),
      CLOUDS_RANGE(weatherRegions, 0, shader::kMaxWeatherRegions),
      CLOUDS_RANGE(superstorms, 0, 1),
      CLOUDS_RANGE(temporalFreshWeight, 0.05, 1.0),
      CLOUDS_RANGE(temporalStillFreshWeight, 0.05, 1.0),
      CLOUDS_RANGE(historyClampMargin, 0.0, 1.0),
      CLOUDS_RANGE(historyClampSpreadPixels, 0.01, 100.0),
      CLOUDS_RANGE(insideLayerMarginMetres, 0.0, 5000.0),
      CLOUDS_RANGE(nearFieldMetres, 0.0, 2000.0),
      CLOUDS_RANGE(historyResetDistanceMetres, 1.0, 1e6),
      CLOUDS_RANGE(historyResetAngleDegrees, 0.1, 180.0),
      CLOUDS_RANGE(relightResetDegrees, 0.01, 180.0),
      CLOUDS_RANGE(relightResetRatio, 0.001, 10.0),
      CLOUDS_RANGE(shadowCascades, 0, 4),
      CLOUDS_RANGE(shadowMapResolution, 16, 1024),
      CLOUDS_RANGE(shadowNearSideMetres, 500.0, 1e6),
      CLOUDS_RANGE(shadowCascadeRatio, 1.5, 8.0),
      CLOUDS_RANGE(shadowSteps, 1, 256),
      CLOUDS_RANGE(shadowCascadesPerFrame, 1, 4),
      CLOUDS_RANGE(shadowFramesPerCascade, 1, 8),
      CLOUDS_RANGE(terrainShadowSteps, 1, 1024),
      CLOUDS_RANGE(godRaySamples, 0, 128),
      CLOUDS_RANGE(godRayLength, 0.05, 1.0),
      CLOUDS_RANGE(godRayDecay, 0.5, 1.0),
      CLOUDS_RANGE(godRayGlowStrength, 0.0, 10.0),
      CLOUDS_RANGE(lightningFlashes, 0, 16),
      CLOUDS_RANGE(lightningBoltSegments, 0, 256),
  };
  return ranges;
}

#undef CLOUDS_RANGE
#undef CLOUDS_FIELD_TYPE

}  // namespace detail

std::string validateSettings(const Settings& s) {
  Checker c;
  for (const detail::SettingRange& r : detail::settingRanges())
    c.range(r.field, r.get(s), r.lo, r.hi);
  c.require(s.layerTopMetres >= s.layerBottomMetres + 1.0f,
            "Settings.layerTopMetres = " + std::to_string(s.layerTopMetres) +
                ": must be above layerBottomMetres (" + std::to_string(s.layerBottomMetres) +
                ") by at least 1 m");
  c.require(glm::length(s.windDirection) > 1e-6f, "Settings.windDirection: must not be zero");
  c.require(s.traceScale == 1.0f || s.traceScale == 0.5f || s.traceScale == 0.25f,
            "Settings.traceScale = " + std::to_string(s.traceScale) + ": must be 1, 0.5 or 0.25");
  c.require(
      s.updateInterval == 1 || s.updateInterval == 4 || s.updateInterval == 16 ||
          s.updateInterval == 64,
      "Settings.updateInterval = " + std::to_string(s.updateInterval) + ": must be 1, 4, 16 or 64");
  c.require(s.movingInsideUpdateInterval == 1 || s.movingInsideUpdateInterval == 4 ||
                s.movingInsideUpdateInterval == 16 || s.movingInsideUpdateInterval == 64,
            "Settings.movingInsideUpdateInterval = " +
                std::to_string(s.movingInsideUpdateInterval) + ": must be 1, 4, 16 or 64");
  c.require(s.jitter == Jitter::None || s.jitter == Jitter::BayerHalton ||
                s.jitter == Jitter::BayerHaltonSubpixel,
            "Settings.jitter: unknown mode " + std::to_string(static_cast<unsigned>(s.jitter)));
  c.require(
      s.heroLight == HeroLight::Cone || s.heroLight == HeroLight::Volume ||
          s.heroLight == HeroLight::Marched,
      "Settings.heroLight: unknown mode " + std::to_string(static_cast<unsigned>(s.heroLight)));
  c.require(
      s.heroDetail == HeroDetail::Off || s.heroDetail == HeroDetail::Uprezzed,
      "Settings.heroDetail: unknown mode " + std::to_string(static_cast<unsigned>(s.heroDetail)));
  return c.error;
}

bool upsamplesTemporally(const Settings& s) {
  return s.temporalUpsampling && s.traceScale < 1.0f;
}

Settings referenceSettings(const Settings& base) {
  Settings s = base;
  s.traceScale = 1.0f;
  s.updateInterval = 1;
  s.temporalReuse = false;
  s.emptySpaceSkipping = false;
  s.noiseLevelOfDetail = false;  // the subpixel jitter filters the noise over the pixel
  s.lightEveryOtherStep = false;
  s.maxViewSteps = 8192;
  s.viewStepMetres = 12.0f;
  s.viewStepGrowth = 0.0015f;
  s.lightSteps = 24;
  s.cheapSampling = false;
  s.transmittanceCutoff = 1e-4f;
  s.detailDistanceMetres = std::max(base.detailDistanceMetres, base.maxDistanceMetres);
  s.jitter = Jitter::BayerHaltonSubpixel;
  s.heroLight = HeroLight::Marched;
  s.nearFieldMetres = 0.0f;  // every pixel is marched every frame, nearer and farther alike
  // The shadow map, fine and fresh (whether there is one at all is the base's).
  s.shadowMapResolution = 512;
  s.shadowSteps = 64;
  s.shadowCascadesPerFrame = 4;
  s.shadowFramesPerCascade = 1;
  s.terrainShadowSteps = 256;
  s.cloudShadowsOnClouds = true;
  if (base.godRaySamples > 0) s.godRaySamples = 64;
  return s;
}

const char* qualityName(Quality quality) {
  switch (quality) {
    case Quality::Low:
      return "Low";
    case Quality::Medium:
      return "Medium";
    case Quality::High:
      return "High";
    case Quality::Ultra:
      return "Ultra";
    case Quality::Reference:
      return "Reference";
  }
  return "?";
}

bool parseQuality(std::string_view name, Quality* quality) {
  for (Quality q :
       {Quality::Low, Quality::Medium, Quality::High, Quality::Ultra, Quality::Reference}) {
    const std::string_view candidate = qualityName(q);
    const bool same = std::equal(name.begin(), name.end(), candidate.begin(), candidate.end(),
                                 [](char a, char b) {
                                   return std::tolower(static_cast<unsigned char>(a)) ==
                                          std::tolower(static_cast<unsigned char>(b));
                                 });
    if (same) {
      *quality = q;
      return true;
    }
  }
  return false;
}

Settings settingsFor(Quality quality, const Settings& base) {
  if (quality == Quality::Reference) return referenceSettings(base);
  Settings s = base;
  s.temporalReuse = true;
  s.cheapSampling = true;
  s.jitter = Jitter::BayerHalton;
  s.transmittanceCutoff = 0.01f;
  // Empty-space skipping and the noise's level of detail do not pay on lavapipe, where the
  // presets are measured (around High: 2% faster without either, as accurate;
  // docs/benchmark/results.md, "Cost knobs"), so no preset has them; a host on a GPU whose
  // benchmark says otherwise turns them on.
  s.emptySpaceSkipping = false;
  s.noiseLevelOfDetail = false;
  // Detail erosion reaches as far as the clouds are drawn in every preset: it costs only where
  // cloud is, and far clouds seen from above are visibly fatter without it.
  s.detailDistanceMetres = 60000.0f;
  // The near/far split (nearFieldMetres) is High's and Ultra's, at Nubis³'s 200 m: flying
  // through dense layer it is 1.2 dB more accurate than one march (docs/how-a-frame-is-made.md).
  // Medium keeps one march: inside a cloud the near field's every-pixel march doubles its time.
  constexpr float kNearFieldMetres = 200.0f;
  s.nearFieldMetres = 0.0f;
  // The clouds' shadow on themselves beyond the light cone is High's and Ultra's: at Medium it
  // took the march from 6.5-8 to 12-15 ms on lavapipe (docs/measurements.md, "The clouds'
  // shadow on themselves").
  s.cloudShadowsOnClouds = quality == Quality::High || quality == Quality::Ultra;
  // The ladder (issue 53): each rung at most 0.6x the next one's time and at least 2 dB less
  // accurate (docs/benchmark/results.md, "Targets"); and Medium, the product's default, is
  // what the sample's 30 fps budget at 640x360 on lavapipe is measured with (issue 52). Low traces
  // a quarter of the resolution per axis, Medium half of it, upsampled spatially; High and Ultra
  // trace half of it and accumulate each output pixel's own rays (temporal upsampling), which shows
  // detail no trace pixel holds: seen from above the layer, 32.9 dB with Medium's march and one
  // edge ray, 34.1 with two.
  switch (quality) {
    case Quality::Low:
      s.traceScale = 0.25f;
      s.updateInterval = 16;
      s.maxViewSteps = 64;
      s.viewStepMetres = 120.0f;
      s.viewStepGrowth = 0.016f;
      s.lightSteps = 3;
      // The cheapest rung stays the cheapest flying inside the layer: the default 2 x 2 refresh
      // there marched four times its rays, and cost more than Medium's 4 x 4 in the default
      // scene's flight (march 8.4 against 8.7 ms, 2026-11-30).
      s.movingInsideUpdateInterval = 16;
      break;
    // Medium marches half High's samples (90 m steps growing 0.8% of the distance, four light
    // samples) and upsamples spatially: temporal upsampling with two edge rays took the default
    // scene's clouds from 13.5 to 18.6 ms a frame at 640x360 (upsample 3.4 -> 7.6 ms, march
    // 5.8 -> 6.8; 2026-12-03), and the frame from 31.5 to 27 fps headless.
    case Quality::Medium:
      s.traceScale = 0.5f;
      s.updateInterval = 16;
      s.maxViewSteps = 64;
      s.viewStepMetres = 90.0f;
      s.viewStepGrowth = 0.008f;
      s.coarseStepFactor = 3.3f;
      s.lightSteps = 4;
      s.temporalUpsampling = false;
      s.edgeRays = 0;
      // Flying inside the layer it keeps its 4 x 4 refresh: High's 2 x 2 there marches four
      // times the rays, and took the default scene's first 150 frames to 34 ms a frame.
      s.movingInsideUpdateInterval = 16;
      break;
    // High: short steps (35 m, growing 0.15% of the distance as the Reference's) that show the rims
    // of clouds tens of kilometres away seen from above the layer, and the near field.
    case Quality::High:
      s.traceScale = 0.5f;
      s.updateInterval = 16;
      s.maxViewSteps = 168;
      s.viewStepMetres = 35.0f;
      s.viewStepGrowth = 0.0015f;  // the Reference's
      s.coarseStepFactor = 3.3f;
      // Four light samples, not six: the benchmark of 2026-11-30 measured four both cheaper
      // (13.7 against 14.0 ms) and nearer the Reference (46.5 against 45.9 dB pooled), the
      // march's 35 m steps already resolving what the fifth and sixth sample added.
      s.lightSteps = 4;
      s.transmittanceCutoff = 0.005f;
      s.temporalUpsampling = true;
      s.edgeRays = 2;
      s.nearFieldMetres = kNearFieldMetres;
      break;
    // Ultra is High refreshed 4x as often, with finer steps still and more light samples: the
    // benchmark's knobs that bought the most accuracy for their time around High. (A full-
    // resolution trace refreshed every 4th frame cost 8x High for less accuracy than either.)
    case Quality::Ultra:
      s.traceScale = 0.5f;
      s.updateInterval = 4;
      s.maxViewSteps = 224;
      s.viewStepMetres = 30.0f;
      s.viewStepGrowth = 0.0015f;  // the Reference's
      s.coarseStepFactor = 3.3f;
      s.lightSteps = 10;
      s.transmittanceCutoff = 0.002f;
      s.temporalUpsampling = true;
      s.nearFieldMetres = kNearFieldMetres;
      break;
    case Quality::Reference:
      break;
  }
  // The shadow map's cost knobs (whether there is one at all is the base's): samples along
  // each texel's sun ray, and texels for Ultra.
  const std::uint32_t shadowSteps[] = {8, 12, 16, 24};
  s.shadowSteps = shadowSteps[static_cast<std::size_t>(quality)];
  const std::uint32_t terrainShadowSteps[] = {24, 32, 48, 64};
  s.terrainShadowSteps = terrainShadowSteps[static_cast<std::size_t>(quality)];
  s.shadowMapResolution = quality == Quality::Ultra ? 256u : 128u;
  s.shadowCascadesPerFrame = 1;
  // A cascade's turn spread over frames (a quarter of its rows a frame at Medium): the finest
  // cascade is then remade every 16 frames at Low, 8 at Medium, 4 at High, 2 at Ultra, the
  // others three times less often; the wind's drift carries them in between.
  const std::uint32_t shadowFramesPerCascade[] = {8, 4, 2, 1};
  s.shadowFramesPerCascade = shadowFramesPerCascade[static_cast<std::size_t>(quality)];
  // God rays' samples along each texel's way to the sun (whether there are any is the base's).
  const std::uint32_t godRaySamples[] = {12, 16, 24, 32};
  if (base.godRaySamples > 0) {
    s.godRaySamples = godRaySamples[static_cast<std::size_t>(quality)];
  }
  return s;
}

}  // namespace clouds
