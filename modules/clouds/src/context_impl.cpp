// clouds::Context::Impl: creation, prepare() and the flow of a frame (order in
// context_impl.h). The passes themselves are recorded in record_weather.cpp,
// record_trace.cpp, record_shadow.cpp, record_god_rays.cpp and record_lightning.cpp.
#include "context_impl.h"

#include <cstring>

#include "cloud_density.h"
#include "descriptor_sets.h"
#include "lightning_bolts.h"
#include "pipeline_variants.h"
#include "weather_regions.h"
#include "wind_displacement.h"

namespace clouds {

using detail::Program;

namespace {

// The storage formats the module's images use (module_images.cpp, shaders' format qualifiers).
constexpr VkFormat kStorageFormats[] = {VK_FORMAT_R8G8B8A8_UNORM,    VK_FORMAT_R16G16B16A16_SFLOAT,
                                        VK_FORMAT_R32G32_SFLOAT,     VK_FORMAT_R32_SFLOAT,
                                        VK_FORMAT_R32G32B32A32_UINT, VK_FORMAT_R32G32_UINT};

const detail::DeviceContext& checkedDevice(const detail::DeviceContext& device) {
  for (VkFormat format : kStorageFormats) {
    if (!device.supportsStorage(format)) {
      throw vkfx::Error(vkfx::Failure::Unsupported,
                        "the device cannot use format " + std::to_string(static_cast<int>(format)) +
                            " as a storage image (is shaderStorageImageExtendedFormats "
                            "enabled?)");
    }
  }
  return device;
}

// A slot's uniform block, written by vkCmdUpdateBuffer in the frames that use it.
detail::OwnedBuffer uniformBlock(const detail::DeviceContext& device, VkDeviceSize bytes,
                                 const std::string& name) {
  return detail::OwnedBuffer(
      device, bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, name);
}

}  // namespace

// Rows of the next period's weather map generated per frame: 1/16 of the map, ~3 ms on lavapipe,
// so a period of 16 frames or more has its map ready when it starts.
constexpr std::uint32_t kWeatherRowsAhead =
    static_cast<std::uint32_t>(shader::kWeatherMapSize) / 16;

Context::Impl::Impl(const CreateInfo& info, const detail::VulkanFunctions& functions)
    : info_(info),
      device_(info.device, info.physicalDevice, info.debugUtils, functions, "clouds"),
      programs_(checkedDevice(device_), info.compositeColorFormat != VK_FORMAT_UNDEFINED),
      images_(device_),
      nearestSampler_(device_.createSampler(
          VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "nearest sampler")),
      linearSampler_(device_.createSampler(VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                           "linear sampler")),
      clampedLinearSampler_(device_.createSampler(
          VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "clamped linear sampler")),
      pool_(detail::makeDescriptorPool(device_, programs_, info.maxFramesInFlight)),
      weatherSchedule_(static_cast<std::uint32_t>(shader::kWeatherMapSize), kWeatherRowsAhead) {
  if (info.passTimings) {
    timer_ =
        std::make_unique<detail::PassTimer>(device_, info.maxFramesInFlight, detail::kPassNames);
  }
  writeFixedSets();
  slots_.resize(info.maxFramesInFlight);
  for (std::uint32_t i = 0; i < info.maxFramesInFlight; ++i) {
    Slot& slot = slots_[i];
    slot.uniforms = detail::OwnedBuffer(
        device_, sizeof(shader::CloudUniforms),
        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
            VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
        "uniforms " + std::to_string(i));
    slot.counters =
        detail::OwnedBuffer(device_, shader::kCounterCount * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            "work counters " + std::to_string(i), /*hostVisible=*/true);
    slot.sceneDistance = allocateSet(Program::SceneDistance);
    slot.march = allocateSet(Program::March);
    slot.reconstruct = allocateSet(Program::Reconstruct);
    slot.nearResolve = allocateSet(Program::NearResolve);
    slot.upsample = allocateSet(Program::Upsample);
    if (programs_.has(Program::Composite)) slot.composite = allocateSet(Program::Composite);
    slot.skyAmbient = allocateSet(Program::SkyAmbient);
    slot.weatherResample = allocateSet(Program::WeatherResample);
    slot.shadowUniforms = uniformBlock(device_, sizeof(shader::CloudUniforms),
                                       "shadow uniforms " + std::to_string(i));
    slot.shadowMap = allocateSet(Program::ShadowMap);
    slot.terrainShadow = allocateSet(Program::TerrainShadow);
    slot.shadowParameters = uniformBlock(device_, sizeof(shader::MarchShadowMap),
                                         "shadow parameters " + std::to_string(i));
    slot.godRayOcclusion = allocateSet(Program::GodRayOcclusion);
    slot.godRays = allocateSet(Program::GodRays);
    slot.lightningBolts = allocateSet(Program::LightningBolts);
    slot.heroLight = allocateSet(Program::HeroLight);
    slot.skyLight = allocateSet(Program::SkyLight);
    slot.godRayLight = uniformBlock(device_, sizeof(shader::GodRayLightUniforms),
                                    "god-ray light " + std::to_string(i));
  }
}

VkDescriptorSet Context::Impl::allocateSet(Program program) {
  const VkDescriptorSetLayout layout = programs_[program].setLayout();
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool_.get();
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  detail::check(device_.fn().vkAllocateDescriptorSets(device_.device(), &info, &set),
                "vkAllocateDescriptorSets");
  return set;
}

void Context::Impl::writeFixedSets() {
  using detail::SetWriter;
  const detail::ModuleImages& im = images_;
  shapeSet_ = allocateSet(Program::ShapeNoise);
  detailSet_ = allocateSet(Program::DetailNoise);
  curlSet_ = allocateSet(Program::CurlNoise);
  SetWriter(device_, shapeSet_)
      .storageImage(shader::kGeneratorTarget, im.shapeNoise.view())
      .commit();
  SetWriter(device_, detailSet_)
      .storageImage(shader::kGeneratorTarget, im.detailNoise.view())
      .commit();
  SetWriter(device_, curlSet_).storageImage(shader::kGeneratorTarget, im.curlNoise.view()).commit();
  shapeMipSet_ = allocateSet(Program::NoiseMip);
  detailMipSet_ = allocateSet(Program::NoiseMip);
  heroNoiseSet_ = allocateSet(Program::HeroNoise);
  heroNoiseMipSet_ = allocateSet(Program::HeroNoiseMip);
  SetWriter(device_, shapeMipSet_)
      .storageImage(shader::kGeneratorTarget, im.shapeNoise.view())
      .commit();
  SetWriter(device_, detailMipSet_)
      .storageImage(shader::kGeneratorTarget, im.detailNoise.view())
      .commit();
  for (std::uint32_t i = 0; i < 2; ++i) {
    weatherSets_[i] = allocateSet(Program::Weather);
    SetWriter(device_, weatherSets_[i])
        .storageImage(shader::kGeneratorTarget, im.weatherMaps[i].view())
        .commit();
    weatherMaxFineSets_[i] = allocateSet(Program::WeatherMaxima);
    SetWriter(device_, weatherMaxFineSets_[i])
        .storageImage(shader::kMaximaSource, im.weatherMaps[i].view())
        .storageImage(shader::kMaximaTarget, im.weatherMaxFine.view())
        .commit();
  }
  weatherMaxCoarseSet_ = allocateSet(Program::WeatherMaxima);
  SetWriter(device_, weatherMaxCoarseSet_)
      .storageImage(shader::kMaximaSource, im.weatherMaxFine.view())
      .storageImage(shader::kMaximaTarget, im.weatherMaxCoarse.view())
      .commit();
}

namespace {

detail::ImageSizes imageSizesFor(const Settings& settings, VkExtent2D renderExtent) {
  const std::uint32_t d = shader::kGodRayDownsample;
  const VkExtent2D godRays =
      settings.godRaySamples > 0
          ? VkExtent2D{(renderExtent.width + d - 1) / d, (renderExtent.height + d - 1) / d}
          : VkExtent2D{0, 0};
  const VkExtent2D trace = detail::traceExtentFor(renderExtent, settings.traceScale);
  return {renderExtent,
          trace,
          upsamplesTemporally(settings),
          godRays,
          settings.lightningFlashes > 0 ? trace : VkExtent2D{0, 0},
          detail::writesCloudDepth(settings) ? renderExtent : VkExtent2D{0, 0},
          settings.nearFieldMetres > 0.0f ? detail::nearFieldExtentFor(trace) : VkExtent2D{0, 0}};
}

VkDeviceSize edgeRayListBytesFor(const Settings& settings, VkExtent2D renderExtent) {
  return detail::edgeRayListBytes(detail::traceExtentFor(renderExtent, settings.traceScale));
}

// The shadow map's cascade atlas: the cascades side by side ({0, 0}: none); and the spare
// cascade, when a cascade is made over several frames.
detail::ShadowExtents shadowExtentFor(const Settings& settings) {
  const std::uint32_t n = settings.shadowCascades > 0 ? settings.shadowMapResolution : 0;
  const std::uint32_t spare = settings.shadowFramesPerCascade > 1 ? n : 0;
  return {{settings.shadowMapResolution * settings.shadowCascades, n}, {spare, spare}};
}

}  // namespace

void Context::Impl::prepare(const Settings& settings, VkExtent2D renderExtent) {
  for (const auto& [program, key] :
       detail::variantsFor(settings, info_.workCounters, heroAtlas_ != nullptr)) {
    if (programs_.has(program)) programs_[program].prepare(key);  // composite: optional
  }
  const detail::ImageSizes sizes = imageSizesFor(settings, renderExtent);
  const VkImage radiance = images_.radiance.image();
  const VkImage depth = images_.depth.image();
  if (!images_.fit(sizes) && images_.grow(sizes, lastFrameIndex_)) {
    temporal_.forget("images resized");
  }
  // New outputs are undefined until written or cleared.
  if (images_.radiance.image() != radiance || images_.depth.image() != depth) {
    outputsHoldClearSky_ = false;
  }
  if (images_.fitShadow(shadowExtentFor(settings), lastFrameIndex_)) shadowCascades_.forget();
  if (images_.fitSkyLight(settings.skyLight, lastFrameIndex_)) skyLightWhole_ = true;
  // The sky light's measures, only for settings that make it.
  if (settings.skyLight) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].skyLightMeasures.buffer() != VK_NULL_HANDLE) continue;
      slots_[i].skyLightMeasures = detail::OwnedBuffer(
          device_, sizeof(shader::SkyLightMeasures), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
          "sky light measures " + std::to_string(i), /*hostVisible=*/true);
    }
  }
  if (heroAtlas_ && settings.heroDetail == HeroDetail::Uprezzed && !heroNoise_) {
    heroNoise_ = std::make_unique<detail::HeroNoise>(device_);
    heroNoiseGenerated_ = false;
  }
  // The flashes' block, only for settings that can have flashes.
  if (settings.lightningFlashes > 0) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].lightning.buffer() != VK_NULL_HANDLE) continue;
      slots_[i].lightning = uniformBlock(device_, sizeof(shader::LightningUniforms),
                                         "lightning " + std::to_string(i));
    }
  }
  // The bolts' buffer, only for settings that can have bolts.
  if (settings.lightningBoltSegments > 0) {
    const VkDeviceSize bytes = detail::boltBufferBytes(settings.lightningBoltSegments);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].bolts.size() >= bytes) continue;
      slots_[i].bolts = detail::OwnedBuffer(
          device_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
          "lightning bolts " + std::to_string(i));
    }
  }
  // The edge rays' list, only for settings that have edge rays.
  if (detail::marchVariant(settings).edgeRays != 0u) {
    const VkDeviceSize bytes = edgeRayListBytesFor(settings, renderExtent);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].edgeRayList.size() >= bytes) continue;
      slots_[i].edgeRayList = detail::OwnedBuffer(device_, bytes,
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                  "edge ray list " + std::to_string(i));
    }
  }
  // Images retired before any frame used them can go now.
  images_.releaseRetired(lastFrameIndex_.value_or(0), info_.maxFramesInFlight);
}

