// Recording a frame's trace: the uniforms, the optional sky ambient, then scene distance ->
// march -> reconstruct -> upsample; or, for a sky that cannot hold cloud, clearing the
// outputs. Barriers are compute-to-compute except for the outputs, which end visible to the
// host's compute and fragment shaders.
#include "context_impl.h"
#include "pipeline_variants.h"

namespace clouds {

using detail::Program;

namespace {

using detail::kStorageRead;
using detail::kStorageWrite;
constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
using detail::kHostReadAccess;
using detail::kHostReadStages;
constexpr VkDeviceSize kUniformBytes = sizeof(shader::CloudUniforms);

// The history variant of a frame: none, read in place (nothing moved) or reprojected.
std::uint32_t historyVariant(bool use, bool still) {
  if (!use) return shader::kHistoryNone;
  return still ? shader::kHistoryInPlace : shader::kHistoryReprojected;
}

struct TraceSamplers {
  VkSampler nearest = VK_NULL_HANDLE;
  VkSampler linear = VK_NULL_HANDLE;
  VkSampler clampedLinear = VK_NULL_HANDLE;
};

// What this frame's trace reads and writes, decided once: the host's optional images or the
// module's stand-ins for those it does not give, the history images, and the optional work.
struct TraceFrame {
  const detail::ModuleImages& images;
  TraceSamplers samplers;
  VkBuffer uniforms = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  VkImageLayout depthLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  bool hazed = false;  // the host gave an aerial perspective
  VkImageView hazeView = VK_NULL_HANDLE;
  VkImageLayout hazeLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  const detail::OwnedImage& historyIn;
  const detail::OwnedImage& historyOut;
  VkImageView outputHistoryIn = VK_NULL_HANDLE;
  VkImageView outputHistoryOut = VK_NULL_HANDLE;
  std::uint32_t shadowMapReads = 0;  // shader::kShadowMapReads*: what the march reads of this
                                     // frame's shadow map (marchKey())
  bool edgeRays = false;             // detail::marchesEdgeRays()
  // The hero clouds' atlas and block. Without them, stand-ins the march's variant never reads:
  // the shape noise (RGBA8 3D) and the frame's uniforms.
  VkImageView heroAtlas = VK_NULL_HANDLE;
  VkBuffer heroBlock = VK_NULL_HANDLE;
  VkImageView heroLight = VK_NULL_HANDLE;  // their light volume, or a 1-texel stand-in
  VkImageView heroNoise = VK_NULL_HANDLE;  // their detail noise, or a stand-in
  // The near field (TemporalFrame::nearField): this frame's samples, and last frame's and this
  // frame's resolved near field; without one, stand-ins of their format (the marched samples)
  // that the variants without it never touch.
  bool nearField = false;
  bool nearHistoryUsable = false;
  VkImageView nearSamples = VK_NULL_HANDLE;
  VkImageView nearHistoryIn = VK_NULL_HANDLE;
  VkImageView nearResolved = VK_NULL_HANDLE;
};

// The hero clouds' images and block (views null without them this frame).
struct HeroBindings {
  VkImageView atlas = VK_NULL_HANDLE;
  VkBuffer block = VK_NULL_HANDLE;
  VkImageView light = VK_NULL_HANDLE;
  VkImageView noise = VK_NULL_HANDLE;
};

TraceFrame traceFrame(const detail::ModuleImages& im, const TraceSamplers& samplers,
                      VkBuffer uniforms, const FrameInputs& inputs, const Settings& settings,
                      const detail::TemporalFrame& temporal, std::uint32_t shadowMapReads,
                      const HeroBindings& heroes) {
  const bool hasDepth = inputs.depthView != VK_NULL_HANDLE;
  const FrameInputs::AerialPerspective& haze = inputs.aerialPerspective;
  const bool hazed = haze.view != VK_NULL_HANDLE;
  // Without temporal upsampling the upsample pass never touches its output history: any
  // storage image of the format fills the bindings.
  const bool upsampling = temporal.upsampleTemporally;
  const VkImageView noOutputHistory = im.samplesPlaceholder.view();
  return TraceFrame{
      .images = im,
      .samplers = samplers,
      .uniforms = uniforms,
      .depthView = hasDepth ? inputs.depthView : im.depthPlaceholder.view(),
      .depthLayout = hasDepth ? inputs.depthLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
      .hazed = hazed,
      .hazeView = hazed ? haze.view : im.hazePlaceholder.view(),
      .hazeLayout = hazed ? haze.layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
      .historyIn = im.history[temporal.readHistory],
      .historyOut = im.history[temporal.writeHistory],
      .outputHistoryIn =
          upsampling ? im.outputHistory[temporal.readHistory].view() : noOutputHistory,
      .outputHistoryOut =
          upsampling ? im.outputHistory[temporal.writeHistory].view() : noOutputHistory,
      .shadowMapReads = shadowMapReads,
      .edgeRays = detail::marchesEdgeRays(settings, temporal),
      .heroAtlas = heroes.atlas != VK_NULL_HANDLE ? heroes.atlas : im.shapeNoise.view(),
      .heroBlock = heroes.atlas != VK_NULL_HANDLE ? heroes.block : uniforms,
      .heroLight = heroes.light != VK_NULL_HANDLE ? heroes.light : im.noHeroLight.view(),
      .heroNoise = heroes.noise != VK_NULL_HANDLE ? heroes.noise : im.shapeNoise.view(),
      .nearField = temporal.nearField,
      .nearHistoryUsable = temporal.useHistory,
      .nearSamples = temporal.nearField ? im.nearSamples.view() : im.traceSamples.view(),
      // Ping-pong by the frame's place in the sequence, which alternates while there is history.
      .nearHistoryIn = temporal.nearField ? im.nearHistory[1 - temporal.temporalIndex % 2].view()
                                          : im.traceSamples.view(),
      .nearResolved = temporal.nearField ? im.nearHistory[temporal.temporalIndex % 2].view()
                                         : im.traceSamples.view(),
  };
}

void writeSceneDistanceSet(const detail::DeviceContext& device, VkDescriptorSet set,
                           const TraceFrame& frame) {
  using namespace shader;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .sampledImage(kSceneDistanceHostDepth, frame.depthView, frame.samplers.nearest,
                    frame.depthLayout)
      .storageImage(kSceneDistanceOut, frame.images.sceneDistance.view())
      .commit();
}

void writeMarchSet(const detail::DeviceContext& device, VkDescriptorSet set,
                   const TraceFrame& frame, const detail::OwnedImage& weatherMap,
                   const detail::OwnedBuffer& counters,
                   const detail::OwnedBuffer& shadowMapParameters,
                   const detail::OwnedBuffer& edgeRayList) {
  using namespace shader;
  const detail::ModuleImages& im = frame.images;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .storageImage(kMarchShapeNoise, im.shapeNoise.view())
      .storageImage(kMarchDetailNoise, im.detailNoise.view())
      .storageImage(kMarchWeatherMap, weatherMap.view())
      .storageImage(kMarchCurlNoise, im.curlNoise.view())
      .storageImage(kMarchSceneDistance, im.sceneDistance.view())
      .storageImage(kMarchSamplesOut, im.traceSamples.view())
      .storageImage(kMarchWeatherMaxFine, im.weatherMaxFine.view())
      .storageImage(kMarchWeatherMaxCoarse, im.weatherMaxCoarse.view())
      .storageBuffer(kMarchCounters, counters.buffer(), counters.size())
      .sampledImage(kMarchCloudShadow,
                    frame.shadowMapReads != 0u ? im.shadowMap.view() : im.depthPlaceholder.view(),
                    frame.samplers.clampedLinear,
                    frame.shadowMapReads != 0u ? VK_IMAGE_LAYOUT_GENERAL
                                               : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .uniformBuffer(kMarchCloudShadowParameters, shadowMapParameters.buffer(),
                     sizeof(MarchShadowMap))
      // Read only by frames that march edge rays (kFlagEdgeRays), which have a history; the
      // variants without edge rays never touch the list, for which the counters stand in.
      .storageImage(kMarchTraceHistory, frame.historyIn.view())
      .storageBuffer(kMarchEdgeRayList, frame.edgeRays ? edgeRayList.buffer() : counters.buffer(),
                     frame.edgeRays ? edgeRayList.size() : counters.size())
      .storageImage(kMarchHeroAtlas, frame.heroAtlas)
      .uniformBuffer(kMarchHeroClouds, frame.heroBlock, sizeof(HeroCloudUniforms))
      .storageImage(kMarchHeroLight, frame.heroLight)
      .storageImage(kMarchHeroNoise, frame.heroNoise)
      .storageImage(kMarchNearFieldOut, frame.nearSamples)
      // Without a sky light, a stand-in of its format the variants without it never touch.
      .storageImage(kMarchSkyLightOut,
                    im.skyLightClouds ? im.skyLightClouds.view() : im.radiance.view())
      .commit();
}

void writeReconstructSet(const detail::DeviceContext& device, VkDescriptorSet set,
                         const TraceFrame& frame, const detail::OwnedBuffer& flashes) {
  using namespace shader;
  const detail::ModuleImages& im = frame.images;
  // Without room for flashes, stand-ins: the frame's uniforms for their block and the
  // radiance output (of the glow's format) for the glow; the variant never touches them.
  const bool glowRoom = flashes.buffer() != VK_NULL_HANDLE;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .storageImage(kReconstructFresh, im.traceSamples.view())
      .storageImage(kReconstructHistory, frame.historyIn.view())
      .storageImage(kReconstructOut, frame.historyOut.view())
      .uniformBuffer(kReconstructFlashes, glowRoom ? flashes.buffer() : frame.uniforms,
                     sizeof(LightningUniforms))
      .storageImage(kReconstructGlow, glowRoom ? im.lightningGlow.view() : im.radiance.view())
      .storageImage(kReconstructSceneDistance, im.sceneDistance.view())
      .commit();
}

void writeUpsampleSet(const detail::DeviceContext& device, VkDescriptorSet set,
                      const TraceFrame& frame) {
  using namespace shader;
  const detail::ModuleImages& im = frame.images;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .storageImage(kUpsampleTraceSamples, frame.historyOut.view())
      .sampledImage(kUpsampleHostDepth, frame.depthView, frame.samplers.nearest, frame.depthLayout)
      .storageImage(kUpsampleRadianceOut, im.radiance.view())
      // Without a depth output, a stand-in the variant never stores to.
      .storageImage(kUpsampleDepthOut, im.depth ? im.depth.view() : im.noDepthOutput.view())
      .storageImage(kUpsampleFresh, im.traceSamples.view())
      .storageImage(kUpsampleHistory, frame.outputHistoryIn)
      .storageImage(kUpsampleHistoryOut, frame.outputHistoryOut)
      .sampledImage(kUpsampleAerialPerspective, frame.hazeView, frame.samplers.linear,
                    frame.hazeLayout)
      // Without a glow, a stand-in: the variants without lightning never read it.
      .sampledImage(
          kUpsampleLightningGlow,
          im.lightningGlow ? im.lightningGlow.view() : im.depthPlaceholder.view(),
          frame.samplers.linear,
          im.lightningGlow ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .sampledImage(
          kUpsampleGodRayLight, im.godRayLight ? im.godRayLight.view() : im.depthPlaceholder.view(),
          frame.samplers.clampedLinear,
          im.godRayLight ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .storageImage(kUpsampleNearField, frame.nearResolved)
      .commit();
}

void writeNearResolveSet(const detail::DeviceContext& device, VkDescriptorSet set,
                         const TraceFrame& frame) {
  using namespace shader;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .storageImage(kNearResolveFresh, frame.nearSamples)
      .storageImage(kNearResolveHistory, frame.nearHistoryIn)
      .storageImage(kNearResolveOut, frame.nearResolved)
      .commit();
}

void writeBoltsSet(const detail::DeviceContext& device, VkDescriptorSet set,
                   const TraceFrame& frame, const detail::OwnedBuffer& bolts) {
  using namespace shader;
  const detail::ModuleImages& im = frame.images;
  detail::SetWriter(device, set)
      .uniformBuffer(kBindingUniforms, frame.uniforms, kUniformBytes)
      .sampledImage(kBoltsHostDepth, frame.depthView, frame.samplers.nearest, frame.depthLayout)
      .storageImage(kBoltsRadiance, im.radiance.view())
      .storageImage(kBoltsDepth, im.depth.view())
      .sampledImage(kBoltsAerialPerspective, frame.hazeView, frame.samplers.linear,
                    frame.hazeLayout)
      .storageBuffer(kBoltsPieces, bolts.buffer(), bolts.size())
      .commit();
}

void resetWorkCounters(const detail::DeviceContext& device, VkCommandBuffer cmd,
                       const detail::OwnedBuffer& counters) {
  device.fn().vkCmdFillBuffer(cmd, counters.buffer(), 0, VK_WHOLE_SIZE, 0u);
  detail::memoryBarrier(device, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, kStorageRead | kStorageWrite);
}

// For the host, once the frame completed (Context::workCounters()).
void makeWorkCountersReadable(const detail::DeviceContext& device, VkCommandBuffer cmd) {
  detail::memoryBarrier(device, cmd, kCompute, kStorageWrite, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_READ_BIT);
}

// The march's second dispatch: one invocation per edge tile the first one listed, as many
// groups as the list says.
void dispatchListedEdgeTiles(const detail::DeviceContext& device, VkCommandBuffer cmd,
                             VkPipeline edgeRaysMarch, const detail::OwnedBuffer& edgeRayList) {
  detail::memoryBarrier(device, cmd, kCompute, kStorageWrite,
                        kCompute | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        kStorageRead | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
  device.fn().vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, edgeRaysMarch);
  device.fn().vkCmdDispatchIndirect(cmd, edgeRayList.buffer(), 0);
}

// The upsample's outputs, for the bolts' pass, which reads and writes them next, or else for
// the host's reads.
void makeOutputsVisible(const detail::DeviceContext& device, VkCommandBuffer cmd,
                        const detail::ModuleImages& im, bool toBolts) {
  im.forEachOutput([&](const detail::OwnedImage& image) {
    detail::barrier(device, cmd, image.image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    kCompute, kStorageWrite, toBolts ? kCompute : kHostReadStages,
                    toBolts ? kStorageRead | kStorageWrite : kHostReadAccess);
  });
}

}  // namespace

void Context::Impl::recordUniforms(VkCommandBuffer cmd, Slot& slot,
                                   const shader::CloudUniforms& uniforms,
                                   const shader::MarchShadowMap* shadow,
                                   const shader::HeroCloudUniforms* heroes) {
  // The previous frame of this slot has completed (host contract), but earlier commands in
  // this queue may still read it: order the update after them.
  detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT | kStorageRead,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.uniforms.buffer(), 0, sizeof(uniforms), &uniforms);
  // Only the march's variant that reads the shadow map reads it.
  if (shadow != nullptr) {
    device_.fn().vkCmdUpdateBuffer(cmd, slot.shadowParameters.buffer(), 0, sizeof(*shadow), shadow);
  }
  // Only the march's hero variant reads it.
  if (heroes != nullptr) {
    device_.fn().vkCmdUpdateBuffer(cmd, slot.heroClouds.buffer(), 0, sizeof(*heroes), heroes);
  }
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT | kStorageRead | kStorageWrite);
}

void Context::Impl::recordSkyAmbient(VkCommandBuffer cmd, const FrameInputs& inputs,
                                     const Settings& settings, bool shadowMapMade, Slot& slot) {
  const auto& fn = device_.fn();
  const bool hasSky = inputs.skyView != VK_NULL_HANDLE;
  const bool groundShadow = inputs.groundAlbedo && shadowMapMade;
  // The last frame's sky light lights what cloud bases see, unless the camera cut since (it saw
  // another place) or the last frame made none.
  const Slot& last = slots_[(inputs.frameIndex + slots_.size() - 1) % slots_.size()];
  const bool fromSkyLight = settings.skyLight && !inputs.reset && inputs.frameIndex > 0 &&
                            last.skyLightFrame == inputs.frameIndex - 1;
  shader::AmbientConstants constants{};
  constants.groundAlbedo = inputs.groundAlbedo.value_or(glm::vec3(0.0f));
  constants.flags = (hasSky ? shader::kAmbientFromSkyImage : 0u) |
                    (inputs.groundAlbedo ? shader::kAmbientGroundLight : 0u) |
                    (groundShadow ? shader::kAmbientGroundShadow : 0u) |
                    (fromSkyLight ? shader::kAmbientFromSkyLight : 0u);
  constants.shadowCascades = settings.shadowCascades;
  constants.shadowTexels = settings.shadowMapResolution;
  // Without a sky image or a shadow map, a placeholder fills the binding the shader skips.
  const VkImageView placeholder = images_.depthPlaceholder.view();
  constexpr VkImageLayout kPlaceholderLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  beginPass(cmd, detail::Pass::SkyAmbient, "clouds: sky ambient");
  // The last frame's measures were written by its sky light pass, earlier on the queue.
  if (fromSkyLight) {
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  }
  const VkBuffer lastMeasures =
      fromSkyLight ? last.skyLightMeasures.buffer() : slot.uniforms.buffer();
  detail::SetWriter(device_, slot.skyAmbient)
      .storageBuffer(shader::kSkyAmbientUniforms, slot.uniforms.buffer(),
                     sizeof(shader::CloudUniforms))
      .sampledImage(shader::kSkyAmbientSky, hasSky ? inputs.skyView : placeholder,
                    linearSampler_.get(), hasSky ? inputs.skyLayout : kPlaceholderLayout)
      .sampledImage(
          shader::kSkyAmbientShadowMap, groundShadow ? images_.shadowMap.view() : placeholder,
          clampedLinearSampler_.get(), groundShadow ? VK_IMAGE_LAYOUT_GENERAL : kPlaceholderLayout)
      .storageBuffer(shader::kSkyAmbientLastSkyLight, lastMeasures,
                     sizeof(shader::SkyLightMeasures))
      .commit();
  const detail::ComputeProgram& program = programs_[Program::SkyAmbient];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                             &slot.skyAmbient, 0, nullptr);
  fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                        &constants);
  fn.vkCmdDispatch(cmd, 1, 1, 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT);
  endPass(cmd, detail::Pass::SkyAmbient);
}

