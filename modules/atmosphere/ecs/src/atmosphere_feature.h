#pragma once
// The atmosphere module as a render feature of the engine: it owns an atmosphere::Context on
// the engine's device, prepares it outside the frame (and publishes what the last completed
// frame measured), and adds two passes before the renderer's opaque scene:
//   "atmosphere"      records Context::dispatch (LUTs, froxels, the sky map) with the inputs
//                     built from the world at that moment, and the clouds' shadow map when a
//                     feature casts one (the froxels' light shafts);
//   "atmosphere sky"  records Context::render without depth into a new scene colour: the sky
//                     and the sun's disc in every pixel, for the renderer to draw over.
// The sky map and the froxels are imported into the graph and handed on as the blackboard's
// fxcontracts::ecs::SkyRadiance and AerialPerspective (whose per-frame values the "atmosphere"
// pass writes when it executes): the renderer hazes its geometry with the froxels, the clouds
// read both.
#include <memory>
#include <optional>

#include "atmosphere/atmosphere.h"
#include "engine/ecs/world.h"
#include "engine/render/render_feature.h"
#include "fxcontracts/ecs/frame_entries.h"

namespace atmosphere::ecs {

class AtmosphereFeature final : public engine::render::RenderFeature {
 public:
  // Throws engine::ecs::ModuleUnsupported when the module cannot be created on this device.
  AtmosphereFeature(engine::ecs::World& world, const engine::render::RenderDevice& device);
  ~AtmosphereFeature() override;

  const char* name() const override { return "atmosphere"; }
  std::uint64_t gpuMemoryBytes() const override { return context_->memoryUsage().totalBytes(); }
  bool drawsSky() const override { return true; }
  void drawSkyInScenePass(VkCommandBuffer cmd) override;
  bool prepare(VkExtent2D extent, std::uint64_t frameIndex) override;
  engine::render::SceneTextures addPassesBeforeScene(
      engine::render::FrameGraph& graph, const engine::render::SceneTextures& scene) override;
  engine::render::SceneTextures addPasses(engine::render::FrameGraph& graph,
                                          const engine::render::SceneTextures& scene) override;
  void finish(std::uint64_t lastFrameIndex) override;

 protected:
  bool publishesEntry(std::type_index entry) const override;
  // Its aerial perspective reads the clouds' shadow map: light shafts in the haze.
  bool readsEntry(std::type_index entry) const override;

 private:
  void publishMeasurements(std::uint64_t completedFrame);
  // What the world reads of the air's parameters: the SunTransmittance they integrate and the
  // ground's albedo (engine/render/scene_components.h), when they change.
  void publishParameters();
  // `shadowView` and `shadowParameters`: the frame's cloud shadow map, if any.
  void dispatch(VkCommandBuffer cmd, VkExtent2D extent, std::uint64_t frameIndex,
                VkImageView shadowView,
                const fxcontracts::ecs::CloudShadowParameterBlock* shadowParameters);
  // This frame's values of the haze the blackboard hands on.
  void describeHaze(fxcontracts::ecs::AerialPerspective& haze) const;
  void reportError(const atmosphere::Error& error);

  engine::ecs::World& world_;
  engine::gfx::Device& device_;
  std::uint32_t framesInFlight_;
  std::unique_ptr<atmosphere::Context> context_;
  atmosphere::Parameters parameters_;  // this frame's, decided in prepare()
  atmosphere::Settings settings_;
  std::optional<atmosphere::Parameters> published_;  // what publishParameters() gave
  atmosphere::Outputs imported_;                     // the outputs the graph imported
  // The outputs the graph may import: none after a failed prepare(), whose outputs may be
  // missing or not yet in their layout.
  atmosphere::Outputs usableOutputs() const;
  bool prepared_ = false;    // this frame's prepare() succeeded
  bool dispatched_ = false;  // this frame's dispatch succeeded
  bool errorLogged_ = false;
};

}  // namespace atmosphere::ecs