std::string Context::Impl::unprepared(const Settings& settings, VkExtent2D renderExtent) const {
  for (const auto& [program, key] :
       detail::variantsFor(settings, info_.workCounters, heroAtlas_ != nullptr)) {
    if (programs_.has(program) && programs_[program].find(key) == VK_NULL_HANDLE) {
      std::string variant = programs_[program].name();
      for (std::uint32_t i = 0; i < key.count; ++i) variant += " " + std::to_string(key.values[i]);
      return "the pipeline variant \"" + variant + "\" these settings use";
    }
  }
  if (!images_.fit(imageSizesFor(settings, renderExtent))) {
    return "images for a " + std::to_string(renderExtent.width) + "x" +
           std::to_string(renderExtent.height) + " render extent at these settings";
  }
  if (!images_.shadowFits(shadowExtentFor(settings))) {
    return "the shadow map for these shadow settings";
  }
  if (heroAtlas_ && settings.heroDetail == HeroDetail::Uprezzed && !heroNoise_) {
    return "the hero clouds' detail noise";
  }
  if (settings.skyLight && !images_.skyLightMap) return "the sky light's images";
  for (const Slot& slot : slots_) {
    if (settings.skyLight && slot.skyLightMeasures.buffer() == VK_NULL_HANDLE) {
      return "the sky light's measures";
    }
    if ((settings.lightningFlashes > 0 && slot.lightning.buffer() == VK_NULL_HANDLE) ||
        slot.bolts.size() < detail::boltBufferBytes(settings.lightningBoltSegments)) {
      return "the lightning buffers for these settings";
    }
    if (detail::marchVariant(settings).edgeRays != 0u &&
        slot.edgeRayList.size() < edgeRayListBytesFor(settings, renderExtent)) {
      return "the edge rays' list for these settings";
    }
  }
  return {};
}