void Context::Impl::recordSkyLight(VkCommandBuffer cmd, const FrameInputs& inputs,
                                   const Settings& settings, bool marched, bool shadowMapMade,
                                   std::uint32_t shadowMapReads, std::uint32_t heroClouds,
                                   Slot& slot) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::SkyLight, "clouds: sky light");
  // The map and the measures may still be read by earlier commands (the host's reads of the
  // last frame's).
  detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, kCompute,
                        kStorageWrite);
  if (marched) {
    // The rays due this frame (CloudUniforms::skyLightRefresh): every texel of the upper half,
    // or one in each 2 x 2 block.
    const bool every = lastUniforms_.skyLightRefresh == shader::kSkyLightEveryTexel;
    const std::uint32_t width = shader::kSkyLightWidth / (every ? 1u : 2u);
    const std::uint32_t height = shader::kSkyLightHeight / 2u / (every ? 1u : 2u);
    bindAndDispatch(cmd, Program::March,
                    programs_[Program::March].find(
                        detail::marchKey(settings, info_.workCounters, shadowMapReads,
                                         shader::kEdgeRaysFind, heroClouds, false, true)),
                    slot.march, width, height);
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  }
  const bool groundShadow = inputs.groundAlbedo && shadowMapMade;
  shader::SkyLightConstants constants{};
  constants.groundAlbedo = inputs.groundAlbedo.value_or(glm::vec3(0.0f));
  constants.flags = (marched ? shader::kSkyLightCloudsMarched : 0u) |
                    (inputs.groundAlbedo ? shader::kSkyLightGround : 0u) |
                    (groundShadow ? shader::kSkyLightGroundShadow : 0u) |
                    (shadowMapMade ? shader::kSkyLightSunAtCamera : 0u);
  constants.shadowCascades = settings.shadowCascades;
  constants.shadowTexels = settings.shadowMapResolution;
  const VkImageView placeholder = images_.depthPlaceholder.view();
  detail::SetWriter(device_, slot.skyLight)
      .uniformBuffer(shader::kBindingUniforms, slot.uniforms.buffer(), kUniformBytes)
      .sampledImage(shader::kSkyLightHostSky, inputs.skyView, linearSampler_.get(),
                    inputs.skyLayout)
      .storageImage(shader::kSkyLightClouds, images_.skyLightClouds.view())
      .sampledImage(
          shader::kSkyLightShadowMap, shadowMapMade ? images_.shadowMap.view() : placeholder,
          clampedLinearSampler_.get(),
          shadowMapMade ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .uniformBuffer(shader::kSkyLightShadowParameters, slot.shadowParameters.buffer(),
                     sizeof(shader::MarchShadowMap))
      .storageImage(shader::kSkyLightMap, images_.skyLightMap.view())
      .storageBuffer(shader::kSkyLightMeasures, slot.skyLightMeasures.buffer(),
                     slot.skyLightMeasures.size())
      .commit();
  const detail::ComputeProgram& program = programs_[Program::SkyLight];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                             &slot.skyLight, 0, nullptr);
  fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                        &constants);
  fn.vkCmdDispatch(cmd, 1, 1, 1);
  // The map for the host's shaders, the measures for the host once the frame completed.
  detail::barrier(device_, cmd, images_.skyLightMap.image(), VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_GENERAL, kCompute, kStorageWrite, kHostReadStages,
                  kHostReadAccess);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_READ_BIT);
  endPass(cmd, detail::Pass::SkyLight);
  slot.skyLightFrame = inputs.frameIndex;
}

