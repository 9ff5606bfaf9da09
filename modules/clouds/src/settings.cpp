// Settings validation, the reference mode and the quality presets.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>

#include "clouds/clouds.h"

namespace clouds {
namespace {

struct Checker {
  std::string error;

  template <typename T>
  void range(const char* field, T value, T lo, T hi) {
    if (!error.empty()) return;
    const bool finite = std::isfinite(static_cast<double>(value));
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

}  // namespace

std::string validateSettings(const Settings& s) {
  Checker c;
  c.range("layerBottomMetres", s.layerBottomMetres, 0.0f, 20000.0f);
  c.range("layerTopMetres", s.layerTopMetres, 0.0f, 30000.0f);
  c.require(s.layerTopMetres > s.layerBottomMetres + 1.0f,
            "Settings.layerTopMetres = " + std::to_string(s.layerTopMetres) +
                ": must be above layerBottomMetres (" + std::to_string(s.layerBottomMetres) +
                ") by at least 1 m");
  c.range("planetRadiusMetres", s.planetRadiusMetres, 1e5f, 1e8f);
  c.range("coverage", s.coverage, 0.0f, 1.0f);
  c.range("cloudType", s.cloudType, 0.0f, 1.0f);
  c.range("typeVariation", s.typeVariation, 0.0f, 2.0f);
  c.range("densityVariation", s.densityVariation, 0.0f, 1.0f);
  c.range("weatherTileMetres", s.weatherTileMetres, 1000.0f, 1e7f);
  c.range("weatherEvolutionPerSecond", s.weatherEvolutionPerSecond, 0.0f, 1.0f);
  c.range("weatherUpdateSeconds", s.weatherUpdateSeconds, 0.0f, 3600.0f);
  c.range("densityMultiplier", s.densityMultiplier, 0.0f, 1e6f);
  c.range("extinctionPerMetre", s.extinctionPerMetre, 0.0f, 100.0f);
  c.range("anvilBias", s.anvilBias, 0.0f, 1.0f);
  c.range("shapeTileMetres", s.shapeTileMetres, 100.0f, 1e7f);
  c.range("detailTileMetres", s.detailTileMetres, 10.0f, 1e6f);
  c.range("detailErosion", s.detailErosion, 0.0f, 1.0f);
  c.range("detailDistanceMetres", s.detailDistanceMetres, 0.0f, 1e7f);
  c.range("curlTileMetres", s.curlTileMetres, 100.0f, 1e7f);
  c.range("curlStrengthMetres", s.curlStrengthMetres, 0.0f, 10000.0f);
  c.range("windDirection.x", s.windDirection.x, -1e6f, 1e6f);
  c.range("windDirection.y", s.windDirection.y, -1e6f, 1e6f);
  c.require(glm::length(s.windDirection) > 1e-6f, "Settings.windDirection: must not be zero");
  c.range("windSpeedMetresPerSecond", s.windSpeedMetresPerSecond, 0.0f, 500.0f);
  c.range("skewMetres", s.skewMetres, 0.0f, 20000.0f);
  c.range("albedo", s.albedo, 0.0f, 1.0f);
  c.range("phaseForwardG", s.phaseForwardG, -1.0f, 1.0f);
  c.range("phaseBackwardG", s.phaseBackwardG, -1.0f, 1.0f);
  c.range("phaseBackwardWeight", s.phaseBackwardWeight, 0.0f, 1.0f);
  c.range("multipleScatteringOctaves", s.multipleScatteringOctaves, 1u, 8u);
  c.range("msExtinctionScale", s.msExtinctionScale, 0.0f, 1.0f);
  c.range("msContribution", s.msContribution, 0.0f, 1.0f);
  c.range("msEccentricityScale", s.msEccentricityScale, 0.0f, 1.0f);
  c.range("inScatterStrength", s.inScatterStrength, 0.0f, 1.0f);
  c.range("inScatterDepthMetres", s.inScatterDepthMetres, 0.0f, 10000.0f);
  c.range("ambientOcclusionStrength", s.ambientOcclusionStrength, 0.0f, 1.0f);
  c.range("ambientStrength", s.ambientStrength, 0.0f, 100.0f);
  c.range("sunStrength", s.sunStrength, 0.0f, 100.0f);
  c.range("maxViewSteps", s.maxViewSteps, 1u, 16384u);
  c.range("viewStepMetres", s.viewStepMetres, 0.5f, 10000.0f);
  c.range("viewStepGrowth", s.viewStepGrowth, 0.0f, 1.0f);
  c.range("lightSteps", s.lightSteps, 0u, 64u);
  c.range("lightConeMetres", s.lightConeMetres, 1.0f, 100000.0f);
  c.range("lightConeSpread", s.lightConeSpread, 0.0f, 2.0f);
  c.range("maxDistanceMetres", s.maxDistanceMetres, 100.0f, 1e7f);
  c.range("transmittanceCutoff", s.transmittanceCutoff, 0.0f, 0.5f);
  c.range("coarseStepFactor", s.coarseStepFactor, 1.0f, 16.0f);
  c.range("emptySamplesToCoarse", s.emptySamplesToCoarse, 1u, 1000u);
  c.require(s.traceScale == 1.0f || s.traceScale == 0.5f || s.traceScale == 0.25f,
            "Settings.traceScale = " + std::to_string(s.traceScale) + ": must be 1, 0.5 or 0.25");
  c.require(
      s.updateInterval == 1 || s.updateInterval == 4 || s.updateInterval == 16 ||
          s.updateInterval == 64,
      "Settings.updateInterval = " + std::to_string(s.updateInterval) + ": must be 1, 4, 16 or 64");
  c.range("upsamplingMaxSamples", s.upsamplingMaxSamples, 1u, 15u);
  c.range("temporalFreshWeight", s.temporalFreshWeight, 0.05f, 1.0f);
  c.range("historyClampMargin", s.historyClampMargin, 0.0f, 1.0f);
  c.range("historyClampSpreadPixels", s.historyClampSpreadPixels, 0.01f, 100.0f);
  c.range("insideLayerMarginMetres", s.insideLayerMarginMetres, 0.0f, 5000.0f);
  c.range("historyResetDistanceMetres", s.historyResetDistanceMetres, 1.0f, 1e6f);
  c.range("historyResetAngleDegrees", s.historyResetAngleDegrees, 0.1f, 180.0f);
  c.range("relightResetDegrees", s.relightResetDegrees, 0.01f, 180.0f);
  c.range("relightResetRatio", s.relightResetRatio, 0.001f, 10.0f);
  c.range("shadowCascades", s.shadowCascades, 0u, 4u);
  c.range("shadowMapResolution", s.shadowMapResolution, 16u, 1024u);
  c.range("shadowNearSideMetres", s.shadowNearSideMetres, 500.0f, 1e6f);
  c.range("shadowCascadeRatio", s.shadowCascadeRatio, 1.5f, 8.0f);
  c.range("shadowSteps", s.shadowSteps, 1u, 256u);
  c.range("shadowCascadesPerFrame", s.shadowCascadesPerFrame, 1u, 4u);
  c.range("shadowFramesPerCascade", s.shadowFramesPerCascade, 1u, 8u);
  c.range("terrainShadowSteps", s.terrainShadowSteps, 1u, 1024u);
  c.range("godRaySamples", s.godRaySamples, 0u, 128u);
  c.range("godRayLength", s.godRayLength, 0.05f, 1.0f);
  c.range("godRayDecay", s.godRayDecay, 0.5f, 1.0f);
  c.range("godRayGlowStrength", s.godRayGlowStrength, 0.0f, 10.0f);
  c.require(s.jitter == Jitter::None || s.jitter == Jitter::BayerHalton ||
                s.jitter == Jitter::BayerHaltonSubpixel,
            "Settings.jitter: unknown mode " + std::to_string(static_cast<unsigned>(s.jitter)));
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
  s.maxViewSteps = 8192;
  s.viewStepMetres = 12.0f;
  s.viewStepGrowth = 0.0015f;
  s.lightSteps = 24;
  s.cheapSampling = false;
  s.transmittanceCutoff = 1e-4f;
  s.detailDistanceMetres = std::max(base.detailDistanceMetres, base.maxDistanceMetres);
  s.jitter = Jitter::BayerHaltonSubpixel;
  // The shadow map, fine and fresh (whether there is one at all is the base's).
  s.shadowMapResolution = 512;
  s.shadowSteps = 64;
  s.shadowCascadesPerFrame = 4;
  s.shadowFramesPerCascade = 1;
  s.terrainShadowSteps = 256;
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
  s.emptySpaceSkipping = true;
  s.cheapSampling = true;
  s.jitter = Jitter::BayerHalton;
  s.transmittanceCutoff = 0.01f;
  switch (quality) {
    // Low and Medium are High at a quarter-resolution trace (the benchmark's best saving per
    // dB lost: half the time for 3.5 dB); Low also takes longer steps and fewer light
    // samples. Detail erosion goes as far as High's: it costs only where cloud is, and
    // cutting it short cost Medium 14 dB seen from above the layer for 1 ms.
    case Quality::Low:
      s.traceScale = 0.25f;
      s.updateInterval = 16;
      s.maxViewSteps = 64;
      s.viewStepMetres = 120.0f;
      s.viewStepGrowth = 0.008f;
      s.lightSteps = 3;
      s.detailDistanceMetres = 60000.0f;
      break;
    case Quality::Medium:
      s.traceScale = 0.25f;
      s.updateInterval = 16;
      s.maxViewSteps = 96;
      s.viewStepMetres = 60.0f;
      s.viewStepGrowth = 0.004f;
      s.lightSteps = 6;
      s.detailDistanceMetres = 60000.0f;
      break;
    case Quality::High:
      s.traceScale = 0.5f;
      s.updateInterval = 16;
      s.maxViewSteps = 96;
      s.viewStepMetres = 60.0f;
      s.viewStepGrowth = 0.004f;
      s.lightSteps = 6;
      s.detailDistanceMetres = 60000.0f;  // to the max distance: far clouds seen from above
                                          // are visibly fatter without their erosion
      s.transmittanceCutoff = 0.005f;
      s.temporalUpsampling = true;
      break;
    case Quality::Ultra:
      s.traceScale = 1.0f;
      s.updateInterval = 4;
      s.maxViewSteps = 160;
      s.viewStepMetres = 40.0f;
      s.viewStepGrowth = 0.003f;
      s.lightSteps = 10;
      s.detailDistanceMetres = 60000.0f;
      s.transmittanceCutoff = 0.002f;
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
