#include "engine/render/render_feature.h"

namespace engine::render {

RenderFeature::~RenderFeature() = default;

SceneTextures RenderFeature::addPassesBeforeScene(FrameGraph& /*graph*/,
                                                  const SceneTextures& scene) {
  return scene;
}

void RenderFeature::drawSkyInScenePass(VkCommandBuffer /*cmd*/) {}

void RenderFeature::finish(std::uint64_t /*lastFrameIndex*/) {}

}  // namespace engine::render
