#pragma once
// The module's implementation behind clouds::Context, and the internal interface its own tests
// and tools reach through detail::ContextAccess (context_access.h).
//
// A frame: [first frame: noise generation] -> weather map and its maxima (when due) ->
// [the shadow map's cascades due: dispatchShadowMap()] -> uniforms -> [sky ambient] ->
// conservative scene distance at trace resolution -> march (one pixel per tile) -> temporal
// reconstruction -> depth-aware upsample into the outputs. The steps up to the weather run
// once per frame, in whichever of dispatchShadowMap() and dispatch() comes first.
//
// Where the code lives:
//   context.cpp          the public API: argument checks, error codes, forwarding here
//   context_impl.cpp     creation, prepare(), the frame's flow, reports
//   module_images.cpp    the images, how they are sized and retired
//   programs.cpp         the pass table (shaders, bindings, push constants)
//   record_weather.cpp   noise generation, the weather map and its maxima
//   record_trace.cpp     uniforms, sky ambient, scene distance, march, reconstruct, upsample
//   shadow_cascades.cpp  where the shadow map's cascades lie and when each is remade
//   record_shadow.cpp    the shadow map's cascades
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "hero_clouds.h"
#include "hero_light_volume.h"
#include "hero_noise.h"
#include "kit.h"
#include "module_images.h"
#include "passes.h"
#include "programs.h"
#include "shadow_cascades.h"
#include "temporal_state.h"
#include "uniforms.h"
#include "weather_schedule.h"

namespace clouds {

class Context::Impl {
 public:
  // Throws vkfx::Error when something cannot be created; what was created is destroyed.
  Impl(const CreateInfo& info, const detail::VulkanFunctions& functions);

  // Throws vkfx::Error (OutOfMemory, VulkanFailure).
  void prepare(const Settings& settings, VkExtent2D renderExtent);
  // Empty when dispatch() can run `settings` at `renderExtent`, else what prepare() must make.
  std::string unprepared(const Settings& settings, VkExtent2D renderExtent) const;
  // Records a frame; the inputs and settings are valid and prepared (context.cpp checks).
  void dispatch(const FrameInputs& inputs, const Settings& settings);
  // Whether dispatchShadowMap() can run `settings` (its pipeline and image exist).
  bool shadowPrepared(const Settings& settings) const;
  // Records the frame's shadow-map cascades (same preconditions).
  void dispatchShadowMap(const FrameInputs& inputs, const Settings& settings);
  void composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent);
  // Throws vkfx::Error (OutOfMemory, VulkanFailure); the assets are valid (context.cpp checks).
  void setHeroCloudAssets(std::span<const NvdfVolume* const> assets);
  std::size_t heroCloudAssets() const { return heroAtlas_ ? heroAtlas_->assets().size() : 0; }

  Outputs outputs() const;
  FrameReport lastFrameReport() const { return report_; }
  MemoryUsage memoryUsage() const;
  WorkCounters workCounters(std::uint64_t frameIndex) const;
  std::vector<PassTiming> passTimings(std::uint64_t frameIndex) const;
  SkyLighting skyLighting(std::uint64_t frameIndex) const;
  const CreateInfo& createInfo() const { return info_; }

  // --- Internal access (the module's tests and tools) ---------------------------------------
  const detail::DeviceContext& device() const { return device_; }
  const detail::ModuleImages& images() const { return images_; }
  // The weather map in use (the other one is being prepared for the next period).
  const detail::OwnedImage& weatherMap() const { return images_.weatherMaps[currentWeather_]; }
  const shader::CloudUniforms& lastUniforms() const { return lastUniforms_; }
  // The hero clouds the last dispatch() drew (count 0: none).
  const shader::HeroCloudUniforms& lastHeroClouds() const { return lastHeroClouds_; }
  // The hero clouds' detail noise (null until prepare() makes it for Settings::heroDetail).
  const detail::HeroNoise* heroNoise() const { return heroNoise_.get(); }
  // The uniforms and per-cascade constants of the last shadow-map cascades recorded.
  const shader::CloudUniforms& lastShadowUniforms() const { return lastShadowUniforms_; }
  const std::vector<shader::ShadowMapConstants>& lastShadowJobs() const { return lastShadowJobs_; }
  // The hero clouds the last shadow-map cascades were made with (count 0: none).
  const shader::HeroCloudUniforms& lastShadowHeroClouds() const { return sliceHeroClouds_; }
  // The terrain-shadow constants of the last cascades recorded with FrameInputs::terrain.
  const std::vector<shader::TerrainShadowConstants>& lastTerrainShadowJobs() const {
    return lastTerrainShadowJobs_;
  }
  std::uint64_t weatherUpdates() const { return weatherUpdates_; }
  // Test-only uniform flags (e.g. shader::kFlagHomogeneous) ORed into every frame.
  void setDebugFlags(std::uint32_t flags) { debugFlags_ = flags; }
  // Tests: a changing look marched as it is (TemporalState::marchedSettings()).
  void leadTheLook(bool on) { temporal_.leadTheLook(on); }