void Context::Impl::recordTrace(VkCommandBuffer cmd, const FrameInputs& inputs,
                                const Settings& settings, const detail::TemporalFrame& temporal,
                                VkExtent2D traceExtent, std::uint32_t shadowMapReads,
                                std::uint32_t heroClouds, Slot& slot) {
  const TraceSamplers samplers{nearestSampler_.get(), linearSampler_.get(),
                               clampedLinearSampler_.get()};
  const bool heroes = heroClouds != shader::kHeroCloudsOff;
  HeroBindings heroBindings;
  if (heroes) {
    heroBindings = {
        heroAtlas_->image().view(), slot.heroClouds.buffer(),
        settings.heroLight == HeroLight::Volume ? heroLight_->image().view() : VK_NULL_HANDLE,
        heroNoiseView()};
  }
  const TraceFrame frame = traceFrame(images_, samplers, slot.uniforms.buffer(), inputs, settings,
                                      temporal, shadowMapReads, heroBindings);
  writeSceneDistanceSet(device_, slot.sceneDistance, frame);
  writeMarchSet(device_, slot.march, frame, weatherMap(), slot.counters, slot.shadowParameters,
                slot.edgeRayList);
  writeReconstructSet(device_, slot.reconstruct, frame, slot.lightning);
  writeUpsampleSet(device_, slot.upsample, frame);

  // Everything these passes write may still be read by earlier commands (last frame's
  // reconstruction and upsample, the host's reads of the outputs).
  detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, kCompute,
                        kStorageWrite);
  if (info_.workCounters) resetWorkCounters(device_, cmd, slot.counters);

  recordSceneDistance(cmd, traceExtent, slot);
  recordMarch(cmd, settings, temporal.tileSize, traceExtent, shadowMapReads, frame.edgeRays,
              heroClouds, slot);
  if (frame.nearField) {
    writeNearResolveSet(device_, slot.nearResolve, frame);
    recordNearField(cmd, settings, traceExtent, shadowMapReads, heroClouds, frame.nearHistoryUsable,
                    slot);
  }
  const bool lightning = recordLightning(cmd, inputs, slot);
  recordReconstruct(cmd, temporal, traceExtent, lightning, slot);
  const bool godRays =
      settings.godRaySamples > 0 &&
      recordGodRays(cmd, inputs, settings, frame.historyOut,
                    frame.nearField ? frame.nearResolved : VK_NULL_HANDLE, /*traced=*/true, slot);
  const std::uint32_t outputHistory = historyVariant(temporal.useOutputHistory, temporal.still);
  const VkPipeline upsample = programs_[Program::Upsample].find(
      detail::upsampleKey(temporal.upsampleTemporally, outputHistory, frame.hazed, godRays,
                          lightning, detail::writesCloudDepth(settings), frame.nearField));
  const bool bolts = !inputs.lightningBolts.empty() && slot.bolts.buffer() != VK_NULL_HANDLE;
  recordUpsample(cmd, upsample, inputs.renderExtent, bolts, slot);
  if (!bolts) return;
  writeBoltsSet(device_, slot.lightningBolts, frame, slot.bolts);
  recordBolts(cmd, inputs, frame.hazed, slot);
}

