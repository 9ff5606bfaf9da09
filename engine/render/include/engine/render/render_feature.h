#pragma once
// Effects that modules add to a renderer they do not own (the atmosphere, the clouds; later god
// rays...). The renderer publishes a RenderDevice before GPU modules install; a module that
// installs registers its RenderFeature in RenderFeatures; the renderer then prepares each
// feature outside command recording and lets it add its passes in three phases, each in
// registration order: what shadows the rest of the frame (the clouds' shadow map), what the
// opaque scene reads (the sky, its light and haze), and what goes after the scene (the
// clouds). A scene without the module has no feature and runs none of its code.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
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

// Fills the device fields every drop-in module's CreateInfo has (clouds, atmosphere): the
// handles, the loader's proc-addr functions, and whether VK_EXT_debug_utils is enabled.
template <typename ModuleCreateInfo>
void describeDevice(const gfx::Device& device, ModuleCreateInfo& info) {
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.debugUtils = device.instance().debugUtilsEnabled();
}

// The lookup parameters of a cloud shadow map for this frame (vkfx/cloud_shadow.h's
// CloudShadowParameters: 13 vec4s, std140), as a receiver copies them into its uniforms.
using CloudShadowParameterBlock = std::array<glm::vec4, 13>;

// What the passes so far made of the scene, at the output extent `extent`: its colour and
// depth (`depth` invalid when the scene has no geometry). A feature that draws the sky also
// hands the renderer and later features its light: the sky's radiance around the camera and
// the aerial perspective (invalid when no feature provides them). A renderer given an aerial
// perspective hazes the geometry it draws with it (vkfx/aerial_perspective.glsl).
struct SceneTextures {
  TextureHandle hdr;
  TextureHandle depth;
  VkExtent2D extent{0, 0};
  // The sky's radiance (kcd/m^2), equirectangular: u the azimuth from +X towards +Z, v = 0 at
  // the zenith, 0.5 at the horizon. Kept in GENERAL (read it with Access::SampledReadGeneral).
  TextureHandle skyRadiance;
  // The haze between the camera and every distance, laid out as vkfx/aerial_perspective.glsl
  // says, its radiance per unit of Sun::illuminance. Kept in GENERAL.
  TextureHandle aerialPerspective;
  std::uint32_t aerialPerspectiveSlices = 0;
  float aerialPerspectiveRangeMetres = 0.0f;
  // What the haze is made of: the air's scattering at the ground (per metre) and its Mie
  // asymmetry, for effects that weigh its Mie share (god rays, vkfx/god_rays.h).
  glm::vec3 hazeRayleighPerMetre{0.0f};
  glm::vec3 hazeMiePerMetre{0.0f};
  float hazeMiePhaseG = 0.8f;
  // The clouds' shadow for receivers lit by the sun (vkfx/cloud_shadow.h), kept in GENERAL,
  // and its parameters, which the pass that writes the map fills when it executes: a pass that
  // reads the map (and so runs after it) reads them at its own execution. Invalid / null when
  // nothing casts cloud shadows.
  TextureHandle cloudShadow;
  const CloudShadowParameterBlock* cloudShadowParameters = nullptr;
  // Filled with the parameters: whether this frame's map was remade whole (no cascade carried
  // over from the frame before: a camera cut, new settings, a sun that turned), so a receiver
  // that keeps what it read from the map across frames must read it again.
  const bool* cloudShadowRemadeWhole = nullptr;
  // Set by the renderer before the shadow passes: whether anything in the frame receives cloud
  // shadows (its geometry, or a feature that does). Without a receiver, no map is made.
  bool cloudShadowReceived = false;
};

class RenderFeature {
 public:
  virtual ~RenderFeature();
  virtual const char* name() const = 0;
  // The optional effects the feature runs in this scene, as it names them (e.g. the clouds'
  // "shadow map", "god rays"): what --describe lists after its pipelines. Default: none.
  virtual std::vector<std::string> effects() const { return {}; }
  // The GPU memory the feature's module holds now (bytes), for the run's report.
  virtual std::uint64_t gpuMemoryBytes() const { return 0; }
  // Whether the feature casts cloud shadows (addShadowPasses() provides
  // SceneTextures::cloudShadow): receivers build their pipelines to read them.
  virtual bool castsCloudShadow() const { return false; }
  // Whether the feature reads SceneTextures::cloudShadow when it exists.
  virtual bool receivesCloudShadow() const { return false; }
  // Whether the feature draws the sky (drawSkyInScenePass()): then the renderer draws none of
  // its own, has a scene pass even without geometry, and hazes its geometry with the feature's
  // aerial perspective.
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
  // Adds the passes that shadow the rest of the frame, before any feature's
  // addPassesBeforeScene() (whose haze may read them) and the scene. Default: none.
  virtual SceneTextures addShadowPasses(FrameGraph& graph, const SceneTextures& scene);
  // Adds the passes the renderer's opaque scene depends on, before it: `scene` has only the
  // extent and what earlier features provided. A feature that draws the sky returns the sky's
  // light and haze (SceneTextures::skyRadiance, aerialPerspective). Default: none.
  virtual SceneTextures addPassesBeforeScene(FrameGraph& graph, const SceneTextures& scene);
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
