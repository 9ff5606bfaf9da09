#include "first_frame_passes.h"

#include "engine/gfx/descriptors.h"
#include "sample_shaders/sky_gradient.comp.spv.h"
#include "sample_shaders/test_pattern.frag.spv.h"
#include "sample_shaders/test_pattern.vert.spv.h"

namespace sample {

using namespace engine;

FirstFramePipelines::FirstFramePipelines(gfx::Device& device, VkFormat hdrFormat,
                                         VkFormat depthFormat) {
  gfx::ComputePipelineDesc sky;
  sky.spirv = sky_gradient_comp_spv;
  sky.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, hdrFormat}};
  sky.pushConstantBytes = sizeof(shaders::SkyGradientConstants);
  sky.debugName = "sky gradient";
  sky_ = gfx::Pipeline(device, sky);

  gfx::GraphicsPipelineDesc pattern;
  pattern.vertexSpirv = test_pattern_vert_spv;
  pattern.fragmentSpirv = test_pattern_frag_spv;
  pattern.pushConstantBytes = sizeof(shaders::TestPatternConstants);
  pattern.colorFormats = {hdrFormat};
  pattern.depthFormat = depthFormat;
  pattern.depthTest = true;
  pattern.depthWrite = true;
  pattern.debugName = "test pattern";
  pattern_ = gfx::Pipeline(device, pattern);
}

render::TextureHandle addSkyGradientPass(render::FrameGraph& graph,
                                         const FirstFramePipelines& pipelines,
                                         const render::TextureDesc& hdrDesc,
                                         const FirstFrameParams* params) {
  struct Data {
    render::TextureHandle hdr;
  };
  const Data& data = graph.addPass<Data>(
      "sky", render::PassType::Compute,
      [&](render::PassBuilder& builder, Data& d) {
        d.hdr = builder.write(builder.createTexture("scene hdr", hdrDesc),
                              render::Access::StorageWrite);
      },
      [&pipelines, params](const Data& d, render::PassContext& context) {
        gfx::DescriptorWriter writer;
        writer.storageImage(0, context.view(d.hdr));
        context.bind(pipelines.sky(), writer);
        gfx::pushConstants(context.cmd(), pipelines.sky(), params->sky);
        const VkExtent3D extent = context.extent(d.hdr);
        vkCmdDispatch(context.cmd(), gfx::groupCount(extent.width, 8),
                      gfx::groupCount(extent.height, 8), 1);
      });
  return data.hdr;
}

SceneTargets addTestPatternPass(render::FrameGraph& graph, const FirstFramePipelines& pipelines,
                                render::TextureHandle hdr, VkFormat depthFormat,
                                const FirstFrameParams* params) {
  struct Data {
    SceneTargets targets;
  };
  const Data& data = graph.addPass<Data>(
      "test pattern", render::PassType::Graphics,
      [&](render::PassBuilder& builder, Data& d) {
        render::TextureDesc depthDesc = graph.textureDesc(hdr);
        depthDesc.format = depthFormat;
        d.targets.depth = builder.createTexture("scene depth", depthDesc);
        d.targets.depth = builder.depthAttachment(d.targets.depth, VK_ATTACHMENT_LOAD_OP_CLEAR);
        d.targets.hdr = builder.colorAttachment(hdr, VK_ATTACHMENT_LOAD_OP_LOAD);
      },
      [&pipelines, params](const Data&, render::PassContext& context) {
        context.bind(pipelines.pattern(), gfx::DescriptorWriter{});
        gfx::pushConstants(context.cmd(), pipelines.pattern(), params->pattern);
        vkCmdDraw(context.cmd(), 18, 1, 0, 0);
      });
  return data.targets;
}

}  // namespace sample
