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

// The history variant of a frame: none, read in place (nothing moved) or reprojected.
std::uint32_t historyVariant(bool use, bool still) {
  if (!use) return shader::kHistoryNone;
  return still ? shader::kHistoryInPlace : shader::kHistoryReprojected;
}

}  // namespace

void Context::Impl::recordUniforms(VkCommandBuffer cmd, Slot& slot,
                                   const shader::CloudUniforms& uniforms,
                                   const shader::MarchTerrainShadow* shadow) {
  // The previous frame of this slot has completed (host contract), but earlier commands in
  // this queue may still read it: order the update after them.
  detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT | kStorageRead,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.uniforms.buffer(), 0, sizeof(uniforms), &uniforms);
  // Only the march's terrain variant reads it.
  if (shadow != nullptr) {
    device_.fn().vkCmdUpdateBuffer(cmd, slot.shadowParameters.buffer(), 0, sizeof(*shadow), shadow);
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
  shader::AmbientConstants constants{};
  constants.groundAlbedo = inputs.groundAlbedo.value_or(glm::vec3(0.0f));
  constants.flags = (hasSky ? shader::kAmbientFromSkyImage : 0u) |
                    (inputs.groundAlbedo ? shader::kAmbientGroundLight : 0u) |
                    (groundShadow ? shader::kAmbientGroundShadow : 0u);
  constants.shadowCascades = settings.shadowCascades;
  constants.shadowTexels = settings.shadowMapResolution;
  // Without a sky image or a shadow map, a placeholder fills the binding the shader skips.
  const VkImageView placeholder = images_.depthPlaceholder.view();
  constexpr VkImageLayout kPlaceholderLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  beginPass(cmd, detail::Pass::SkyAmbient, "clouds: sky ambient");
  detail::SetWriter(device_, slot.skyAmbient)
      .storageBuffer(shader::kSkyAmbientUniforms, slot.uniforms.buffer(),
                     sizeof(shader::CloudUniforms))
      .sampledImage(shader::kSkyAmbientSky, hasSky ? inputs.skyView : placeholder,
                    linearSampler_.get(), hasSky ? inputs.skyLayout : kPlaceholderLayout)
      .sampledImage(
          shader::kSkyAmbientShadowMap, groundShadow ? images_.shadowMap.view() : placeholder,
          clampedLinearSampler_.get(), groundShadow ? VK_IMAGE_LAYOUT_GENERAL : kPlaceholderLayout)
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

void Context::Impl::recordTrace(VkCommandBuffer cmd, const FrameInputs& inputs,
                                const Settings& settings, const detail::TemporalFrame& temporal,
                                VkExtent2D traceExtent, bool terrainShadow, Slot& slot) {
  const auto& fn = device_.fn();
  const detail::ModuleImages& im = images_;
  const bool hasDepth = inputs.depthView != VK_NULL_HANDLE;
  const VkImageView depthView = hasDepth ? inputs.depthView : im.depthPlaceholder.view();
  const VkImageLayout depthLayout =
      hasDepth ? inputs.depthLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkSampler nearest = nearestSampler_.get();
  const FrameInputs::AerialPerspective& haze = inputs.aerialPerspective;
  const bool hazed = haze.view != VK_NULL_HANDLE;
  const VkBuffer uniforms = slot.uniforms.buffer();
  const VkDeviceSize uniformBytes = sizeof(shader::CloudUniforms);
  const detail::OwnedImage& historyIn = im.history[temporal.readHistory];
  const detail::OwnedImage& historyOut = im.history[temporal.writeHistory];
  // Without temporal upsampling the upsample pass never touches its output history: any
  // storage image of the format fills the bindings.
  const bool upsampling = temporal.upsampleTemporally;
  const VkImageView outputHistoryIn =
      upsampling ? im.outputHistory[temporal.readHistory].view() : im.samplesPlaceholder.view();
  const VkImageView outputHistoryOut =
      upsampling ? im.outputHistory[temporal.writeHistory].view() : im.samplesPlaceholder.view();
  const bool edgeRays = detail::marchesEdgeRays(settings, temporal);

  using namespace shader;
  detail::SetWriter(device_, slot.sceneDistance)
      .uniformBuffer(kBindingUniforms, uniforms, uniformBytes)
      .sampledImage(kSceneDistanceHostDepth, depthView, nearest, depthLayout)
      .storageImage(kSceneDistanceOut, im.sceneDistance.view())
      .commit();
  detail::SetWriter(device_, slot.march)
      .uniformBuffer(kBindingUniforms, uniforms, uniformBytes)
      .storageImage(kMarchShapeNoise, im.shapeNoise.view())
      .storageImage(kMarchDetailNoise, im.detailNoise.view())
      .storageImage(kMarchWeatherMap, weatherMap().view())
      .storageImage(kMarchCurlNoise, im.curlNoise.view())
      .storageImage(kMarchSceneDistance, im.sceneDistance.view())
      .storageImage(kMarchSamplesOut, im.traceSamples.view())
      .storageImage(kMarchWeatherMaxFine, im.weatherMaxFine.view())
      .storageImage(kMarchWeatherMaxCoarse, im.weatherMaxCoarse.view())
      .storageBuffer(kMarchCounters, slot.counters.buffer(), slot.counters.size())
      .sampledImage(
          kMarchCloudShadow, terrainShadow ? im.shadowMap.view() : im.depthPlaceholder.view(),
          clampedLinearSampler_.get(),
          terrainShadow ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .uniformBuffer(kMarchCloudShadowParameters, slot.shadowParameters.buffer(),
                     sizeof(MarchTerrainShadow))
      // Read only by frames that march edge rays (kFlagEdgeRays), which have a history; the
      // variants without edge rays never touch the list, for which the counters stand in.
      .storageImage(kMarchTraceHistory, historyIn.view())
      .storageBuffer(kMarchEdgeRayList,
                     edgeRays ? slot.edgeRayList.buffer() : slot.counters.buffer(),
                     edgeRays ? slot.edgeRayList.size() : slot.counters.size())
      .commit();
  // Without room for flashes, stand-ins: the frame's uniforms for their block and the
  // radiance output (of the glow's format) for the glow; the variant never touches them.
  const bool glowRoom = slot.lightning.buffer() != VK_NULL_HANDLE;
  detail::SetWriter(device_, slot.reconstruct)
      .uniformBuffer(kBindingUniforms, uniforms, uniformBytes)
      .storageImage(kReconstructFresh, im.traceSamples.view())
      .storageImage(kReconstructHistory, historyIn.view())
      .storageImage(kReconstructOut, historyOut.view())
      .uniformBuffer(kReconstructFlashes, glowRoom ? slot.lightning.buffer() : uniforms,
                     sizeof(LightningUniforms))
      .storageImage(kReconstructGlow, glowRoom ? im.lightningGlow.view() : im.radiance.view())
      .storageImage(kReconstructSceneDistance, im.sceneDistance.view())
      .commit();
  detail::SetWriter(device_, slot.upsample)
      .uniformBuffer(kBindingUniforms, uniforms, uniformBytes)
      .storageImage(kUpsampleTraceSamples, historyOut.view())
      .sampledImage(kUpsampleHostDepth, depthView, nearest, depthLayout)
      .storageImage(kUpsampleRadianceOut, im.radiance.view())
      // Without a depth output, a stand-in the variant never stores to.
      .storageImage(kUpsampleDepthOut, im.depth ? im.depth.view() : im.noDepthOutput.view())
      .storageImage(kUpsampleFresh, im.traceSamples.view())
      .storageImage(kUpsampleHistory, outputHistoryIn)
      .storageImage(kUpsampleHistoryOut, outputHistoryOut)
      .sampledImage(kUpsampleAerialPerspective, hazed ? haze.view : im.hazePlaceholder.view(),
                    linearSampler_.get(),
                    hazed ? haze.layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      // Without a glow, a stand-in: the variants without lightning never read it.
      .sampledImage(
          kUpsampleLightningGlow,
          im.lightningGlow ? im.lightningGlow.view() : im.depthPlaceholder.view(),
          linearSampler_.get(),
          im.lightningGlow ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .sampledImage(
          kUpsampleGodRayLight, im.godRayLight ? im.godRayLight.view() : im.depthPlaceholder.view(),
          clampedLinearSampler_.get(),
          im.godRayLight ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .commit();

  // Everything these passes write may still be read by earlier commands (last frame's
  // reconstruction and upsample, the host's reads of the outputs).
  detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, kCompute,
                        kStorageWrite);
  if (info_.workCounters) {
    fn.vkCmdFillBuffer(cmd, slot.counters.buffer(), 0, VK_WHOLE_SIZE, 0u);
    detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, kStorageRead | kStorageWrite);
  }

  beginPass(cmd, detail::Pass::SceneDistance, "clouds: scene distance");
  bindAndDispatch(cmd, Program::SceneDistance, programs_[Program::SceneDistance].find(),
                  slot.sceneDistance, traceExtent.width, traceExtent.height);
  // The barrier is part of the pass: on lavapipe a dispatch only starts the work, and the
  // barrier waits for it.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::SceneDistance);

  const std::uint32_t k = temporal.tileSize;
  if (edgeRays) recordEdgeRayListReset(cmd, slot);
  beginPass(cmd, detail::Pass::March, "clouds: march");
  // One invocation per tile: only the pixels marched this frame.
  const detail::ComputeProgram& march = programs_[Program::March];
  bindAndDispatch(cmd, Program::March,
                  march.find(detail::marchKey(settings, info_.workCounters, terrainShadow)),
                  slot.march, (traceExtent.width + k - 1) / k, (traceExtent.height + k - 1) / k);
  if (edgeRays) {
    // Then one per edge tile the march listed, as many groups as the list says.
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite,
                          kCompute | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                          kStorageRead | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                         march.find(detail::marchKey(settings, info_.workCounters, terrainShadow,
                                                     shader::kEdgeRaysMarch)));
    fn.vkCmdDispatchIndirect(cmd, slot.edgeRayList.buffer(), 0);
  }
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::March);

  if (info_.workCounters) {
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, VK_PIPELINE_STAGE_2_HOST_BIT,
                          VK_ACCESS_2_HOST_READ_BIT);
  }
  const bool lightning = recordLightning(cmd, inputs, slot);
  beginPass(cmd, detail::Pass::Reconstruct, "clouds: reconstruct");
  const std::uint32_t history = historyVariant(temporal.useHistory, temporal.still);
  bindAndDispatch(cmd, Program::Reconstruct,
                  programs_[Program::Reconstruct].find(detail::reconstructKey(history, lightning)),
                  slot.reconstruct, traceExtent.width, traceExtent.height);
  // The upsample samples the glow.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute,
                        kStorageRead | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  endPass(cmd, detail::Pass::Reconstruct);

  const bool godRays = settings.godRaySamples > 0 &&
                       recordGodRays(cmd, inputs, settings, historyOut, /*traced=*/true, slot);

  beginPass(cmd, detail::Pass::Upsample, "clouds: upsample");
  const std::uint32_t outputHistory = historyVariant(temporal.useOutputHistory, temporal.still);
  bindAndDispatch(cmd, Program::Upsample,
                  programs_[Program::Upsample].find(
                      detail::upsampleKey(upsampling, outputHistory, hazed, godRays, lightning,
                                          detail::writesCloudDepth(settings))),
                  slot.upsample, inputs.renderExtent.width, inputs.renderExtent.height);
  // The bolts' pass reads and writes the outputs next; else the host reads them.
  const bool bolts = !inputs.lightningBolts.empty() && slot.bolts.buffer() != VK_NULL_HANDLE;
  im.forEachOutput([&](const detail::OwnedImage& image) {
    detail::barrier(device_, cmd, image.image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    kCompute, kStorageWrite, bolts ? kCompute : kHostReadStages,
                    bolts ? kStorageRead | kStorageWrite : kHostReadAccess);
  });
  endPass(cmd, detail::Pass::Upsample);
  if (!bolts) return;
  detail::SetWriter(device_, slot.lightningBolts)
      .uniformBuffer(kBindingUniforms, uniforms, uniformBytes)
      .sampledImage(kBoltsHostDepth, depthView, nearest, depthLayout)
      .storageImage(kBoltsRadiance, im.radiance.view())
      .storageImage(kBoltsDepth, im.depth.view())
      .sampledImage(kBoltsAerialPerspective, hazed ? haze.view : im.hazePlaceholder.view(),
                    linearSampler_.get(),
                    hazed ? haze.layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .storageBuffer(kBoltsPieces, slot.bolts.buffer(), slot.bolts.size())
      .commit();
  recordBolts(cmd, inputs, hazed, slot);
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
