#include "clouds/ecs/cloud_renderer.h"

#include "engine/core/error.h"
#include "engine/core/log.h"

namespace clouds::ecs {

using namespace engine::render;

CloudRenderer::CloudRenderer(engine::gfx::Device& device, VkExtent2D maxExtent,
                             VkFormat depthFormat, std::uint32_t noiseSeed,
                             std::uint32_t framesInFlight)
    : device_(device) {
  clouds::CreateInfo info;
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.depthFormat = depthFormat;
  info.compositeColorFormat = kCompositeFormat;
  info.maxRenderExtent = maxExtent;
  info.maxFramesInFlight = framesInFlight;
  info.reversedZ = true;
  info.noiseSeed = noiseSeed;
  info.passTimings = true;  // a few timestamps: where the clouds' time goes, for HUD and logs
  std::string error;
  context_ = clouds::Context::create(info, &error);
  if (!context_) throw engine::Error("clouds module: " + error);
}

CloudRenderer::~CloudRenderer() {
  // The module's objects may still be used by frames in flight.
  device_.waitIdle();
}

void CloudRenderer::dispatch(VkCommandBuffer cmd, VkExtent2D extent, VkImageView depth,
                             std::uint64_t frameIndex) {
  clouds::FrameInputs inputs = inputs_;
  inputs.commandBuffer = cmd;
  inputs.renderExtent = extent;
  inputs.depthView = depth;
  inputs.depthLayout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
  inputs.frameIndex = frameIndex;
  if (context_->dispatch(inputs, settings_, &lastError_)) {
    lastError_.clear();
    return;
  }
  // Settings are validated when a scene loads; reaching this is a bug worth seeing once.
  if (!errorReported_) engine::log::error("clouds dispatch: " + lastError_);
  errorReported_ = true;
}

void CloudRenderer::composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent) {
  if (!lastError_.empty()) return;
  std::string error;
  if (!context_->composite(cmd, color, extent, &error)) {
    engine::log::error("clouds composite: " + error);
  }
}

CloudPassOutputs addCloudPasses(FrameGraph& graph, CloudRenderer& renderer, TextureHandle sceneDepth,
                                TextureHandle hdr) {
  const clouds::Outputs out = renderer.context().outputs();
  const TextureDesc& hdrDesc = graph.textureDesc(hdr);
  // The module keeps its outputs in GENERAL between frames and synchronises its own writes;
  // the graph sees them as imported storage images.
  const ResourceState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  auto import = [&](const char* name, const clouds::OutputImage& image) {
    ImportedTexture texture;
    texture.image = image.image;
    texture.view = image.view;
    texture.desc.extent = hdrDesc.extent;
    texture.desc.format = image.format;
    texture.initial = general;
    texture.final = general;
    return graph.importTexture(name, texture);
  };
  const TextureHandle radiance = import("cloud radiance", out.radiance);
  const TextureHandle depth = import("cloud depth", out.depth);

  struct MarchData {
    TextureHandle sceneDepth, radiance, depth;
  };
  const MarchData& march = graph.addPass<MarchData>(
      "clouds", PassType::Compute,
      [&](PassBuilder& builder, MarchData& d) {
        if (sceneDepth.valid()) d.sceneDepth = builder.read(sceneDepth, Access::SampledRead);
        d.radiance = builder.write(radiance, Access::StorageWrite);
        d.depth = builder.write(depth, Access::StorageWrite);
      },
      [&renderer](const MarchData& d, PassContext& context) {
        const VkExtent3D extent = context.extent(d.radiance);
        const VkImageView sceneDepthView =
            d.sceneDepth.valid() ? context.view(d.sceneDepth) : VK_NULL_HANDLE;
        renderer.dispatch(context.cmd(), {extent.width, extent.height}, sceneDepthView,
                          context.frameIndex());
      });

  struct CompositeData {
    TextureHandle hdr, radiance;
  };
  const CompositeData& composite = graph.addPass<CompositeData>(
      "clouds composite", PassType::Compute,
      [&](PassBuilder& builder, CompositeData& d) {
        d.radiance = builder.read(march.radiance, Access::StorageRead);
        d.hdr = builder.write(hdr, Access::StorageWrite);
      },
      [&renderer](const CompositeData& d, PassContext& context) {
        const VkExtent3D extent = context.extent(d.hdr);
        renderer.composite(context.cmd(), context.view(d.hdr), {extent.width, extent.height});
      });
  return CloudPassOutputs{composite.hdr, march.radiance, march.depth};
}

}  // namespace clouds::ecs
