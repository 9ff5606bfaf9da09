#pragma once
// Effects that modules add to a renderer they do not own (the clouds; later the atmosphere,
// god rays...). The renderer publishes a RenderDevice before GPU modules install; a module
// that installs registers its RenderFeature in RenderFeatures; the renderer then prepares each
// feature outside command recording and lets it add its passes after the opaque scene, in
// registration order. A scene without the module has no feature and runs none of its code.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "engine/gfx/device.h"
#include "engine/render/frame_graph.h"

namespace engine::render {

// Context singleton: what features create their GPU objects with.
struct RenderDevice {
  gfx::Device* device = nullptr;
  VkFormat hdrFormat = VK_FORMAT_UNDEFINED;    // the scene colour features read and write
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;  // the scene depth (reversed-Z)
  std::uint32_t framesInFlight = 0;
  VkExtent2D maxExtent{0, 0};  // the largest output the renderer will ask for
};

// The scene's colour and depth at the output extent; `depth` is invalid when the scene has no
// geometry.
struct SceneTextures {
  TextureHandle hdr;
  TextureHandle depth;
};

class RenderFeature {
 public:
  virtual ~RenderFeature();
  virtual const char* name() const = 0;
  // Outside command recording, before the frame `frameIndex` is recorded (every frame before
  // frameIndex - framesInFlight has completed): create pipelines and grow resources for an
  // output of `extent`. Returns true when the textures addPasses() imported changed, so the
  // graph must be rebuilt.
  virtual bool prepare(VkExtent2D extent, std::uint64_t frameIndex) = 0;
  // Adds the feature's passes after the opaque scene; returns the scene textures later passes
  // use (the colour with the effect applied).
  virtual SceneTextures addPasses(FrameGraph& graph, const SceneTextures& scene) = 0;
  // After the renderer drained the device at the end of a run, `lastFrameIndex` the last frame
  // recorded: read back what only a completed frame has.
  virtual void finish(std::uint64_t lastFrameIndex);
};

// Context singleton: the features installed modules registered, in the order their passes run.
struct RenderFeatures {
  std::vector<RenderFeature*> features;
};

}  // namespace engine::render
