#include "engine/render/tonemap_pass.h"

#include "engine/gfx/descriptors.h"
#include "render_shaders/fullscreen.vert.spv.h"
#include "render_shaders/tonemap.frag.spv.h"
#include "tonemap_operator.h"

namespace engine::render {

Tonemapper::Tonemapper(gfx::Device& device, VkFormat hdrFormat, VkFormat targetFormat)
    : targetFormat_(targetFormat),
      sampler_(device, gfx::SamplerDesc{VK_FILTER_NEAREST, VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "tonemap sampler"}) {
  gfx::GraphicsPipelineDesc desc;
  desc.vertexSpirv = fullscreen_vert_spv;
  desc.fragmentSpirv = tonemap_frag_spv;
  desc.bindings = {{shaders::kTonemapHdrBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    hdrFormat, VK_IMAGE_VIEW_TYPE_2D, VK_FILTER_NEAREST}};
  desc.pushConstantBytes = sizeof(shaders::TonemapConstants);
  desc.colorFormats = {targetFormat};
  desc.debugName = "tonemap";
  pipeline_ = gfx::Pipeline(device, desc);
}

TextureHandle addTonemapPass(FrameGraph& graph, const Tonemapper& tonemapper, TextureHandle hdr,
                             TextureHandle target, const TonemapSettings* settings,
                             TonemapOverlay overlay) {
  struct Data {
    TextureHandle hdr;
    TextureHandle target;
  };
  const char* name = overlay ? "tonemap + overlay" : "tonemap";
  const Data& data = graph.addPass<Data>(
      name, PassType::Graphics,
      [&](PassBuilder& builder, Data& d) {
        d.hdr = builder.read(hdr, Access::SampledRead);
        d.target = builder.colorAttachment(target, VK_ATTACHMENT_LOAD_OP_DONT_CARE);
      },
      [&tonemapper, settings, overlay = std::move(overlay)](const Data& d, PassContext& context) {
        gfx::DescriptorWriter writer;
        writer.combinedImageSampler(shaders::kTonemapHdrBinding, context.view(d.hdr),
                                    tonemapper.sampler());
        context.bind(tonemapper.pipeline(), writer);
        shaders::TonemapConstants constants{settings->exposure, settings->rawHdrView ? 1u : 0u,
                                            0.0f, 0.0f};
        gfx::pushConstants(context.cmd(), tonemapper.pipeline(), constants);
        vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        if (overlay) overlay(context);
      });
  return data.target;
}

}  // namespace engine::render
