#include "engine/render/render_feature.h"

#include <string>

#include "engine/core/error.h"

namespace engine::render {

RenderFeature::~RenderFeature() = default;

SceneTextures RenderFeature::addShadowPasses(FrameGraph& /*graph*/, const SceneTextures& scene) {
  return scene;
}

SceneTextures RenderFeature::addPassesBeforeScene(FrameGraph& /*graph*/,
                                                  const SceneTextures& scene) {
  return scene;
}

bool usableRenderDevice(const RenderDevice* device, std::string& reason) {
  if (device != nullptr && device->device != nullptr) return true;
  reason = "no renderer published a RenderDevice";
  return false;
}

void Blackboard::missing(const char* typeName) {
  throw Error(std::string("frame graph blackboard: no entry of type ") + typeName);
}

void RenderFeature::drawSkyInScenePass(VkCommandBuffer /*cmd*/) {}

void RenderFeature::finish(std::uint64_t /*lastFrameIndex*/) {}

}  // namespace engine::render