void Context::Impl::recordHeroLight(VkCommandBuffer cmd, std::uint32_t instances, Slot& slot) {
  heroLight_->recordFirstUse(cmd);
  if (instances == 0) return;
  beginPass(cmd, detail::Pass::HeroLight, "clouds: hero light volume");
  heroLight_->recordSweep(cmd, programs_[Program::HeroLight], slot.heroLight,
                          heroAtlas_->image().view(), heroNoiseView(), slot.heroClouds.buffer(),
                          instances, lastUniforms_.sunDirection);
  endPass(cmd, detail::Pass::HeroLight);
}

void Context::Impl::recordSceneDistance(VkCommandBuffer cmd, VkExtent2D traceExtent, Slot& slot) {
  beginPass(cmd, detail::Pass::SceneDistance, "clouds: scene distance");
  bindAndDispatch(cmd, Program::SceneDistance, programs_[Program::SceneDistance].find(),
                  slot.sceneDistance, traceExtent.width, traceExtent.height);
  // The barrier is part of the pass: on lavapipe a dispatch only starts the work, and the
  // barrier waits for it.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::SceneDistance);
}

void Context::Impl::recordMarch(VkCommandBuffer cmd, const Settings& settings,
                                std::uint32_t tileSize, VkExtent2D traceExtent,
                                std::uint32_t shadowMapReads, bool edgeRays,
                                std::uint32_t heroClouds, Slot& slot) {
  const std::uint32_t k = tileSize;
  if (edgeRays) recordEdgeRayListReset(cmd, slot);
  beginPass(cmd, detail::Pass::March, "clouds: march");
  // One invocation per tile: only the pixels marched this frame.
  const detail::ComputeProgram& march = programs_[Program::March];
  bindAndDispatch(cmd, Program::March,
                  march.find(detail::marchKey(settings, info_.workCounters, shadowMapReads,
                                              shader::kEdgeRaysFind, heroClouds)),
                  slot.march, (traceExtent.width + k - 1) / k, (traceExtent.height + k - 1) / k);
  if (edgeRays) {
    dispatchListedEdgeTiles(
        device_, cmd,
        march.find(detail::marchKey(settings, info_.workCounters, shadowMapReads,
                                    shader::kEdgeRaysMarch, heroClouds)),
        slot.edgeRayList);
  }
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::March);
  if (info_.workCounters) makeWorkCountersReadable(device_, cmd);
}