 private:
  // What one frame-in-flight slot owns: its uniforms, counters and descriptor sets (rewritten
  // by each frame that uses the slot, after the host waited for the slot's previous frame).
  struct Slot {
    detail::OwnedBuffer uniforms;
    detail::OwnedBuffer counters;  // host-visible, CreateInfo::workCounters
    VkDescriptorSet sceneDistance = VK_NULL_HANDLE;
    VkDescriptorSet march = VK_NULL_HANDLE;
    VkDescriptorSet reconstruct = VK_NULL_HANDLE;
    VkDescriptorSet nearResolve = VK_NULL_HANDLE;
    VkDescriptorSet upsample = VK_NULL_HANDLE;
    VkDescriptorSet composite = VK_NULL_HANDLE;
    VkDescriptorSet skyAmbient = VK_NULL_HANDLE;
    VkDescriptorSet weatherResample = VK_NULL_HANDLE;
    detail::OwnedBuffer shadowUniforms;  // the CloudUniforms the shadow map is made with
    VkDescriptorSet shadowMap = VK_NULL_HANDLE;
    VkDescriptorSet terrainShadow = VK_NULL_HANDLE;
    detail::OwnedBuffer shadowParameters;  // the march's MarchShadowMap
    VkDescriptorSet godRayOcclusion = VK_NULL_HANDLE;
    VkDescriptorSet godRays = VK_NULL_HANDLE;
    detail::OwnedBuffer godRayLight;  // god_rays.comp's GodRayLightUniforms
    detail::OwnedBuffer lightning;    // this frame's LightningUniforms (lightningFlashes > 0)
    detail::OwnedBuffer bolts;        // this frame's bolts on screen (lightningBoltSegments > 0)
    detail::OwnedBuffer edgeRayList;  // the march's edge tiles and their dispatch (edgeRays)
    VkDescriptorSet lightningBolts = VK_NULL_HANDLE;
    detail::OwnedBuffer heroClouds;  // this frame's HeroCloudUniforms (with hero cloud assets)
    detail::OwnedBuffer shadowHeroClouds;        // those the shadow map is made with (likewise)
    VkDescriptorSet heroLight = VK_NULL_HANDLE;  // the light volume's sweep
    VkDescriptorSet skyLight = VK_NULL_HANDLE;
    detail::OwnedBuffer skyLightMeasures;        // host-visible SkyLightMeasures (skyLight)
    std::optional<std::uint64_t> skyLightFrame;  // the frame whose measures it holds
  };

  VkDescriptorSet allocateSet(detail::Program program);
  // What each frame records once, before its first pass: retiring images, the pass timer's
  // frame, first layouts, the noise (first frame) and the weather.
  void startFrame(const FrameInputs& inputs, const Settings& settings, Slot& slot);
  void writeFixedSets();
  // A debug label and, with CreateInfo::passTimings, timestamps around a pass.
  void beginPass(VkCommandBuffer cmd, detail::Pass pass, const char* label);
  void endPass(VkCommandBuffer cmd, detail::Pass pass);
  void bindAndDispatch(VkCommandBuffer cmd, detail::Program program, VkPipeline pipeline,
                       VkDescriptorSet set, std::uint32_t width, std::uint32_t height);

  // record_weather.cpp
  void recordNoise(VkCommandBuffer cmd);
  void recordNoiseMipChains(VkCommandBuffer cmd);  // (part of recordNoise)
  void recordWeather(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                     Slot& slot);
  void recordWeatherRows(VkCommandBuffer cmd, const Settings& settings,
                         const detail::WeatherWork& work, double mapTimeSeconds);
  void recordWeatherMaxima(VkCommandBuffer cmd);

  // record_shadow.cpp
  void recordShadowMap(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                       const detail::ShadowPlan& plan, Slot& slot);
  void recordTerrainShadow(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                           const std::vector<detail::CascadeJob>& jobs, Slot& slot);
  void copySpareIntoAtlas(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t resolution);
  void makeShadowMapVisible(VkCommandBuffer cmd);

