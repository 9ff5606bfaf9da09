#pragma once
// The sample's renderer. It looks at the world once to decide which passes the scene needs:
//   [features before the scene: atmosphere, atmosphere sky] or [sky] -> [terrain, water] ->
//   [features after the scene: clouds, clouds composite] -> tonemap -> [hud] -> capture
// (its own gradient sky only when no feature draws the sky; the terrain hazed by the sky
// feature's aerial perspective, else fogged; terrain only with a terrain; the
// features installed modules registered in engine::render::RenderFeatures, e.g. the clouds only
// with a cloud layer: their pipelines are not even created otherwise), prepares the features and
// rebuilds the frame graph when the output size or a feature's resources change, and each frame
// fills the per-frame constants from the world, records, submits and presents. Windowed and
// headless runs use it identically; only the PresentTarget differs.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/ecs/events.h"
#include "engine/ecs/world.h"
#include "engine/gfx/device.h"
#include "engine/gfx/frame_ring.h"
#include "engine/render/frame_capture.h"
#include "engine/render/frame_graph.h"
#include "engine/render/present_target.h"
#include "engine/render/render_feature.h"
#include "engine/render/tonemap_pass.h"
#include "game/game_components.h"
#include "render/sky_pass.h"
#include "render/terrain_heightfield.h"
#include "render/terrain_sunlight.h"

namespace sample {

class TerrainRenderer;
class WaterRenderer;
class Hud;

struct RendererOptions {
  VkExtent2D maxExtent{3840, 2160};                // largest output size the clouds allocate for
  std::filesystem::path captureDirectory = "out";  // where named (script) captures go
  bool hud = false;                                // on-screen help and frame rate (windowed runs)
  bool hudClears = true;  // the HUD's opaque backgrounds as clears (hud_draw_plan.h)
};

class Renderer {
 public:
  static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  Renderer(engine::gfx::Device& device, engine::render::PresentTarget& target,
           engine::ecs::World& world, const RendererOptions& options);
  ~Renderer();

  void renderFrame(engine::ecs::World& world);
  // Waits for every frame in flight, writes any pending capture and lets the features read
  // back the last frame's results.
  void finish();

  std::vector<std::string> passNames() const;
  std::vector<std::string> pipelineNames() const;
  // GPU memory in use (bytes): the renderer's own resources (the engine's allocator), then
  // each feature's module by name.
  std::vector<std::pair<std::string, std::uint64_t>> gpuMemory() const;
  // What casts long shadows this frame: "clouds" (a feature's shadow map), "terrain" (its
  // heightfield, handed to that map).
  std::vector<std::string> shadowCasters() const;
  std::span<const engine::gfx::TimedScope> lastGpuTimings() const { return ring_.lastTimings(); }
  const engine::render::FrameCapture& capture() const { return capture_; }
  Hud* hud() { return hud_.get(); }

 private:
  void rebuildGraph(VkExtent2D extent);
  void updateFrameConstants(engine::ecs::World& world, VkExtent2D extent);
  std::optional<std::filesystem::path> takeCaptureRequest(engine::ecs::World& world);
  // The latest completed frame's GPU time into the world (engine::render::GpuFrameTime).
  void publishGpuFrameTime(engine::ecs::World& world, std::uint64_t frameIndex) const;
  template <typename Predicate>
  bool anyFeature(Predicate predicate) const {
    return std::any_of(features_.begin(), features_.end(), predicate);
  }

  engine::gfx::Device& device_;
  engine::render::PresentTarget& target_;
  RendererOptions options_;
  engine::gfx::FrameRing ring_;
  engine::render::Tonemapper tonemapper_;
  std::unique_ptr<SkyPass> sky_;  // when no feature draws the sky
  std::unique_ptr<TerrainRenderer> terrain_;
  engine::shaders::TerrainMaterials terrainMaterials_{};  // SceneFrame::terrain
  std::unique_ptr<WaterRenderer> water_;                  // a scene with water only
  glm::vec4 waterBed_{0.0f};  // SceneFrame::waterBed: the terrain's extent (x, z), or none
  // Under shadow-casting clouds, the terrain's heightfield (published as
  // engine::render::TerrainHeightfield when the terrain casts shadows: then world_ is set) and
  // the sunlight map made over it.
  std::unique_ptr<TerrainHeightfieldImage> heightfield_;
  std::unique_ptr<TerrainSunlight> sunlight_;
  engine::ecs::World* world_ = nullptr;
  glm::dvec3 cameraPosition_{0.0};  // this frame's (world, m), for the sunlight pass
  std::vector<engine::render::RenderFeature*> features_;    // owned by their modules
  std::vector<engine::render::RenderFeature*> skyDrawers_;  // those of them that draw the sky
  std::unique_ptr<Hud> hud_;
  engine::render::FrameCapture capture_;
  std::unique_ptr<engine::render::FrameGraph> graph_;
  engine::render::TextureHandle targetHandle_;
  VkExtent2D graphExtent_{0, 0};
  SceneFrameBinding sceneFrame_{};
  // A hazed terrain's aerial perspective while the feature that makes it has none (its
  // prepare() failed): one texel, no in-scatter and full transmittance. Made when first needed.
  std::unique_ptr<engine::gfx::Image> noHaze_;
  engine::render::TextureHandle importNoHaze(engine::render::FrameGraph& graph);
  engine::render::TonemapSettings tonemap_{};
  engine::ecs::EventReader<CaptureFrame> captureReader_;
};

}  // namespace sample