void Context::Impl::recordNearField(VkCommandBuffer cmd, const Settings& settings,
                                    VkExtent2D traceExtent, std::uint32_t shadowMapReads,
                                    std::uint32_t heroClouds, bool history, Slot& slot) {
  beginPass(cmd, detail::Pass::NearField, "clouds: near field");
  // One invocation per near-field pixel, every frame; then their resolve with the history.
  const VkPipeline nearField = programs_[Program::March].find(detail::marchKey(
      settings, info_.workCounters, shadowMapReads, shader::kEdgeRaysFind, heroClouds, true));
  const VkExtent2D extent = detail::nearFieldExtentFor(traceExtent);
  bindAndDispatch(cmd, Program::March, nearField, slot.march, extent.width, extent.height);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  bindAndDispatch(cmd, Program::NearResolve,
                  programs_[Program::NearResolve].find(detail::nearResolveKey(history)),
                  slot.nearResolve, extent.width, extent.height);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::NearField);
  if (info_.workCounters) makeWorkCountersReadable(device_, cmd);
}

void Context::Impl::recordReconstruct(VkCommandBuffer cmd, const detail::TemporalFrame& temporal,
                                      VkExtent2D traceExtent, bool lightning, Slot& slot) {
  beginPass(cmd, detail::Pass::Reconstruct, "clouds: reconstruct");
  const std::uint32_t history = historyVariant(temporal.useHistory, temporal.still);
  bindAndDispatch(cmd, Program::Reconstruct,
                  programs_[Program::Reconstruct].find(detail::reconstructKey(history, lightning)),
                  slot.reconstruct, traceExtent.width, traceExtent.height);
  // The upsample samples the glow.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute,
                        kStorageRead | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  endPass(cmd, detail::Pass::Reconstruct);
}