  // record_god_rays.cpp: between the reconstruction and the upsample, which adds their light;
  // with `made` false (nothing marched) only the mask's clear. Returns whether the light was
  // made (the upsample then adds it).
  // `nearField`: the near field resolved, when the frame has one (VK_NULL_HANDLE: none).
  bool recordGodRays(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                     const detail::OwnedImage& traceSamples, VkImageView nearField, bool traced,
                     Slot& slot);

  // record_trace.cpp
  // `shadow`: the march's shadow-map block, when this frame's march reads the map; `heroes`:
  // its hero clouds, when it draws any.
  void recordUniforms(VkCommandBuffer cmd, Slot& slot, const shader::CloudUniforms& uniforms,
                      const shader::MarchShadowMap* shadow,
                      const shader::HeroCloudUniforms* heroes);
  void recordSkyAmbient(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                        bool shadowMapMade, Slot& slot);
  // Empties the edge rays' list before the march fills it (Settings::edgeRays).
  void recordEdgeRayListReset(VkCommandBuffer cmd, Slot& slot);
  // The outputs as the empty sky, unless they still hold it (outputsHoldClearSky_).
  void recordClearSky(VkCommandBuffer cmd, Slot& slot);
  // record_lightning.cpp: this frame's flashes into the slot's block; whether there are any
  // (the reconstruction then makes their glow and the upsample adds it).
  bool recordLightning(VkCommandBuffer cmd, const FrameInputs& inputs, Slot& slot);
  // This frame's bolts drawn into the radiance output (its set written), which the upsample
  // left ready for compute reads and writes; then the outputs made visible to the host.
  void recordBolts(VkCommandBuffer cmd, const FrameInputs& inputs, bool hazed, Slot& slot);
  // The hero light volume's sweep of `instances` (bits; none: only its first layout) from the
  // block recordUniforms() wrote.
  void recordHeroLight(VkCommandBuffer cmd, std::uint32_t instances, Slot& slot);
  // This frame's hero block for `inputs` (their detail as `settings` ask, when it is made).
  shader::HeroCloudUniforms heroBlock(const FrameInputs& inputs, const Settings& settings) const;
  // The detail noise's image, or a stand-in the march never reads (the header says no detail).
  VkImageView heroNoiseView() const;
  // `heroClouds`: the variant (shader::kHeroClouds*) that draws this frame's hero clouds
  // (recordUniforms() wrote them), kHeroCloudsOff for none.
  void recordTrace(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                   const detail::TemporalFrame& temporal, VkExtent2D traceExtent,
                   std::uint32_t shadowMapReads, std::uint32_t heroClouds, Slot& slot);
  // recordTrace()'s passes, in their order, each over the set recordTrace() wrote for it.
  void recordSceneDistance(VkCommandBuffer cmd, VkExtent2D traceExtent, Slot& slot);
  // `edgeRays`: detail::marchesEdgeRays(), which adds the edge tiles' dispatch.
  void recordMarch(VkCommandBuffer cmd, const Settings& settings, std::uint32_t tileSize,
                   VkExtent2D traceExtent, std::uint32_t shadowMapReads, bool edgeRays,
                   std::uint32_t heroClouds, Slot& slot);
  // The near field's pass (TemporalFrame::nearField): every near-field pixel's ray to the split,
  // and their resolve with last frame's (`history`: it is usable).
  void recordNearField(VkCommandBuffer cmd, const Settings& settings, VkExtent2D traceExtent,
                       std::uint32_t shadowMapReads, std::uint32_t heroClouds, bool history,
                       Slot& slot);
  // `lightning`: recordLightning() wrote flashes, whose glow is reconstructed too.
  void recordReconstruct(VkCommandBuffer cmd, const detail::TemporalFrame& temporal,
                         VkExtent2D traceExtent, bool lightning, Slot& slot);
  // The sky light (Settings::skyLight), after the frame's other passes: the march's sky-light
  // pass when `marched` (recordTrace() wrote its set and the uniforms' skyLightRefresh), then
  // the map and its measures over the host's sky. `shadowMapReads`, `heroClouds`: the frame's
  // march variant's.
  void recordSkyLight(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                      bool marched, bool shadowMapMade, std::uint32_t shadowMapReads,
                      std::uint32_t heroClouds, Slot& slot);
  // `toBolts`: the bolts' pass follows; else the outputs are left visible to the host.
  void recordUpsample(VkCommandBuffer cmd, VkPipeline pipeline, VkExtent2D renderExtent,
                      bool toBolts, Slot& slot);

