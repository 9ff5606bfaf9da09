#include "render/sky_pass.h"

#include "bindings.h"
#include "engine/gfx/descriptors.h"
#include "sample_shaders/sky.comp.spv.h"

namespace sample {

using namespace engine;

SkyPass::SkyPass(gfx::Device& device, VkFormat hdrFormat) {
  gfx::ComputePipelineDesc desc;
  desc.spirv = sky_comp_spv;
  desc.bindings = {{shaders::kSkyFrameBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                   {shaders::kSkyColorBinding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, hdrFormat}};
  desc.debugName = "sky";
  pipeline_ = gfx::Pipeline(device, desc);
}

render::TextureHandle addSkyPass(render::FrameGraph& graph, const SkyPass& sky,
                                 const render::TextureDesc& hdrDesc,
                                 const SceneFrameBinding* frame) {
  struct Data {
    render::TextureHandle hdr;
  };
  const Data& data = graph.addPass<Data>(
      "sky", render::PassType::Compute,
      [&](render::PassBuilder& builder, Data& d) {
        d.hdr = builder.write(builder.createTexture("scene hdr", hdrDesc),
                              render::Access::StorageWrite);
      },
      [&sky, frame](const Data& d, render::PassContext& context) {
        gfx::DescriptorWriter writer;
        writer.uniformBuffer(shaders::kSkyFrameBinding, frame->slice.buffer, frame->slice.offset,
                             frame->slice.size);
        writer.storageImage(shaders::kSkyColorBinding, context.view(d.hdr));
        context.bind(sky.pipeline(), writer);
        const VkExtent3D extent = context.extent(d.hdr);
        vkCmdDispatch(context.cmd(), gfx::groupCount(extent.width, 8),
                      gfx::groupCount(extent.height, 8), 1);
      });
  return data.hdr;
}

}  // namespace sample