bool Context::Impl::shadowPrepared(const Settings& settings) const {
  if (settings.shadowCascades == 0) return true;
  const bool heroes = heroAtlas_ != nullptr;
  const auto prepared = [&](std::uint32_t heroVariant) {
    return programs_[Program::ShadowMap].find(detail::shadowMapKey(settings, heroVariant)) !=
           VK_NULL_HANDLE;
  };
  return prepared(shader::kHeroCloudsOff) &&
         (!heroes ||
          (prepared(shader::kHeroCloudsAuthored) && prepared(shader::kHeroCloudsLiving))) &&
         images_.shadowFits(shadowExtentFor(settings));
}

void Context::Impl::beginPass(VkCommandBuffer cmd, detail::Pass pass, const char* label) {
  device_.beginLabel(cmd, label);
  if (timer_) timer_->begin(cmd, detail::index(pass));
}

void Context::Impl::endPass(VkCommandBuffer cmd, detail::Pass pass) {
  if (timer_) timer_->end(cmd, detail::index(pass));
  device_.endLabel(cmd);
}

void Context::Impl::bindAndDispatch(VkCommandBuffer cmd, Program program, VkPipeline pipeline,
                                    VkDescriptorSet set, std::uint32_t width,
                                    std::uint32_t height) {
  const auto& fn = device_.fn();
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, programs_[program].layout(), 0, 1,
                             &set, 0, nullptr);
  const shader::FrameUniformsIndex index{0};
  fn.vkCmdPushConstants(cmd, programs_[program].layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(index), &index);
  fn.vkCmdDispatch(cmd, detail::groupsFor(width, shader::kWorkgroupSize2D),
                   detail::groupsFor(height, shader::kWorkgroupSize2D), 1);
}

