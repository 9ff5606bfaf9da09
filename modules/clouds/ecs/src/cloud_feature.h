#pragma once
// The clouds module as a render feature of the engine: it owns a clouds::Context on the
// engine's device (and the painted weather maps, when the layer or its weather has some),
// prepares it outside the frame, and adds its passes to the renderer's frame graph: first, when
// the layer casts shadows,
//   "cloud shadows"     records Context::dispatchShadowMap (the cascades due this frame) and
//                       hands the map and its parameters to the passes after it (the haze,
//                       the terrain) as the blackboard's fxcontracts::ecs::CloudShadow, when
//                       the frame has a receiver (fxcontracts::ecs::CloudShadowWanted);
// then after the opaque scene:
//   "clouds"            reads the scene depth (and the blackboard's sky radiance and aerial
//                       perspective when a feature that draws the sky provides them) and
//                       records Context::dispatch with the inputs built from the world and the
//                       blackboard at that moment (cloud_frame.h);
//   "clouds composite"  applies the result over the scene colour (colour * T + radiance).
// The module's outputs are imported into the graph so later passes can read them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "engine/ecs/world.h"
#include "engine/gfx/resources.h"
#include "engine/render/render_feature.h"
#include "fxcontracts/ecs/frame_entries.h"

namespace clouds::ecs {

struct CloudLayer;
struct HostFrame;

class CloudFeature final : public engine::render::RenderFeature {
 public:
  // Throws engine::ecs::ModuleUnsupported when the module cannot be created on this device,
  // engine::Error when a painted weather map (the layer's, the weather timeline's) cannot be
  // read.
  CloudFeature(engine::ecs::World& world, const engine::render::RenderDevice& device,
               const CloudLayer& layer);
  ~CloudFeature() override;

  const char* name() const override { return "clouds"; }
  std::vector<std::string> effects() const override;
  std::uint64_t gpuMemoryBytes() const override { return context_->memoryUsage().totalBytes(); }
  bool prepare(VkExtent2D extent, std::uint64_t frameIndex) override;
  engine::render::SceneTextures addShadowPasses(
      engine::render::FrameGraph& graph, const engine::render::SceneTextures& scene) override;
  // Puts the sky light's map on the blackboard (fxcontracts::ecs::CoveredSkyRadiance).
  engine::render::SceneTextures addPassesBeforeScene(
      engine::render::FrameGraph& graph, const engine::render::SceneTextures& scene) override;
  engine::render::SceneTextures addPasses(engine::render::FrameGraph& graph,
                                          const engine::render::SceneTextures& scene) override;
  void finish(std::uint64_t lastFrameIndex) override;

 protected:
  bool publishesEntry(std::type_index entry) const override;
  bool readsEntry(std::type_index entry) const override;

 private:
  // This frame's hero clouds into `inputs` (kept in heroClouds_, which the span points at).
  void placeHeroClouds(clouds::FrameInputs& inputs);
  // This frame's weather regions into `inputs` (kept in weatherRegions_).
  void placeWeatherRegions(clouds::FrameInputs& inputs);
  // This frame's painted weather into `frame`: the layer's map, or the weather timeline's key's
  // blending into the next one's.
  void choosePaintedWeather(HostFrame& frame) const;
  void dispatch(const HostFrame& host);
  // Fills `shadow`'s per-frame values.
  void dispatchShadowMap(const HostFrame& host, fxcontracts::ecs::CloudShadow& shadow);
  void composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent);
  void reportError(const clouds::Error& error);
  // `settings` as the engine uses them (no depth output; the sky light with a drawn sky).
  clouds::Settings forTheEngine(clouds::Settings settings) const;
  // The sky light of a completed frame as the scene's CoveredSkyLight (none when the frame made
  // none).
  void publishSkyLight(const clouds::SkyLighting& measured);
  // Prepares every preset a budgeted camera may switch to (frame_budget.h), once per set and
  // extent, so that a switch builds nothing mid-flight.
  void prepareGovernedPresets(VkExtent2D extent);

  engine::ecs::World& world_;
  engine::gfx::Device& device_;
  // The frame graph has a drawn sky (fxcontracts::ecs::SkyRadiance): the clouds make the sky
  // light over it, from the prepare() after the graph was built.
  bool skyOnGraph_ = false;
  std::uint32_t framesInFlight_;
  std::unique_ptr<engine::gfx::Image> weatherMap_;  // the layer's painted map, if any
  // The weather timeline's painted maps (CloudWeather::keyWeatherMaps), each file read once,
  // and which of them each timeline key shows.
  std::vector<std::unique_ptr<engine::gfx::Image>> scheduledMaps_;
  std::vector<std::size_t> keyMap_;
  std::unique_ptr<clouds::Context> context_;
  clouds::Settings settings_;                          // this frame's, decided in prepare()
  std::vector<clouds::Quality> preparedAhead_;         // the governed presets prepared
  VkExtent2D preparedAheadExtent_{0, 0};               // at this extent
  bool preparedAheadSkyLit_ = false;                   // with skyOnGraph_ as it was
  std::vector<clouds::LightningFlash> flashes_;        // this frame's (FrameInputs points at them)
  std::vector<clouds::LightningBoltSegment> bolts_;    // likewise
  std::vector<clouds::HeroCloud> heroClouds_;          // likewise
  std::vector<clouds::WeatherRegion> weatherRegions_;  // likewise
  std::optional<std::uint64_t> heroFrame_;             // the frame heroClouds_ were chosen for
  bool hasHeroClouds_ = false;  // the layer has hero cloud assets (loaded into the context)
  bool lifecycleProblemLogged_ = false;        // a bad HeroCloudLifecycle is worth seeing once
  clouds::Outputs imported_;                   // the outputs the graph imported
  engine::render::TextureHandle skyLightMap_;  // imported before the scene (none: no sky light)
  // The outputs the graph may import: none after a failed prepare(), whose outputs may be
  // missing or not yet in their layout.
  clouds::Outputs usableOutputs() const;
  bool prepared_ = false;     // this frame's prepare() succeeded
  bool castsShadow_ = false;  // the layer's settings have a shadow map
  bool dispatched_ = false;   // this frame's dispatch succeeded
  bool errorLogged_ = false;
};

}  // namespace clouds::ecs
