// Recording a frame's lightning: its flashes, which the reconstruction makes the clouds' glow
// with (kept out of the history, so no flash enters one), and its bolts, projected onto the
// screen and drawn into the radiance output after the upsample (after the histories too).
#include "context_impl.h"
#include "lightning_bolts.h"
#include "pipeline_variants.h"

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

bool Context::Impl::recordLightning(VkCommandBuffer cmd, const FrameInputs& inputs, Slot& slot) {
  if (inputs.lightningFlashes.empty() || slot.lightning.buffer() == VK_NULL_HANDLE) return false;
  shader::LightningUniforms block{};
  block.count.x = static_cast<std::uint32_t>(inputs.lightningFlashes.size());
  for (std::size_t i = 0; i < inputs.lightningFlashes.size(); ++i) {
    const LightningFlash& flash = inputs.lightningFlashes[i];
    const glm::vec3 relative(flash.positionMetres - inputs.cameraPosition);
    block.flash[2 * i] = glm::vec4(relative, flash.radiusMetres);
    block.flash[2 * i + 1] = glm::vec4(flash.radiance, 0.0f);
  }
  beginPass(cmd, detail::Pass::Lightning, "clouds: lightning");
  // The slot's previous frame has completed (host contract); earlier commands may still read
  // the block.
  detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT, kTransfer,
                        kTransferWrite);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.lightning.buffer(), 0, sizeof(block), &block);
  detail::memoryBarrier(device_, cmd, kTransfer, kTransferWrite, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT);
  endPass(cmd, detail::Pass::Lightning);
  return true;
}

void Context::Impl::recordBolts(VkCommandBuffer cmd, const FrameInputs& inputs, bool hazed,
                                Slot& slot) {
  const auto& fn = device_.fn();
  const detail::ProjectedBolts bolts = detail::projectBolts(inputs);
  beginPass(cmd, detail::Pass::LightningBolts, "clouds: lightning bolts");
  if (bolts.header.count.x > 0) {
    // The slot's previous frame has completed (host contract); earlier commands may still read
    // the buffer.
    detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, kTransfer,
                          kTransferWrite);
    fn.vkCmdUpdateBuffer(cmd, slot.bolts.buffer(), 0, sizeof(bolts.header), &bolts.header);
    // Within vkCmdUpdateBuffer's 64 KiB: kBoltMaxTiles and kBoltMaxTileIndices bound it.
    const std::vector<std::uint32_t> words = bolts.words();
    fn.vkCmdUpdateBuffer(cmd, slot.bolts.buffer(), sizeof(bolts.header),
                         words.size() * sizeof(std::uint32_t), words.data());
    detail::memoryBarrier(device_, cmd, kTransfer, kTransferWrite, kCompute,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    // Only the blocks of the tiles that hold pieces are dispatched, or, when they are too many
    // to list, the bolts' bounds on screen.
    const glm::vec4 bounds = bolts.header.bounds;
    const glm::uvec2 extent(inputs.renderExtent.width, inputs.renderExtent.height);
    shader::LightningBoltsConstants constants{};
    constants.listedBlocks = bolts.blocks.empty() ? 0u : 1u;
    constants.origin =
        glm::uvec2(glm::clamp(glm::floor(glm::vec2(bounds)), glm::vec2(0.0f), glm::vec2(extent)));
    const glm::uvec2 end = glm::uvec2(
        glm::clamp(glm::ceil(glm::vec2(bounds.z, bounds.w)), glm::vec2(0.0f), glm::vec2(extent)));
    const glm::uvec2 size = glm::max(end, constants.origin) - constants.origin;
    const glm::uvec2 groups = bolts.blocks.empty()
                                  ? glm::uvec2(detail::groupsFor(size.x, shader::kWorkgroupSize2D),
                                               detail::groupsFor(size.y, shader::kWorkgroupSize2D))
                                  : glm::uvec2(std::uint32_t(bolts.blocks.size()), 1u);
    const detail::ComputeProgram& program = programs_[Program::LightningBolts];
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                         program.find(detail::boltsKey(hazed)));
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                               &slot.lightningBolts, 0, nullptr);
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
    fn.vkCmdDispatch(cmd, groups.x, groups.y, 1);
  }
  images_.forEachOutput([&](const detail::OwnedImage& image) {
    detail::barrier(device_, cmd, image.image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    kCompute, kStorageWrite, kHostReadStages, kHostReadAccess);
  });
  endPass(cmd, detail::Pass::LightningBolts);
}

}  // namespace clouds