namespace {

// Coverage = weather texel + 2 coverage - 1 (cloud_density.h) is at most 2 coverage for the
// fullest texel: with no coverage, or no extinction, in the surrounding weather and every
// region, no texel can hold cloud.
bool skyIsClear(const FrameInputs& in, const Settings& s) {
  const float fullest = shader::layerCoverage(1.0f, detail::fullestCoverage(s, in.weatherRegions));
  return fullest <= 0.0f || detail::densestMultiplier(s, in.weatherRegions) <= 0.0f ||
         s.extinctionPerMetre <= 0.0f;
}

}  // namespace

void Context::Impl::startFrame(const FrameInputs& inputs, const Settings& settings, Slot& slot) {
  if (lastFrameIndex_ == inputs.frameIndex) return;  // the frame's other call did it
  const VkCommandBuffer cmd = inputs.commandBuffer;
  images_.releaseRetired(inputs.frameIndex, info_.maxFramesInFlight);
  if (heroAtlas_) {
    heroAtlas_->releaseStaging(inputs.frameIndex, info_.maxFramesInFlight);
    heroAtlas_->recordUpload(cmd, inputs.frameIndex);
  }
  if (timer_) timer_->beginFrame(cmd, static_cast<std::uint32_t>(&slot - slots_.data()));
  images_.recordInitialLayouts(cmd);
  if (!noiseGenerated_) recordNoise(cmd);
  if (heroNoise_ && !heroNoiseGenerated_) {
    beginPass(cmd, detail::Pass::HeroNoise, "clouds: hero detail noise");
    heroNoise_->recordGeneration(cmd, programs_[Program::HeroNoise], heroNoiseSet_,
                                 programs_[Program::HeroNoiseMip], heroNoiseMipSet_,
                                 info_.noiseSeed);
    endPass(cmd, detail::Pass::HeroNoise);
    heroNoiseGenerated_ = true;
  }
  recordWeather(cmd, inputs, settings, slot);
  lastFrameIndex_ = inputs.frameIndex;
  shadowCascadesMade_ = 0;
}

