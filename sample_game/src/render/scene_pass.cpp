#include "render/scene_pass.h"

#include "engine/gfx/descriptors.h"
#include "fxcontracts/ecs/frame_entries.h"

namespace sample {

using namespace engine;

SceneTargets addScenePass(render::FrameGraph& graph, SceneSurfaces surfaces,
                          const render::SceneTextures& scene, render::TextureHandle sunlight,
                          std::span<render::RenderFeature* const> skyDrawers, VkFormat hdrFormat,
                          VkFormat depthFormat, const SceneFrameBinding* frame) {
  struct Data {
    SceneTargets targets;
    render::TextureHandle haze;
    render::TextureHandle sunlight;
    render::TextureHandle clearSky;    // the water's reflection: the atmosphere's sky map
    render::TextureHandle coveredSky;  // or the clouds' sky light, once it holds a sky
  };
  const TerrainRenderer* terrain = surfaces.terrain;
  const WaterRenderer* water = surfaces.water;
  const bool featureSky = !skyDrawers.empty();
  const auto* haze = graph.blackboard().find<fxcontracts::ecs::AerialPerspective>();
  const auto* sky = graph.blackboard().find<fxcontracts::ecs::SkyRadiance>();
  const auto* covered = graph.blackboard().find<fxcontracts::ecs::CoveredSkyRadiance>();
  const bool hazed = (terrain != nullptr && terrain->hazedByAerialPerspective()) ||
                     (water != nullptr && water->hazedByAerialPerspective());
  const bool shadowed = (terrain != nullptr && terrain->shadowedByClouds()) ||
                        (water != nullptr && water->shadowedByClouds());
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
        if (hazed && haze != nullptr) {
          d.haze = builder.read(haze->volume, render::Access::SampledReadGeneral);
        }
        if (shadowed) d.sunlight = builder.read(sunlight, render::Access::SampledReadGeneral);
        // The sky reads what the feature recorded before the scene (ordered after it; the
        // feature synchronises its own images).
        const bool reflects = water != nullptr && water->hazedByAerialPerspective();
        if (sky != nullptr && (featureSky || reflects)) {
          d.clearSky = builder.read(sky->texture, render::Access::SampledReadGeneral);
        }
        if (reflects && covered != nullptr) {
          d.coveredSky = builder.read(covered->texture, render::Access::SampledReadGeneral);
        }
      },
      [surfaces, frame, skyDrawers](const Data& d, render::PassContext& context) {
        gfx::ConstantRing::Slice constants = frame->slice;
        if (d.haze.valid()) {
          // The haze's reach as its pass (ordered before this one) wrote it this frame.
          const auto& air = context.blackboard().get<fxcontracts::ecs::AerialPerspective>();
          shaders::SceneFrame hazedFrame = frame->data;
          hazedFrame.fog.y = air.rangeMetres;
          hazedFrame.fog.z = float(air.slices);
          constants = context.constants().push(hazedFrame);
        }
        // The water's part beyond the bed's reach first (it hides the bed there, which then
        // costs no shading), the terrain, the water over the bed, and the sky where none is.
        // A hazed water reflects a sky map; in a frame with none (the atmosphere failed to
        // prepare) it is not drawn.
        const WaterRenderer* lake = surfaces.water;
        if (lake != nullptr && lake->hazedByAerialPerspective() && !d.clearSky.valid() &&
            !d.coveredSky.valid()) {
          lake = nullptr;
        }
        const auto bindWater = [&] {
          gfx::DescriptorWriter writer;
          writer.uniformBuffer(WaterRenderer::kFrameBinding, constants.buffer, constants.offset,
                               constants.size);
          if (lake->hazedByAerialPerspective()) {
            writer.combinedImageSampler(WaterRenderer::kHazeBinding, context.view(d.haze),
                                        lake->clampedSampler(), VK_IMAGE_LAYOUT_GENERAL);
            const bool reflectCovered =
                d.coveredSky.valid() && (frame->reflectsCoveredSky || !d.clearSky.valid());
            writer.combinedImageSampler(WaterRenderer::kSkyBinding,
                                        context.view(reflectCovered ? d.coveredSky : d.clearSky),
                                        lake->skySampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          if (lake->shadowedByClouds()) {
            writer.combinedImageSampler(WaterRenderer::kSunlightBinding, context.view(d.sunlight),
                                        lake->clampedSampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          context.bind(lake->pipeline(), writer);
        };
        if (lake != nullptr) {
          bindWater();
          lake->drawFar(context.cmd());
        }
        if (const TerrainRenderer* ground = surfaces.terrain) {
          gfx::DescriptorWriter writer;
          writer.uniformBuffer(TerrainRenderer::kFrameBinding, constants.buffer, constants.offset,
                               constants.size);
          if (ground->hazedByAerialPerspective()) {
            writer.combinedImageSampler(TerrainRenderer::kHazeBinding, context.view(d.haze),
                                        ground->linearSampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          if (ground->shadowedByClouds()) {
            writer.combinedImageSampler(TerrainRenderer::kSunlightBinding, context.view(d.sunlight),
                                        ground->linearSampler(), VK_IMAGE_LAYOUT_GENERAL);
          }
          writer.combinedImageSampler(TerrainRenderer::kBaseColourBinding,
                                      ground->baseColour().view(), ground->baseColour().sampler(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
          context.bind(ground->pipeline(), writer);
          ground->draw(context.cmd());
        }
        if (lake != nullptr) {
          if (surfaces.terrain != nullptr) bindWater();
          lake->drawNear(context.cmd());
        }
        for (render::RenderFeature* feature : skyDrawers)
          feature->drawSkyInScenePass(context.cmd());
      });
  return data.targets;
}

}  // namespace sample
