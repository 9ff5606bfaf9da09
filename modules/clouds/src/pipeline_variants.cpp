#include "pipeline_variants.h"

#include <tuple>

#include "cloud_types.h"
#include "uniforms.h"

namespace clouds::detail {

namespace {
constexpr std::size_t kKeyCapacity = std::tuple_size_v<decltype(SpecializationKey::values)>;
static_assert(shader::kMarchSpecCount <= kKeyCapacity && shader::kUpsampleSpecCount <= kKeyCapacity,
              "a program has more specialization constants than a key holds");
}  // namespace

SpecializationKey marchKey(const Settings& settings, bool workCounters,
                           std::uint32_t shadowMapReads, std::uint32_t edgeRays,
                           std::uint32_t heroClouds, bool nearField, bool skyLight) {
  const MarchVariant v = marchVariant(settings);
  SpecializationKey key;
  key.values[shader::kSpecJitter] = v.jitter;
  key.values[shader::kSpecDetail] = v.detail;
  key.values[shader::kSpecCheapSampling] = v.cheapSampling;
  key.values[shader::kSpecMultipleScattering] = v.multipleScattering;
  key.values[shader::kSpecLightSteps] = v.lightSteps;
  key.values[shader::kSpecCounters] = workCounters ? 1u : 0u;
  key.values[shader::kSpecEmptySpace] = v.emptySpace;
  key.values[shader::kSpecShadowMapRead] = shadowMapReads;
  key.values[shader::kSpecLightReuse] = v.lightReuse;
  key.values[shader::kSpecEdgeRays] =
      v.edgeRays != 0u && !nearField && !skyLight ? edgeRays : shader::kEdgeRaysOff;
  key.values[shader::kSpecHeroClouds] = heroClouds;
  // Only a march that draws hero clouds has a use for their lighting's variants.
  key.values[shader::kSpecHeroLight] =
      heroClouds != shader::kHeroCloudsOff ? v.heroLight : shader::kHeroLightCone;
  key.values[shader::kSpecNearField] = nearField ? 1u : 0u;
  key.values[shader::kSpecSkyLight] = skyLight ? 1u : 0u;
  key.values[shader::kSpecWeatherRegions] = settings.weatherRegions;
  key.values[shader::kSpecVortex] = settings.superstorms;
  key.count = shader::kMarchSpecCount;
  return key;
}

SpecializationKey reconstructKey(std::uint32_t history, bool lightning) {
  SpecializationKey key;
  key.values[shader::kSpecHistory] = history;
  key.values[shader::kSpecReconstructLightning] = lightning ? 1u : 0u;
  key.count = shader::kReconstructSpecCount;
  return key;
}

SpecializationKey nearResolveKey(bool history) {
  SpecializationKey key;
  key.values[shader::kSpecNearHistory] = history ? 1u : 0u;
  key.count = shader::kNearResolveSpecCount;
  return key;
}

SpecializationKey upsampleKey(bool temporalUpsampling, std::uint32_t outputHistory, bool hazed,
                              bool godRays, bool lightning, bool depthOutput, bool nearField) {
  SpecializationKey key;
  key.values[shader::kSpecTemporalUpsampling] = temporalUpsampling ? 1u : 0u;
  key.values[shader::kSpecOutputHistory] = outputHistory;
  key.values[shader::kSpecAerialPerspective] = hazed ? 1u : 0u;
  key.values[shader::kSpecUpsampleGodRays] = godRays ? 1u : 0u;
  key.values[shader::kSpecUpsampleLightning] = lightning ? 1u : 0u;
  key.values[shader::kSpecUpsampleDepthOutput] = depthOutput ? 1u : 0u;
  key.values[shader::kSpecUpsampleNearField] = nearField ? 1u : 0u;
  key.count = shader::kUpsampleSpecCount;
  return key;
}

bool writesCloudDepth(const Settings& settings) {
  return settings.depthOutput || settings.lightningBoltSegments > 0;
}

SpecializationKey boltsKey(bool hazed) {
  SpecializationKey key;
  key.values[shader::kSpecBoltsAerialPerspective] = hazed ? 1u : 0u;
  key.count = shader::kBoltsSpecCount;
  return key;
}

SpecializationKey godRayOcclusionKey(bool nearField) {
  SpecializationKey key;
  key.values[shader::kSpecGodRayNearField] = nearField ? 1u : 0u;
  key.count = shader::kGodRayOcclusionSpecCount;
  return key;
}

SpecializationKey godRaysKey(std::uint32_t light) {
  SpecializationKey key;
  key.values[shader::kSpecGodRayLight] = light;
  key.count = shader::kGodRaySpecCount;
  return key;
}

SpecializationKey shadowMapKey(const Settings& settings, std::uint32_t heroClouds) {
  SpecializationKey key;
  key.values[shader::kSpecShadowEmptySpace] = settings.emptySpaceSkipping ? 1u : 0u;
  key.values[shader::kSpecShadowHeroClouds] = heroClouds;
  key.values[shader::kSpecShadowWeatherRegions] = settings.weatherRegions;
  key.values[shader::kSpecShadowVortex] = settings.superstorms;
  key.count = shader::kShadowSpecCount;
  return key;
}

std::vector<std::pair<Program, SpecializationKey>> variantsFor(const Settings& settings,
                                                               bool workCounters, bool heroClouds) {
  const std::uint32_t histories[] = {shader::kHistoryNone, shader::kHistoryInPlace,
                                     shader::kHistoryReprojected};
  std::vector<std::pair<Program, SpecializationKey>> variants;
  // The tiles' march, and with edge rays the edge rays' march; with hero cloud assets, each
  // without them, with them as authored and with living ones.
  const std::uint32_t heroVariants[] = {shader::kHeroCloudsOff, shader::kHeroCloudsAuthored,
                                        shader::kHeroCloudsLiving};
  const auto addMarch = [&](std::uint32_t shadowMapReads) {
    for (std::uint32_t heroes : heroVariants) {
      if (heroes != shader::kHeroCloudsOff && !heroClouds) continue;
      variants.emplace_back(Program::March, marchKey(settings, workCounters, shadowMapReads,
                                                     shader::kEdgeRaysFind, heroes));
      if (settings.nearFieldMetres > 0.0f) {
        variants.emplace_back(Program::March, marchKey(settings, workCounters, shadowMapReads,
                                                       shader::kEdgeRaysFind, heroes, true));
      }
      if (settings.skyLight) {
        variants.emplace_back(Program::March, marchKey(settings, workCounters, shadowMapReads,
                                                       shader::kEdgeRaysFind, heroes, false, true));
      }
      if (marchVariant(settings).edgeRays == 0u) continue;
      variants.emplace_back(Program::March, marchKey(settings, workCounters, shadowMapReads,
                                                     shader::kEdgeRaysMarch, heroes));
    }
  };
  addMarch(0u);
  // With lightning, frames without a flash write no glow.
  for (std::uint32_t history : histories) {
    for (bool lightning : {false, true}) {
      if (lightning && settings.lightningFlashes == 0) continue;
      variants.emplace_back(Program::Reconstruct, reconstructKey(history, lightning));
    }
  }
  if (settings.nearFieldMetres > 0.0f) {
    for (bool history : {false, true})
      variants.emplace_back(Program::NearResolve, nearResolveKey(history));
  }
  // Without temporal upsampling there is never an output history to read.
  const bool upsampling = upsamplesTemporally(settings);
  for (std::uint32_t history : histories) {
    if (!upsampling && history != shader::kHistoryNone) continue;
    for (bool hazed : {false, true}) {
      // With god rays, frames whose sun is off screen add no light; with lightning, frames
      // without a flash glow with none.
      for (bool godRays : {false, true}) {
        if (godRays && settings.godRaySamples == 0) continue;
        for (bool lightning : {false, true}) {
          if (lightning && settings.lightningFlashes == 0) continue;
          // With a near field, frames away from the clouds have none.
          for (bool nearField : {false, true}) {
            if (nearField && settings.nearFieldMetres == 0.0f) continue;
            variants.emplace_back(Program::Upsample,
                                  upsampleKey(upsampling, history, hazed, godRays, lightning,
                                              writesCloudDepth(settings), nearField));
          }
        }
      }
    }
  }
  // The light volume's sweep, only for hero clouds lit by it.
  if (heroClouds && settings.heroLight == HeroLight::Volume) {
    variants.emplace_back(Program::HeroLight, SpecializationKey{});
  }
  // The detail noise's generators, only for hero clouds that are up-rezzed.
  if (heroClouds && settings.heroDetail == HeroDetail::Uprezzed) {
    variants.emplace_back(Program::HeroNoise, SpecializationKey{});
    variants.emplace_back(Program::HeroNoiseMip, SpecializationKey{});
  }
  // No shadow map, no shadow pipelines (and no terrain shadow: it lives in the map).
  if (settings.shadowCascades > 0) {
    variants.emplace_back(Program::ShadowMap, shadowMapKey(settings));
    if (heroClouds) {
      variants.emplace_back(Program::ShadowMap,
                            shadowMapKey(settings, shader::kHeroCloudsAuthored));
      variants.emplace_back(Program::ShadowMap, shadowMapKey(settings, shader::kHeroCloudsLiving));
    }
    variants.emplace_back(Program::TerrainShadow, SpecializationKey{});
    // A frame with a map reads the terrain's channel when the host gave its terrain, and the
    // clouds' with cloudShadowsOnClouds.
    const std::uint32_t clouds = settings.cloudShadowsOnClouds ? shader::kShadowMapReadsClouds : 0u;
    addMarch(shader::kShadowMapReadsTerrain | clouds);
    if (clouds != 0u) addMarch(clouds);
  }
  // No room for bolts, no bolt pipelines.
  if (settings.lightningBoltSegments > 0) {
    for (bool hazed : {false, true})
      variants.emplace_back(Program::LightningBolts, boltsKey(hazed));
  }
  // No god rays, no god-ray pipelines (and the upsample without their light, above).
  if (settings.godRaySamples > 0) {
    // With a near field, frames away from the clouds have none.
    for (bool nearField : {false, true}) {
      if (nearField && settings.nearFieldMetres == 0.0f) continue;
      variants.emplace_back(Program::GodRayOcclusion, godRayOcclusionKey(nearField));
    }
    for (std::uint32_t light : {shader::kGodRaysMaskHaze, shader::kGodRaysGlow}) {
      variants.emplace_back(Program::GodRays, godRaysKey(light));
    }
  }
  return variants;
}

}  // namespace clouds::detail