void Context::Impl::dispatchShadowMap(const FrameInputs& inputs, const Settings& settings) {
  if (settings.shadowCascades == 0) return;
  const VkCommandBuffer cmd = inputs.commandBuffer;
  const auto slotIndex = static_cast<std::uint32_t>(inputs.frameIndex % slots_.size());
  Slot& slot = slots_[slotIndex];
  device_.beginLabel(cmd, "clouds: shadow map");
  startFrame(inputs, settings, slot);
  const detail::ShadowPlan plan = shadowCascades_.plan(inputs, settings);
  if (!plan.jobs.empty() || plan.slice) recordShadowMap(cmd, inputs, settings, plan, slot);
  shadowCascades_.commit(plan, inputs, settings);
  for (const detail::CascadeJob& job : plan.jobs) shadowCascadesMade_ |= 1u << job.cascade;
  if (plan.slice && plan.slice->last) shadowCascadesMade_ |= 1u << plan.slice->job.cascade;
  shadowParameters_ = shadowCascades_.parameters(
      inputs.cameraPosition, detail::windDisplacementOf(inputs, settings), settings);
  shadowFrame_ = inputs.frameIndex;
  report_.shadowCascadesMade = shadowCascadesMade_;
  device_.endLabel(cmd);
}

void Context::Impl::dispatch(const FrameInputs& inputs, const Settings& settings) {
  const VkCommandBuffer cmd = inputs.commandBuffer;
  const auto slotIndex = static_cast<std::uint32_t>(inputs.frameIndex % slots_.size());
  Slot& slot = slots_[slotIndex];
  device_.beginLabel(cmd, "clouds");
  startFrame(inputs, settings, slot);

  // Hero clouds stand wherever the host puts them, whatever the layer's coverage (those their
  // lives leave empty are left out: a frame of only those has none).
  lastHeroClouds_ = heroBlock(inputs, settings);
  const bool heroClouds = lastHeroClouds_.count.x > 0;
  const bool inHeroCloud =
      detail::cameraInHeroCloudBox(lastHeroClouds_, settings.insideLayerMarginMetres);
  const bool nearHeroCloud =
      settings.nearFieldMetres > 0.0f &&
      detail::cameraInHeroCloudBox(lastHeroClouds_, settings.nearFieldMetres);

  const VkExtent2D traceExtent = detail::traceExtentFor(inputs.renderExtent, settings.traceScale);
  const detail::TemporalFrame temporal =
      temporal_.plan(inputs, settings, traceExtent, inHeroCloud, nearHeroCloud);
  const detail::UniformContext uniformContext{info_.reversedZ, inputs.depthView != VK_NULL_HANDLE,
                                              traceExtent, inputs.renderExtent, temporal};
  FrameInputs marched = inputs;
  marched.weatherRegions = temporal_.marchedRegions(inputs, temporal);
  lastUniforms_ =
      detail::buildUniforms(marched, temporal_.marchedSettings(settings, temporal), uniformContext);
  lastUniforms_.flags |= debugFlags_;
  // Hero clouds lit by their light volume: each instance's slot, and those to sweep first.
  const bool heroLightVolume = heroClouds && settings.heroLight == HeroLight::Volume;
  const std::uint32_t heroSweep =
      heroLightVolume ? heroLight_->assignSlots(lastHeroClouds_, lastUniforms_.sunDirection) : 0u;
  // The sky light's texels this frame's march refreshes: all of them when its clouds image
  // does not hold the sky, else the next quarter.
  lastUniforms_.skyLightRefresh =
      skyLightWhole_ || inputs.reset ? shader::kSkyLightEveryTexel : skyLightRound_;
  if (skyIsClear(inputs, settings) && !heroClouds) {
    // Nothing can be marched: the outputs are the empty sky, and the next frame starts afresh.
    if (settings.skyLight) {
      recordUniforms(cmd, slot, lastUniforms_, nullptr, nullptr);
      recordSkyLight(cmd, inputs, settings, /*marched=*/false, false, 0u, shader::kHeroCloudsOff,
                     slot);
      skyLightWhole_ = true;
    }
    recordClearSky(cmd, slot);
    outputsHoldClearSky_ = true;
    if (settings.godRaySamples > 0)
      recordGodRays(cmd, inputs, settings, images_.history[0], VK_NULL_HANDLE, false, slot);
    temporal_.forget("after a clear sky");
    report_ = FrameReport{
        {0, 0}, 0, false, temporal.insideLayer, "clear sky: nothing to march", shadowCascadesMade_};
    report_.insideHeroCloud = temporal.insideHeroCloud;
  } else {
    // dispatchShadowMap() made (or kept) the shadow map before, this frame.
    const bool shadowMapMade =
        settings.shadowCascades > 0 && images_.shadowMap && shadowFrame_ == inputs.frameIndex;
    // The terrain's shadow reaches the clouds through the shadow map's terrain channel, so only
    // with a map made with the terrain; the clouds' own, beyond the light cone, through its
    // cloud channel.
    const bool terrainShadow = inputs.terrain.heightView != VK_NULL_HANDLE && shadowMapMade;
    const bool cloudsOnClouds = settings.cloudShadowsOnClouds && shadowMapMade;
    const std::uint32_t shadowMapReads = (terrainShadow ? shader::kShadowMapReadsTerrain : 0u) |
                                         (cloudsOnClouds ? shader::kShadowMapReadsClouds : 0u);
    // The march's variants that read the shadow map, and the sky light's meter at the camera,
    // read its parameters.
    const bool shadowMapParametersRead =
        shadowMapReads != 0u || (settings.skyLight && shadowMapMade);
    shader::MarchShadowMap shadow{};
    if (shadowMapParametersRead) {
      // This frame's dispatchShadowMap() placed them for this frame's camera.
      std::memcpy(&shadow.map, &shadowParameters_, sizeof(shadowParameters_));
      shadow.terrainTopMetres = inputs.terrain.maxAltitudeMetres;
    }
    recordUniforms(cmd, slot, lastUniforms_, shadowMapParametersRead ? &shadow : nullptr,
                   heroClouds ? &lastHeroClouds_ : nullptr);
    if (heroLightVolume) recordHeroLight(cmd, heroSweep, slot);
    if (inputs.skyView != VK_NULL_HANDLE || inputs.groundAlbedo) {
      recordSkyAmbient(cmd, inputs, settings, shadowMapMade, slot);
    }
    const std::uint32_t heroVariant =
        heroClouds ? detail::heroCloudVariant(lastHeroClouds_) : shader::kHeroCloudsOff;
    recordTrace(cmd, inputs, settings, temporal, traceExtent, shadowMapReads, heroVariant, slot);
    if (settings.skyLight) {
      recordSkyLight(cmd, inputs, settings, /*marched=*/true, shadowMapMade, shadowMapReads,
                     heroVariant, slot);
      // After a whole refresh the quarters start again from the first after it.
      const std::uint32_t refreshed = lastUniforms_.skyLightRefresh;
      skyLightRound_ = (refreshed == shader::kSkyLightEveryTexel ? 1u : refreshed + 1u) % 4u;
      skyLightWhole_ = false;
    }
    outputsHoldClearSky_ = false;
    temporal_.commit(temporal, inputs, settings, traceExtent);
    report_ = FrameReport{traceExtent,          temporal.tileSize,    temporal.useHistory,
                          temporal.insideLayer, temporal.resetReason, shadowCascadesMade_};
    report_.insideHeroCloud = temporal.insideHeroCloud;
    report_.nearField = temporal.nearField;
  }
  device_.endLabel(cmd);
  lastSlot_ = slotIndex;
  lastExtent_ = inputs.renderExtent;
}