void Context::Impl::recordUpsample(VkCommandBuffer cmd, VkPipeline pipeline,
                                   VkExtent2D renderExtent, bool toBolts, Slot& slot) {
  beginPass(cmd, detail::Pass::Upsample, "clouds: upsample");
  bindAndDispatch(cmd, Program::Upsample, pipeline, slot.upsample, renderExtent.width,
                  renderExtent.height);
  makeOutputsVisible(device_, cmd, images_, toBolts);
  endPass(cmd, detail::Pass::Upsample);
}

void Context::Impl::recordEdgeRayListReset(VkCommandBuffer cmd, Slot& slot) {
  // An empty list: no groups (x 0, y 1, z 1) and no tiles, once earlier commands in this queue
  // (a frame of this slot recorded in the same submission) are done with it.
  const std::uint32_t empty[4] = {0u, 1u, 1u, 0u};
  static_assert(sizeof(empty) == shader::kEdgeRayListHeaderBytes);
  detail::memoryBarrier(device_, cmd, kCompute | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        kStorageRead | kStorageWrite | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.edgeRayList.buffer(), 0, sizeof(empty), empty);
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, kStorageRead | kStorageWrite);
}

void Context::Impl::recordClearSky(VkCommandBuffer cmd, Slot& slot) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::ClearSky, "clouds: clear sky");
  const VkPipelineStageFlags2 transfer = VK_PIPELINE_STAGE_2_CLEAR_BIT;
  // Still the empty sky of an earlier clear frame, visible to the host's reads since that
  // frame's barrier: nothing to clear (at 640x360 on lavapipe, the clears and their barriers
  // cost about a tenth of Low's overcast frame).
  const bool clear = !outputsHoldClearSky_;
  // The outputs (and the counters) may still be read by earlier commands.
  if (clear || info_.workCounters) {
    detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, transfer,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  }
  if (clear) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkClearColorValue noCloud{};
    noCloud.float32[3] = 1.0f;  // transmittance 1, no radiance
    fn.vkCmdClearColorImage(cmd, images_.radiance.image(), VK_IMAGE_LAYOUT_GENERAL, &noCloud, 1,
                            &range);
    if (images_.depth) {
      const VkClearColorValue noDepth{};
      fn.vkCmdClearColorImage(cmd, images_.depth.image(), VK_IMAGE_LAYOUT_GENERAL, &noDepth, 1,
                              &range);
    }
    images_.forEachOutput([&](const detail::OwnedImage& image) {
      detail::barrier(device_, cmd, image.image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                      transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kHostReadStages, kHostReadAccess);
    });
  }
  if (info_.workCounters) {
    fn.vkCmdFillBuffer(cmd, slot.counters.buffer(), 0, VK_WHOLE_SIZE, 0u);
    detail::memoryBarrier(device_, cmd, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  }
  endPass(cmd, detail::Pass::ClearSky);
}

}  // namespace clouds
