// Recording a frame's lightning: its flashes' glow in the reconstructed clouds (after the
// temporal reconstruction, so no flash enters a history) and its bolts, projected onto the
// screen for the upsample to draw.
#include "context_impl.h"
#include "lightning_bolts.h"

namespace clouds {

using detail::Program;

namespace {

using detail::kStorageWrite;
constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
using detail::kHostReadAccess;
using detail::kHostReadStages;
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
constexpr VkAccessFlags2 kTransferWrite = VK_ACCESS_2_TRANSFER_WRITE_BIT;

}  // namespace

std::uint32_t Context::Impl::recordLightning(VkCommandBuffer cmd, const FrameInputs& inputs,
                                             const detail::OwnedImage& traceSamples,
                                             VkExtent2D traceExtent, Slot& slot) {
  const auto& fn = device_.fn();
  // Bolts come with flashes (validateSettings): no room for flashes, no lightning.
  const bool boltRoom = slot.bolts.buffer() != VK_NULL_HANDLE;
  if (slot.lightning.buffer() == VK_NULL_HANDLE ||
      (inputs.lightningFlashes.empty() && (inputs.lightningBolts.empty() || !boltRoom))) {
    return shader::kLightningNone;
  }
  // This frame's flashes, camera-relative.
  shader::LightningUniforms block{};
  block.count.x = static_cast<std::uint32_t>(inputs.lightningFlashes.size());
  for (std::size_t i = 0; i < inputs.lightningFlashes.size(); ++i) {
    const LightningFlash& flash = inputs.lightningFlashes[i];
    const glm::vec3 relative(flash.positionMetres - inputs.cameraPosition);
    block.flash[2 * i] = glm::vec4(relative, flash.radiusMetres);
    block.flash[2 * i + 1] = glm::vec4(flash.radiance, 0.0f);
  }
  const detail::ProjectedBolts bolts =
      boltRoom ? detail::projectBolts(inputs) : detail::ProjectedBolts{};

  beginPass(cmd, detail::Pass::Lightning, "clouds: lightning");
  // The slot's previous frame has completed (host contract); earlier commands may still read
  // the blocks and the glow.
  detail::memoryBarrier(
      device_, cmd, kHostReadStages | kCompute,
      VK_ACCESS_2_UNIFORM_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | kHostReadAccess,
      kTransfer | kCompute, kTransferWrite | kStorageWrite);
  fn.vkCmdUpdateBuffer(cmd, slot.lightning.buffer(), 0, sizeof(block), &block);
  if (boltRoom) {
    fn.vkCmdUpdateBuffer(cmd, slot.bolts.buffer(), 0, sizeof(bolts.header), &bolts.header);
    if (!bolts.segments.empty()) {
      fn.vkCmdUpdateBuffer(cmd, slot.bolts.buffer(), sizeof(bolts.header),
                           bolts.segments.size() * sizeof(glm::vec4), bolts.segments.data());
    }
  }
  detail::memoryBarrier(device_, cmd, kTransfer, kTransferWrite, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  detail::SetWriter(device_, slot.lightningGlow)
      .uniformBuffer(shader::kBindingUniforms, slot.uniforms.buffer(),
                     sizeof(shader::CloudUniforms))
      .storageImage(shader::kGlowTraceSamples, traceSamples.view())
      .uniformBuffer(shader::kGlowFlashes, slot.lightning.buffer(),
                     sizeof(shader::LightningUniforms))
      .storageImage(shader::kGlowOut, images_.lightningGlow.view())
      .commit();
  bindAndDispatch(cmd, Program::LightningGlow, programs_[Program::LightningGlow].find(),
                  slot.lightningGlow, traceExtent.width, traceExtent.height);
  detail::barrier(device_, cmd, images_.lightningGlow.image(), VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_GENERAL, kCompute, kStorageWrite, kCompute,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  endPass(cmd, detail::Pass::Lightning);
  return bolts.header.count.x > 0 ? shader::kLightningBolts : shader::kLightningGlow;
}

}  // namespace clouds