void Context::Impl::composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent) {
  const auto& fn = device_.fn();
  Slot& slot = slots_[lastSlot_];
  detail::SetWriter(device_, slot.composite)
      .storageImage(shader::kCompositeHostColor, color)
      .storageImage(shader::kCompositeClouds, images_.radiance.view())
      .commit();
  device_.beginLabel(cmd, "clouds: composite");
  const detail::ComputeProgram& program = programs_[Program::Composite];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                             &slot.composite, 0, nullptr);
  shader::CompositeConstants constants{};
  constants.extent = glm::uvec2(extent.width, extent.height);
  fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                        &constants);
  const std::uint32_t group = shader::kWorkgroupSize2D;
  fn.vkCmdDispatch(cmd, (extent.width + group - 1) / group, (extent.height + group - 1) / group, 1);
  device_.endLabel(cmd);
}

Outputs Context::Impl::outputs() const {
  Outputs out;
  const detail::OwnedImage& radiance = images_.radiance;
  const detail::OwnedImage& depth = images_.depth;
  out.radiance = {radiance.image(), radiance.view(), radiance.format()};
  if (depth) out.depth = {depth.image(), depth.view(), depth.format()};  // else null
  out.extent = lastExtent_;
  const detail::OwnedImage& shadow = images_.shadowMap;
  if (shadow) {
    out.shadowMap = {shadow.image(), shadow.view(), shadow.format()};
    out.shadowParameters = shadowParameters_;
  }
  const detail::OwnedImage& sky = images_.skyLightMap;
  if (sky) out.skyLight = {sky.image(), sky.view(), sky.format()};
  const detail::OwnedImage& mask = images_.godRayMask;
  if (mask) {
    out.godRayMask = {mask.image(), mask.view(), mask.format()};
    out.godRaySun = godRayParameters_.sun;
    out.godRayBlur = godRayParameters_.blur;
  }
  return out;
}

