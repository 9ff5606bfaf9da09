#include <chrono>
#include <memory>
#include <vector>

#include "engine/gfx/barriers.h"
#include "engine/gfx/descriptors.h"
#include "engine/gfx/formats.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"

namespace engine::gfx {
namespace {

VkImageType imageTypeFor(VkImageViewType viewType) {
  switch (viewType) {
    case VK_IMAGE_VIEW_TYPE_1D:
    case VK_IMAGE_VIEW_TYPE_1D_ARRAY:
      return VK_IMAGE_TYPE_1D;
    case VK_IMAGE_VIEW_TYPE_3D:
      return VK_IMAGE_TYPE_3D;
    default:
      return VK_IMAGE_TYPE_2D;
  }
}

// Stand-in resources for one pipeline's bindings. They live until the warm-up submission has
// completed (released through the device's deferred queue afterwards).
struct StandIns {
  std::vector<Image> images;
  std::vector<Buffer> buffers;
  std::vector<Sampler> samplers;
  DescriptorWriter writer;
};

void makeStandIns(Device& device, VkCommandBuffer cmd, const Pipeline& pipeline,
                  StandIns& standIns) {
  for (const DescriptorBinding& b : pipeline.bindings()) {
    const bool isImage = b.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ||
                         b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
                         b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    VkSampler sampler = VK_NULL_HANDLE;
    if (b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ||
        b.type == VK_DESCRIPTOR_TYPE_SAMPLER) {
      SamplerDesc samplerDesc;
      samplerDesc.filter = b.filter;
      samplerDesc.addressMode = b.addressMode;
      samplerDesc.debugName = pipeline.name() + " warm-up sampler";
      standIns.samplers.emplace_back(device, samplerDesc);
      sampler = standIns.samplers.back().vk();
    }
    if (isImage) {
      const bool storage = b.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      ImageDesc desc;
      desc.type = imageTypeFor(b.viewType);
      desc.format = b.format != VK_FORMAT_UNDEFINED ? b.format : VK_FORMAT_R8G8B8A8_UNORM;
      desc.usage = storage ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_SAMPLED_BIT;
      desc.debugName = pipeline.name() + " warm-up image";
      standIns.images.emplace_back(device, desc);
      const Image& image = standIns.images.back();
      const ImageState target =
          storage ? kComputeGeneral
                  : ImageState{isDepthFormat(desc.format)
                                   ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                   : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               kShaderRead.stages, kShaderRead.access};
      imageBarrier(cmd, image.vk(), image.fullRange(), kUndefined, target);
      if (storage) {
        standIns.writer.storageImage(b.binding, image.view());
      } else if (b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE) {
        standIns.writer.sampledImage(b.binding, image.view(), target.layout);
      } else {
        standIns.writer.combinedImageSampler(b.binding, image.view(), sampler, target.layout);
      }
    } else if (b.type == VK_DESCRIPTOR_TYPE_SAMPLER) {
      standIns.writer.sampler(b.binding, sampler);
    } else {
      BufferDesc desc;
      desc.sizeBytes = 64 * 1024;
      desc.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
      desc.debugName = pipeline.name() + " warm-up buffer";
      standIns.buffers.emplace_back(device, desc);
      const VkBuffer buffer = standIns.buffers.back().vk();
      vkCmdFillBuffer(cmd, buffer, 0, VK_WHOLE_SIZE, 0);
      if (b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
        standIns.writer.uniformBuffer(b.binding, buffer);
      } else {
        standIns.writer.storageBuffer(b.binding, buffer);
      }
    }
  }
}

void recordGraphicsWarmUp(Device& device, VkCommandBuffer cmd, const Pipeline& pipeline,
                          StandIns& standIns) {
  std::vector<VkRenderingAttachmentInfo> colors;
  for (VkFormat format : pipeline.colorFormats()) {
    ImageDesc desc;
    desc.format = format;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    desc.debugName = pipeline.name() + " warm-up target";
    standIns.images.emplace_back(device, desc);
    const Image& image = standIns.images.back();
    imageBarrier(
        cmd, image.vk(), image.fullRange(), kUndefined,
        {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    VkRenderingAttachmentInfo attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    attachment.imageView = image.view();
    attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colors.push_back(attachment);
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (pipeline.depthFormat() != VK_FORMAT_UNDEFINED) {
    ImageDesc desc;
    desc.format = pipeline.depthFormat();
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    desc.debugName = pipeline.name() + " warm-up depth";
    standIns.images.emplace_back(device, desc);
    const Image& image = standIns.images.back();
    imageBarrier(
        cmd, image.vk(), image.fullRange(), kUndefined,
        {VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
    depth.imageView = image.view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  }
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {1, 1}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(colors.size());
  rendering.pColorAttachments = colors.data();
  if (pipeline.depthFormat() != VK_FORMAT_UNDEFINED) rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {1, 1}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  for (const auto& binding : pipeline.vertexBindings()) {
    BufferDesc desc;
    desc.sizeBytes = 4096;
    desc.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    desc.memory = MemoryUsage::Upload;
    desc.debugName = pipeline.name() + " warm-up vertices";
    standIns.buffers.emplace_back(device, desc);
    std::fill_n(standIns.buffers.back().mapped(), desc.sizeBytes, std::byte{0});
    const VkBuffer buffer = standIns.buffers.back().vk();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, binding.binding, 1, &buffer, &offset);
  }
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);
}

}  // namespace

double warmUpPipelines(Device& device, std::span<const Pipeline* const> pipelines) {
  const auto start = std::chrono::steady_clock::now();
  DescriptorArena arena(device, "pipeline warm-up descriptors");
  std::vector<std::unique_ptr<StandIns>> standIns;
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    for (const Pipeline* pipeline : pipelines) {
      if (pipeline == nullptr || !*pipeline) continue;
      auto& s = *standIns.emplace_back(std::make_unique<StandIns>());
      makeStandIns(device, cmd, *pipeline, s);
      // Stand-ins must be visible to the warm-up work (clears and layout changes above).
      VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
      barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
      barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
      barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
      barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
      VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dependency.memoryBarrierCount = 1;
      dependency.pMemoryBarriers = &barrier;
      vkCmdPipelineBarrier2(cmd, &dependency);

      if (pipeline->bindPoint() == VK_PIPELINE_BIND_POINT_COMPUTE) {
        bindPipeline(device, cmd, *pipeline, arena, s.writer);
        if (pipeline->pushConstantBytes() > 0) {
          std::vector<std::byte> zeros(pipeline->pushConstantBytes());
          vkCmdPushConstants(cmd, pipeline->layout(), pipeline->pushConstantStages(), 0,
                             pipeline->pushConstantBytes(), zeros.data());
        }
        vkCmdDispatch(cmd, 1, 1, 1);
      } else {
        bindPipeline(device, cmd, *pipeline, arena, s.writer);
        if (pipeline->pushConstantBytes() > 0) {
          std::vector<std::byte> zeros(pipeline->pushConstantBytes());
          vkCmdPushConstants(cmd, pipeline->layout(), pipeline->pushConstantStages(), 0,
                             pipeline->pushConstantBytes(), zeros.data());
        }
        recordGraphicsWarmUp(device, cmd, *pipeline, s);
      }
    }
  });
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace engine::gfx
