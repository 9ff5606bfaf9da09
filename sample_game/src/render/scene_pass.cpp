#include "render/scene_pass.h"

#include "engine/gfx/descriptors.h"

namespace sample {

using namespace engine;

SceneTargets addScenePass(render::FrameGraph& graph, const TerrainRenderer* terrain,
                          const render::SceneTextures& scene, render::TextureHandle sunlight,
                          std::span<render::RenderFeature* const> skyDrawers, VkFormat hdrFormat,
                          VkFormat depthFormat, const SceneFrameBinding* frame) {
  struct Data {
    SceneTargets targets;
    render::TextureHandle haze;
    render::TextureHandle sunlight;
  };
  const bool featureSky = !skyDrawers.empty();
  const Data& data = graph.addPass<Data>(
      featureSky ? "scene" : "terrain", render::PassType::Graphics,
      [&](render::PassBuilder& builder, Data& d) {
        render::TextureDesc desc;
        desc.extent = {scene.extent.width, scene.extent.height, 1};
        desc.format = hdrFormat;
        d.targets.hdr = scene.hdr.valid()
                            ? builder.colorAttachment(scene.hdr, VK_ATTACHMENT_LOAD_OP_LOAD)
                            : builder.colorAttachment(builder.createTexture("scene hdr", desc),
                                                      VK_ATTACHMENT_LOAD_OP_CLEAR);
        desc.format = depthFormat;
        d.targets.depth = builder.depthAttachment(builder.createTexture("scene depth", desc),
                                                  VK_ATTACHMENT_LOAD_OP_CLEAR);
        if (terrain != nullptr && terrain->hazedByAerialPerspective()) {
          d.haze = builder.read(scene.aerialPerspective, render::Access::SampledReadGeneral);
        }
        if (terrain != nullptr && terrain->shadowedByClouds()) {
          d.sunlight = builder.read(sunlight, render::Access::SampledReadGeneral);
        }
        // The sky reads what the feature recorded before the scene (ordered after it; the
        // feature synchronises its own images).
        if (featureSky && scene.skyRadiance.valid()) {
          builder.read(scene.skyRadiance, render::Access::SampledReadGeneral);
        }
      },
      [terrain, frame, skyDrawers](const Data& d, render::PassContext& context) {
        if (terrain != nullptr) {
          gfx::DescriptorWriter writer;
          writer.uniformBuffer(TerrainRenderer::kFrameBinding, frame->slice.buffer,
                               frame->slice.offset, frame->slice.size);
          if (d.haze.valid()) {
            writer.combinedImageSampler(TerrainRenderer::kHazeBinding, context.view(d.haze),
                                        terrain->linearSampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          if (d.sunlight.valid()) {
            writer.combinedImageSampler(TerrainRenderer::kSunlightBinding, context.view(d.sunlight),
                                        terrain->linearSampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          context.bind(terrain->pipeline(), writer);
          terrain->draw(context.cmd());
        }
        for (render::RenderFeature* feature : skyDrawers)
          feature->drawSkyInScenePass(context.cmd());
      });
  return data.targets;
}

}  // namespace sample