MemoryUsage Context::Impl::memoryUsage() const {
  MemoryUsage usage = images_.memoryUsage();
  for (const Slot& slot : slots_) {
    usage.bufferBytes += slot.uniforms.bytes() + slot.counters.bytes() +
                         slot.shadowUniforms.bytes() + slot.shadowParameters.bytes() +
                         slot.godRayLight.bytes() + slot.edgeRayList.bytes();
    usage.lightningBytes += slot.lightning.bytes() + slot.bolts.bytes();
    usage.heroCloudBytes += slot.heroClouds.bytes() + slot.shadowHeroClouds.bytes();
    usage.skyLightBytes += slot.skyLightMeasures.bytes();
  }
  if (heroAtlas_) usage.heroCloudBytes += heroAtlas_->bytes();
  if (heroLight_) usage.heroCloudBytes += heroLight_->bytes();
  if (heroNoise_) usage.heroCloudBytes += heroNoise_->bytes();
  return usage;
}

shader::HeroCloudUniforms Context::Impl::heroBlock(const FrameInputs& inputs,
                                                   const Settings& settings) const {
  if (heroAtlas_ == nullptr) return {};
  shader::HeroCloudUniforms block =
      detail::heroCloudUniforms(heroAtlas_->assets(), inputs.heroClouds, inputs.cameraPosition);
  block.count.w = settings.heroDetail == HeroDetail::Uprezzed && heroNoise_
                      ? shader::kHeroDetailUprezzed
                      : shader::kHeroDetailOff;
  return block;
}

