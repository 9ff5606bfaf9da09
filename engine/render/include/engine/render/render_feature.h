#pragma once
// Effects that modules add to a renderer they do not own. The renderer publishes a RenderDevice
// before GPU modules install; a module that installs registers its RenderFeature in
// RenderFeatures; the renderer then prepares each feature outside command recording and lets it
// add its passes in three phases, each in registration order: what the rest of the frame reads
// (e.g. shadow maps), what the opaque scene reads (e.g. a sky and its light), and what goes after
// the scene. Features hand each other per-frame values through the graph's blackboard, in entry
// types the engine does not know. A scene without the module has no feature and runs none of its
// code.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <typeindex>
#include <typeinfo>
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

// For a GPU module's supported(): whether `device` (the world's RenderDevice, null when no
// renderer published one) can be used; if not, says why in `reason`.
bool usableRenderDevice(const RenderDevice* device, std::string& reason);

// Fills the device fields every drop-in module's CreateInfo has: the handles, the loader's
// proc-addr functions, and whether VK_EXT_debug_utils is enabled.
template <typename ModuleCreateInfo>
void describeDevice(const gfx::Device& device, ModuleCreateInfo& info) {
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.debugUtils = device.instance().debugUtilsEnabled();
}

// What the passes so far made of the scene, at the output extent `extent`: its colour and
// depth (`depth` invalid when the scene has no geometry). Everything else effects hand each
// other (a sky's light, a volume of scattered light, a shadow map and its parameters) travels
// as entries of the graph's blackboard (blackboard.h), typed by the contract between them.
struct SceneTextures {
  TextureHandle hdr;
  TextureHandle depth;
  VkExtent2D extent{0, 0};
};

class RenderFeature {
 public:
  virtual ~RenderFeature();
  virtual const char* name() const = 0;
  // The optional effects the feature runs in this scene, as it names them (e.g. "shadow map"):
  // what a renderer lists after the feature's pipelines. Default: none.
  virtual std::vector<std::string> effects() const { return {}; }
  // The GPU memory the feature's module holds now (bytes), for the run's report.
  virtual std::uint64_t gpuMemoryBytes() const { return 0; }
  // Whether the feature publishes a blackboard entry of type `Entry` in the frames it adds
  // passes to (publishes<Entry>()), and whether it reads one when there is one (reads<Entry>()).
  // Asked before any graph is built, so that a renderer can make the pipelines that read an
  // entry, and tell its publisher that someone will.
  template <typename Entry>
  bool publishes() const {
    return publishesEntry(typeid(Entry));
  }
  template <typename Entry>
  bool reads() const {
    return readsEntry(typeid(Entry));
  }
  // Whether the feature draws the sky (drawSkyInScenePass()): then the renderer draws none of
  // its own and has a scene pass even without geometry.
  virtual bool drawsSky() const { return false; }
  // Inside the renderer's scene pass (dynamic rendering: RenderDevice's hdr colour and depth,
  // the frame's extent), after its opaque geometry: draws the sky where the depth is still the
  // far plane. Only for features that draw the sky.
  virtual void drawSkyInScenePass(VkCommandBuffer cmd);
  // Outside command recording, before the frame `frameIndex` is recorded (every frame before
  // frameIndex - framesInFlight has completed): create pipelines and grow resources for an
  // output of `extent`. Returns true when the textures addPasses() imported changed, so the
  // graph must be rebuilt.
  virtual bool prepare(VkExtent2D extent, std::uint64_t frameIndex) = 0;
  // Adds the passes whose results the rest of the frame reads (e.g. shadow maps), before any
  // feature's addPassesBeforeScene() and the scene. Default: none.
  virtual SceneTextures addShadowPasses(FrameGraph& graph, const SceneTextures& scene);
  // Adds the passes the renderer's opaque scene depends on, before it: `scene` has only the
  // extent and what earlier features provided; what the feature makes for the scene (a sky's
  // light) goes on the graph's blackboard. Default: none.
  virtual SceneTextures addPassesBeforeScene(FrameGraph& graph, const SceneTextures& scene);
  // Adds the feature's passes after the opaque scene; returns the scene textures later passes
  // use (the colour with the effect applied).
  virtual SceneTextures addPasses(FrameGraph& graph, const SceneTextures& scene) = 0;
  // After the renderer drained the device at the end of a run, `lastFrameIndex` the last frame
  // recorded: read back what only a completed frame has.
  virtual void finish(std::uint64_t lastFrameIndex);

 protected:
  // publishes<Entry>() and reads<Entry>(), by type. Default: nothing.
  virtual bool publishesEntry(std::type_index /*entry*/) const { return false; }
  virtual bool readsEntry(std::type_index /*entry*/) const { return false; }
};

// Context singleton: the features installed modules registered, in the order their passes run.
struct RenderFeatures {
  std::vector<RenderFeature*> features;
};

}  // namespace engine::render