  // Declaration order is destruction order reversed: everything below uses device_.
  CreateInfo info_;
  detail::DeviceContext device_;
  detail::Programs programs_;
  detail::ModuleImages images_;
  detail::UniqueSampler nearestSampler_;
  detail::UniqueSampler linearSampler_;         // repeats (the sky image wraps in azimuth)
  detail::UniqueSampler clampedLinearSampler_;  // the shadow map, the host's heightfield
  detail::UniqueDescriptorPool pool_;           // frees every descriptor set with it
  std::unique_ptr<detail::PassTimer> timer_;    // CreateInfo::passTimings
  std::vector<Slot> slots_;

  // Sets over fixed images, written once.
  VkDescriptorSet shapeSet_ = VK_NULL_HANDLE;
  VkDescriptorSet detailSet_ = VK_NULL_HANDLE;
  VkDescriptorSet shapeMipSet_ = VK_NULL_HANDLE;   // noise_mip.comp on the shape noise's chain
  VkDescriptorSet detailMipSet_ = VK_NULL_HANDLE;  // ... and on the detail noise's
  VkDescriptorSet curlSet_ = VK_NULL_HANDLE;
  VkDescriptorSet heroNoiseSet_ = VK_NULL_HANDLE;        // hero_noise.comp (written when made)
  VkDescriptorSet heroNoiseMipSet_ = VK_NULL_HANDLE;     // hero_noise_mip.comp on its chain
  std::array<VkDescriptorSet, 2> weatherSets_{};         // generator, per map
  std::array<VkDescriptorSet, 2> weatherMaxFineSets_{};  // map -> fine maxima, per map
  VkDescriptorSet weatherMaxCoarseSet_ = VK_NULL_HANDLE;

  bool noiseGenerated_ = false;
  detail::WeatherSchedule weatherSchedule_;
  std::uint32_t currentWeather_ = 0;  // index into images_.weatherMaps
  std::uint64_t weatherUpdates_ = 0;
  // The last frame that recorded anything (startFrame()): the last use of the current images.
  std::optional<std::uint64_t> lastFrameIndex_;
  std::uint32_t lastSlot_ = 0;
  VkExtent2D lastExtent_{0, 0};
  detail::TemporalState temporal_;
  // The outputs hold the empty sky a clear frame made, and nothing has written them since
  // (each upsample, bolt and image replacement resets it): a clear sky that stays clear costs
  // no clears after its first frame.
  bool outputsHoldClearSky_ = false;
  // The sky light's clouds image does not hold the sky (new, or a clear frame or a cut since):
  // the next frame marches every texel of it, not a quarter.
  bool skyLightWhole_ = true;
  std::uint32_t skyLightRound_ = 0;  // the quarter of its texels the next frame marches
  // The hero clouds' assets (setHeroCloudAssets()); none: no atlas, no hero march.
  std::unique_ptr<detail::HeroCloudAtlas> heroAtlas_;
  std::unique_ptr<detail::HeroLightVolume> heroLight_;  // with the atlas (Settings::heroLight)
  // Made by prepare() for settings that up-rez them (Settings::heroDetail), generated by the
  // next frame, kept while there are hero clouds.
  std::unique_ptr<detail::HeroNoise> heroNoise_;
  bool heroNoiseGenerated_ = false;
  detail::ShadowCascades shadowCascades_;
  ShadowMapParameters shadowParameters_{};
  std::optional<std::uint64_t> shadowFrame_;     // the frame of the last dispatchShadowMap()
  std::uint32_t shadowCascadesMade_ = 0;         // this frame's (FrameReport::shadowCascadesMade)
  shader::GodRayParameters godRayParameters_{};  // the last dispatch()'s (Outputs::godRay*)
  FrameReport report_{};
  shader::CloudUniforms lastUniforms_{};
  shader::HeroCloudUniforms lastHeroClouds_{};
  shader::CloudUniforms lastShadowUniforms_{};
  // The field the shadow map is made with: this frame's, or for a cascade made in slices the
  // frame's of its first slice.
  shader::CloudUniforms sliceUniforms_{};
  shader::HeroCloudUniforms sliceHeroClouds_{};  // the hero clouds it is made with
  std::vector<shader::ShadowMapConstants> lastShadowJobs_;
  std::vector<shader::TerrainShadowConstants> lastTerrainShadowJobs_;
  std::uint32_t debugFlags_ = 0;
};

}  // namespace clouds