VkImageView Context::Impl::heroNoiseView() const {
  return heroNoise_ ? heroNoise_->image().view() : images_.shapeNoise.view();
}

void Context::Impl::setHeroCloudAssets(std::span<const NvdfVolume* const> assets) {
  // The host waited for the GPU (the call's contract): the old atlas can go at once.
  heroLight_.reset();
  heroAtlas_.reset();
  for (Slot& slot : slots_) {
    slot.heroClouds = detail::OwnedBuffer();
    slot.shadowHeroClouds = detail::OwnedBuffer();
  }
  sliceHeroClouds_ = shader::HeroCloudUniforms{};
  if (assets.empty()) {
    heroNoise_.reset();
    heroNoiseGenerated_ = false;
    return;
  }
  heroAtlas_ = std::make_unique<detail::HeroCloudAtlas>(device_, detail::packHeroAtlas(assets));
  heroLight_ = std::make_unique<detail::HeroLightVolume>(device_, heroAtlas_->assets());
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    slots_[i].heroClouds = uniformBlock(device_, sizeof(shader::HeroCloudUniforms),
                                        "hero clouds " + std::to_string(i));
    slots_[i].shadowHeroClouds = uniformBlock(device_, sizeof(shader::HeroCloudUniforms),
                                              "shadow hero clouds " + std::to_string(i));
  }
}

WorkCounters Context::Impl::workCounters(std::uint64_t frameIndex) const {
  const Slot& slot = slots_[frameIndex % slots_.size()];
  const auto* values = static_cast<const std::uint32_t*>(slot.counters.mapped());
  WorkCounters counters;
  if (values == nullptr || !info_.workCounters) return counters;
  counters.viewSamples = values[shader::kCounterViewSamples];
  counters.lightSamples = values[shader::kCounterLightSamples];
  counters.tracedPixels = values[shader::kCounterTracedPixels];
  counters.edgeRays = values[shader::kCounterEdgeRays];
  counters.nearFieldRays = values[shader::kCounterNearFieldRays];
  counters.earlyExits = values[shader::kCounterEarlyExits];
  counters.skippedCells = values[shader::kCounterSkippedCells];
  return counters;
}

SkyLighting Context::Impl::skyLighting(std::uint64_t frameIndex) const {
  const Slot& slot = slots_[frameIndex % slots_.size()];
  const auto* measured =
      static_cast<const shader::SkyLightMeasures*>(slot.skyLightMeasures.mapped());
  if (measured == nullptr || slot.skyLightFrame != frameIndex) return {};
  SkyLighting sky;
  sky.valid = true;
  sky.upperIrradianceOverPi = glm::vec3(measured->upperIrradianceOverPi);
  sky.zenith = glm::vec3(measured->zenith);
  sky.horizon = glm::vec3(measured->horizon);
  sky.lower = glm::vec3(measured->lower);
  sky.clearIrradianceOverPi = glm::vec3(measured->clearIrradianceOverPi);
  sky.sunTransmittanceAtCamera = measured->viewpoint.x;
  sky.seenFromAltitudeMetres = measured->viewpoint.y;
  sky.coverTopMetres = measured->viewpoint.z;
  sky.sunlitShareAround = measured->viewpoint.w;
  return sky;
}

std::vector<PassTiming> Context::Impl::passTimings(std::uint64_t frameIndex) const {
  if (!timer_) return {};
  std::vector<PassTiming> timings;
  for (const vkfx::PassTime& t :
       timer_->read(static_cast<std::uint32_t>(frameIndex % slots_.size()))) {
    timings.push_back(PassTiming{t.name, t.milliseconds});
  }
  return timings;
}

}  // namespace clouds
