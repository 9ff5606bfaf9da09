#include "render/scene_pass.h"

#include "engine/gfx/descriptors.h"
#include "fxcontracts/ecs/frame_entries.h"

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
  const auto* haze = graph.blackboard().find<fxcontracts::ecs::AerialPerspective>();
  const auto* sky = graph.blackboard().find<fxcontracts::ecs::SkyRadiance>();
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
        if (terrain != nullptr && terrain->hazedByAerialPerspective() && haze != nullptr) {
          d.haze = builder.read(haze->volume, render::Access::SampledReadGeneral);
        }
        if (terrain != nullptr && terrain->shadowedByClouds()) {
          d.sunlight = builder.read(sunlight, render::Access::SampledReadGeneral);
        }
        // The sky reads what the feature recorded before the scene (ordered after it; the
        // feature synchronises its own images).
        if (featureSky && sky != nullptr) {
          builder.read(sky->texture, render::Access::SampledReadGeneral);
        }
      },
      [terrain, frame, skyDrawers](const Data& d, render::PassContext& context) {
        if (terrain != nullptr) {
          gfx::ConstantRing::Slice constants = frame->slice;
          if (d.haze.valid()) {
            // The haze's reach as its pass (ordered before this one) wrote it this frame.
            const auto& air = context.blackboard().get<fxcontracts::ecs::AerialPerspective>();
            shaders::SceneFrame hazed = frame->data;
            hazed.fog.y = air.rangeMetres;
            hazed.fog.z = float(air.slices);
            constants = context.constants().push(hazed);
          }
          gfx::DescriptorWriter writer;
          writer.uniformBuffer(TerrainRenderer::kFrameBinding, constants.buffer, constants.offset,
                               constants.size);
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
