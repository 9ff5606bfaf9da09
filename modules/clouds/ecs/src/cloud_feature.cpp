#include "cloud_feature.h"

#include <algorithm>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_frame.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/assets/image_io.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/ecs/module.h"
#include "engine/gfx/upload.h"
#include "engine/render/scene_components.h"

namespace clouds::ecs {

using namespace engine::render;

namespace {

constexpr VkFormat kCompositeFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

// A painted weather map (R coverage, G type, B density) from an image file, for the module's
// FrameInputs::weatherView.
std::unique_ptr<engine::gfx::Image> loadWeatherMap(engine::gfx::Device& device,
                                                   const std::filesystem::path& path) {
  const engine::assets::ImageRgba32f image = engine::assets::readImage(path);
  std::vector<std::uint8_t> texels(image.pixels.size());
  for (std::size_t i = 0; i < texels.size(); ++i) {
    texels[i] = static_cast<std::uint8_t>(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  auto gpu = std::make_unique<engine::gfx::Image>(
      device, engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                     VK_FORMAT_R8G8B8A8_UNORM,
                                     {image.width, image.height, 1},
                                     1,
                                     1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     "painted weather map"});
  engine::gfx::uploadToImage(device, *gpu, std::as_bytes(std::span(texels)),
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  return gpu;
}

bool sameImages(const clouds::Outputs& a, const clouds::Outputs& b) {
  return a.radiance.image == b.radiance.image && a.depth.image == b.depth.image &&
         a.shadowMap.image == b.shadowMap.image && a.skyLight.image == b.skyLight.image;
}

// The module's outputs are kept in GENERAL between frames, their writes synchronised by the
// module: the graph sees them as imported storage images.
engine::render::TextureHandle importOutput(engine::render::FrameGraph& graph, const char* name,
                                           const clouds::OutputImage& image, VkExtent3D extent) {
  const engine::render::ResourceState general{VK_IMAGE_LAYOUT_GENERAL,
                                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  engine::render::ImportedTexture texture;
  texture.image = image.image;
  texture.view = image.view;
  texture.desc.extent = extent;
  texture.desc.format = image.format;
  texture.initial = general;
  texture.final = general;
  return graph.importTexture(name, texture);
}

}  // namespace

CloudFeature::CloudFeature(engine::ecs::World& world, const RenderDevice& device,
                           const CloudLayer& layer)
    : world_(world), device_(*device.device), framesInFlight_(device.framesInFlight) {
  if (device.hdrFormat != kCompositeFormat) {
    throw engine::ecs::ModuleUnsupported("the clouds composite needs an RGBA16F scene colour");
  }
  world_.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& weather) {
        std::vector<std::filesystem::path> files;
        for (const std::filesystem::path& file : weather.keyWeatherMaps) {
          const auto known = std::find(files.begin(), files.end(), file);
          keyMap_.push_back(static_cast<std::size_t>(known - files.begin()));
          if (known == files.end()) {
            files.push_back(file);
            scheduledMaps_.push_back(loadWeatherMap(device_, file));
          }
        }
      });
  // The layer's own map, unless the schedule paints every key (it then holds the layer's map
  // where a key has none of its own).
  if (layer.weatherMap && scheduledMaps_.empty()) {
    weatherMap_ = loadWeatherMap(device_, *layer.weatherMap);
  }
  castsShadow_ = layer.settings.shadowCascades > 0;
  clouds::CreateInfo info;
  engine::render::describeDevice(device_, info);
  info.depthFormat = device.depthFormat;
  info.compositeColorFormat = kCompositeFormat;
  info.maxRenderExtent = device.maxExtent;
  info.maxFramesInFlight = device.framesInFlight;
  info.reversedZ = true;
  info.noiseSeed = layer.noiseSeed;
  info.passTimings = true;  // a few timestamps: where the clouds' time goes, for HUD and logs
  clouds::Error error;
  context_ = clouds::Context::create(info, &error);
  if (!context_) {
    throw engine::ecs::ModuleUnsupported("the clouds module cannot run on this device: " +
                                         error.message + " (" + errorCodeName(error.code) + ")");
  }
  // The scene checked its assets when it loaded: what fails here is the device (memory).
  std::vector<const clouds::NvdfVolume*> heroAssets;
  for (const auto& asset : layer.heroCloudAssets) heroAssets.push_back(asset.get());
  hasHeroClouds_ = !heroAssets.empty();
  if (hasHeroClouds_ && !context_->setHeroCloudAssets(heroAssets, &error)) {
    throw engine::ecs::ModuleUnsupported("the clouds module cannot load the hero clouds: " +
                                         error.message + " (" + errorCodeName(error.code) + ")");
  }
}

CloudFeature::~CloudFeature() {
  // The module's objects may still be used by frames in flight. A destructor must not throw:
  // a device lost only now is reported and teardown goes on.
  try {
    device_.waitIdle();
  } catch (const engine::Error& error) {
    engine::log::error(std::string("CloudFeature teardown: ") + error.what());
  }
}

bool CloudFeature::prepare(VkExtent2D extent, std::uint64_t frameIndex) {
  auto& status = world_.ctx().get<CloudStatus>();
  status.report = context_->lastFrameReport();
  status.memory = context_->memoryUsage();
  if (frameIndex >= framesInFlight_) {
    // The slot about to be reused holds the latest completed frame's timestamps and sky light.
    status.passTimings = context_->passTimings(frameIndex - framesInFlight_);
    publishSkyLight(context_->skyLighting(frameIndex - framesInFlight_));
  }
  settings_ = forTheEngine(cloudSettings(world_));
  clouds::Error error;
  prepareGovernedPresets(extent);
  prepared_ = context_->prepare(settings_, extent, &error);
  if (!prepared_) reportError(error);
  // A change rebuilds the graph: with the clouds' passes, or without them until prepare()
  // succeeds again.
  return !sameImages(usableOutputs(), imported_);
}

clouds::Settings CloudFeature::forTheEngine(clouds::Settings settings) const {
  // The engine's passes read the clouds' radiance only (addPasses() hands on no depth): the
  // module need not store its depth output (a quarter of its upsample on lavapipe).
  settings.depthOutput = false;
  // The scene's ambient is lit by the sky with its clouds (CoveredSkyLight) when the layer asks
  // for it and the frame graph has a drawn sky to lay them over; a scene without one pays
  // nothing for it.
  settings.skyLight = settings.skyLight && skyOnGraph_;
  return settings;
}

void CloudFeature::publishSkyLight(const clouds::SkyLighting& measured) {
  if (!measured.valid) {
    world_.ctx().erase<CoveredSkyLight>();
    return;
  }
  CoveredSkyLight covered;
  covered.light.zenith = measured.zenith;
  covered.light.horizon = measured.horizon;
  covered.light.ground = measured.lower;
  covered.irradianceOverPi = measured.upperIrradianceOverPi;
  covered.sunAtCamera = measured.sunTransmittanceAtCamera;
  covered.sunAround = measured.sunlitShareAround;
  covered.seenFromMetres = measured.seenFromAltitudeMetres;
  covered.clearAboveMetres = measured.coverTopMetres;
  world_.ctx().emplaceOrReplace<CoveredSkyLight>(covered);
}

void CloudFeature::prepareGovernedPresets(VkExtent2D extent) {
  const std::span<const clouds::Quality> presets = governedPresets(world_);
  if (std::equal(presets.begin(), presets.end(), preparedAhead_.begin(), preparedAhead_.end()) &&
      extent.width == preparedAheadExtent_.width && extent.height == preparedAheadExtent_.height &&
      skyOnGraph_ == preparedAheadSkyLit_) {
    return;
  }
  preparedAhead_.assign(presets.begin(), presets.end());
  preparedAheadExtent_ = extent;
  preparedAheadSkyLit_ = skyOnGraph_;
  // Dearest first: its images are the largest, and the others then fit in them.
  for (auto it = presets.rbegin(); it != presets.rend(); ++it) {
    clouds::Error error;
    if (!context_->prepare(forTheEngine(cloudSettingsFor(world_, *it)), extent, &error)) {
      reportError(error);
    }
  }
}

clouds::Outputs CloudFeature::usableOutputs() const {
  return prepared_ ? context_->outputs() : clouds::Outputs{};
}

void CloudFeature::finish(std::uint64_t lastFrameIndex) {
  auto& status = world_.ctx().get<CloudStatus>();
  status.report = context_->lastFrameReport();
  status.memory = context_->memoryUsage();
  status.passTimings = context_->passTimings(lastFrameIndex);
}

void CloudFeature::reportError(const clouds::Error& error) {
  world_.ctx().get<CloudStatus>().lastError = error.message;
  // Settings are validated when a scene loads, so this is a bug or the device out of memory:
  // worth seeing once. The frame goes on without clouds; prepare() is tried again next frame.
  if (!errorLogged_) {
    engine::log::error(error.message + " (" + errorCodeName(error.code) + ")");
  }
  errorLogged_ = true;
}

void CloudFeature::placeHeroClouds(clouds::FrameInputs& inputs) {
  if (!hasHeroClouds_) return;
  // The shadow pass and the clouds pass of a frame draw the same clouds: chosen once.
  if (heroFrame_ != inputs.frameIndex) {
    std::string problem;
    heroClouds_ = heroClouds(world_, inputs.cameraPosition, clouds::kMaxHeroClouds, &problem);
    if (!problem.empty() && !lifecycleProblemLogged_) {
      engine::log::error("a hero cloud is not drawn: " + problem);
      lifecycleProblemLogged_ = true;
    }
    heroFrame_ = inputs.frameIndex;
  }
  inputs.heroClouds = heroClouds_;
}

void CloudFeature::placeWeatherRegions(clouds::FrameInputs& inputs) {
  weatherRegions_ = currentWeatherRegions(world_);
  inputs.weatherRegions = weatherRegions_;
}

void CloudFeature::choosePaintedWeather(HostFrame& frame) const {
  frame.weatherView = weatherMap_ ? weatherMap_->view() : VK_NULL_HANDLE;
  const std::optional<clouds::WeatherPhase> phase = paintedWeatherPhase(world_);
  if (!phase || phase->from >= keyMap_.size() || phase->to >= keyMap_.size()) return;
  const std::size_t from = keyMap_[phase->from];
  const std::size_t to = keyMap_[phase->to];
  frame.weatherView = scheduledMaps_[from]->view();
  if (to != from && phase->blend > 0.0f) {
    frame.weatherBlendView = scheduledMaps_[to]->view();
    frame.weatherBlend = phase->blend;
  }
}

void CloudFeature::dispatch(const HostFrame& host) {
  HostFrame frame = host;
  choosePaintedWeather(frame);
  clouds::Error error;
  clouds::FrameInputs inputs = cloudFrameInputs(world_, frame);
  flashes_ = lightningFlashes(world_, settings_.lightningFlashes);
  inputs.lightningFlashes = flashes_;
  bolts_ = lightningBolts(world_, settings_.lightningBoltSegments);
  inputs.lightningBolts = bolts_;
  placeHeroClouds(inputs);
  placeWeatherRegions(inputs);
  // The sky light lays the clouds over the drawn sky: none without one.
  clouds::Settings settings = settings_;
  settings.skyLight = settings.skyLight && inputs.skyView != VK_NULL_HANDLE;
  dispatched_ = context_->dispatch(inputs, settings, &error);
  if (dispatched_) {
    auto& status = world_.ctx().get<CloudStatus>();
    status.lastError.clear();
    status.report = context_->lastFrameReport();  // this frame's, for what reads it after
  } else {
    reportError(error);
  }
}

std::vector<std::string> CloudFeature::effects() const {
  std::vector<std::string> names;
  if (settings_.shadowCascades > 0) {
    names.emplace_back("shadow map");
    // The terrain's shadow in the map, with a heightfield the scene publishes.
    const auto* ground = world_.ctx().tryGet<engine::render::TerrainHeightfield>();
    if (ground != nullptr && ground->view != VK_NULL_HANDLE) names.emplace_back("terrain shadow");
  }
  if (settings_.godRaySamples > 0) names.emplace_back("god rays");
  if (settings_.lightningFlashes > 0) names.emplace_back("lightning");
  if (settings_.lightningBoltSegments > 0) names.emplace_back("lightning bolts");
  if (hasHeroClouds_) names.emplace_back("hero clouds");
  if (settings_.weatherRegions > 0) names.emplace_back("weather regions");
  if (settings_.superstorms > 0) names.emplace_back("superstorm");
  // As forTheEngine() decides it (settings_ is the last prepared frame's: none yet before the
  // first frame, when a description is printed).
  if (skyOnGraph_ && cloudSettings(world_).skyLight) names.emplace_back("sky light");
  return names;
}

bool CloudFeature::publishesEntry(std::type_index entry) const {
  if (entry == typeid(fxcontracts::ecs::CoveredSkyRadiance)) return cloudSettings(world_).skyLight;
  return castsShadow_ && entry == typeid(fxcontracts::ecs::CloudShadow);
}

bool CloudFeature::readsEntry(std::type_index entry) const {
  return entry == typeid(fxcontracts::ecs::SkyRadiance) ||
         entry == typeid(fxcontracts::ecs::AerialPerspective);
}

void CloudFeature::dispatchShadowMap(const HostFrame& host, fxcontracts::ecs::CloudShadow& shadow) {
  HostFrame frame = host;
  choosePaintedWeather(frame);
  clouds::Error error;
  clouds::FrameInputs inputs = cloudFrameInputs(world_, frame);
  placeHeroClouds(inputs);
  placeWeatherRegions(inputs);
  if (context_->dispatchShadowMap(inputs, settings_, &error)) {
    const clouds::ShadowMapParameters& p = context_->outputs().shadowParameters;
    static_assert(sizeof(p) == sizeof(shadow.parameters));
    std::copy(std::begin(p.cascade), std::end(p.cascade), shadow.parameters.begin());
    shadow.parameters.back() = p.info;
    const std::uint32_t every = (1u << settings_.shadowCascades) - 1u;
    shadow.remadeWhole = context_->lastFrameReport().shadowCascadesMade == every;
  } else {
    shadow.parameters = {};  // no shadow rather than a stale one
    shadow.remadeWhole = true;
    reportError(error);
  }
}

void CloudFeature::composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent) {
  if (!dispatched_) return;  // no clouds this frame: the scene colour stays as it is
  clouds::Error error;
  if (!context_->composite(cmd, color, extent, &error)) reportError(error);
}

SceneTextures CloudFeature::addShadowPasses(FrameGraph& graph, const SceneTextures& scene) {
  imported_ = usableOutputs();
  // No receiver in this frame, no map.
  if (!castsShadow_ || !graph.blackboard().has<fxcontracts::ecs::CloudShadowWanted>() ||
      imported_.shadowMap.image == VK_NULL_HANDLE) {
    return scene;
  }
  const VkExtent3D extent{settings_.shadowMapResolution * settings_.shadowCascades,
                          settings_.shadowMapResolution, 1};
  const TextureHandle map = importOutput(graph, "cloud shadow map", imported_.shadowMap, extent);
  struct ShadowData {
    TextureHandle map;
  };
  const ShadowData& shadow = graph.addPass<ShadowData>(
      "cloud shadows", PassType::Compute,
      [&](PassBuilder& builder, ShadowData& d) {
        d.map = builder.write(map, Access::StorageWrite);
      },
      [this, sceneExtent = scene.extent](const ShadowData&, PassContext& context) {
        HostFrame host;
        host.commandBuffer = context.cmd();
        host.extent = sceneExtent;
        host.frameIndex = context.frameIndex();
        dispatchShadowMap(host, context.blackboard().get<fxcontracts::ecs::CloudShadow>());
      });
  graph.blackboard().put(fxcontracts::ecs::CloudShadow{shadow.map});
  return scene;
}

SceneTextures CloudFeature::addPassesBeforeScene(FrameGraph& graph, const SceneTextures& scene) {
  imported_ = usableOutputs();
  skyLightMap_ = {};
  if (imported_.skyLight.image != VK_NULL_HANDLE) {
    skyLightMap_ = importOutput(graph, "cloud sky light", imported_.skyLight,
                                {clouds::kSkyLightExtent.width, clouds::kSkyLightExtent.height, 1});
    graph.blackboard().put(fxcontracts::ecs::CoveredSkyRadiance{skyLightMap_});
  }
  return scene;
}

SceneTextures CloudFeature::addPasses(FrameGraph& graph, const SceneTextures& scene) {
  imported_ = usableOutputs();
  if (imported_.radiance.image == VK_NULL_HANDLE) return scene;  // prepare() failed
  const VkExtent3D sceneExtent = graph.textureDesc(scene.hdr).extent;
  const TextureHandle radiance =
      importOutput(graph, "cloud radiance", imported_.radiance, sceneExtent);
  // The depth output exists only for the bolts' pass, which the module runs inside dispatch().
  const TextureHandle depth = imported_.depth.image != VK_NULL_HANDLE
                                  ? importOutput(graph, "cloud depth", imported_.depth, sceneExtent)
                                  : TextureHandle{};

  // What other features made for this frame: the sky's light, the haze, the shadow map.
  const auto* sky = graph.blackboard().find<fxcontracts::ecs::SkyRadiance>();
  const auto* haze = graph.blackboard().find<fxcontracts::ecs::AerialPerspective>();
  const auto* shadow = graph.blackboard().find<fxcontracts::ecs::CloudShadow>();
  skyOnGraph_ = sky != nullptr;
  struct MarchData {
    TextureHandle sceneDepth, skyRadiance, aerialPerspective, radiance, depth;
  };
  const MarchData& march = graph.addPass<MarchData>(
      "clouds", PassType::Compute,
      [&](PassBuilder& builder, MarchData& d) {
        if (scene.depth.valid()) d.sceneDepth = builder.read(scene.depth, Access::SampledRead);
        if (sky != nullptr) d.skyRadiance = builder.read(sky->texture, Access::SampledReadGeneral);
        if (haze != nullptr) {
          d.aerialPerspective = builder.read(haze->volume, Access::SampledReadGeneral);
        }
        // The march reads the map (mountains shade the clouds; at High and Ultra the clouds
        // shade themselves beyond the light cone), the ambient pass its mean (the clouds' shade
        // on the ground that lights their bases).
        if (shadow != nullptr) builder.read(shadow->map, Access::SampledReadGeneral);
        d.radiance = builder.write(radiance, Access::StorageWrite);
        if (depth.valid()) d.depth = builder.write(depth, Access::StorageWrite);
        // The sky light's map, after the scene's readers (a reflection) of the frames' before.
        if (skyLightMap_.valid()) builder.write(skyLightMap_, Access::StorageWrite);
      },
      [this](const MarchData& d, PassContext& context) {
        const auto viewOf = [&](TextureHandle h) {
          return h.valid() ? context.view(h) : VK_NULL_HANDLE;
        };
        const VkExtent3D extent = context.extent(d.radiance);
        HostFrame host;
        host.commandBuffer = context.cmd();
        host.extent = {extent.width, extent.height};
        host.depthView = viewOf(d.sceneDepth);
        host.skyRadianceView = viewOf(d.skyRadiance);
        host.aerialPerspectiveView = viewOf(d.aerialPerspective);
        // The haze's values as its pass (ordered before this one) wrote them this frame.
        using fxcontracts::ecs::AerialPerspective;
        if (const auto* air = context.blackboard().find<AerialPerspective>()) {
          host.aerialPerspectiveSlices = air->slices;
          host.aerialPerspectiveRangeMetres = air->rangeMetres;
          host.hazeRayleighPerMetre = air->rayleighScatteringPerMetre;
          host.hazeMiePerMetre = air->mieScatteringPerMetre;
          host.hazeMiePhaseG = air->miePhaseG;
        }
        host.frameIndex = context.frameIndex();
        dispatch(host);
      });

  struct CompositeData {
    TextureHandle hdr, radiance;
  };
  const CompositeData& composited = graph.addPass<CompositeData>(
      "clouds composite", PassType::Compute,
      [&](PassBuilder& builder, CompositeData& d) {
        d.radiance = builder.read(march.radiance, Access::StorageRead);
        // God rays read the scene's depth and haze (fxcontracts/god_rays.h).
        if (settings_.godRaySamples > 0) {
          if (scene.depth.valid()) builder.read(scene.depth, Access::SampledRead);
          if (haze != nullptr) builder.read(haze->volume, Access::SampledReadGeneral);
        }
        d.hdr = builder.write(scene.hdr, Access::StorageWrite);
      },
      [this](const CompositeData& d, PassContext& context) {
        const VkExtent3D extent = context.extent(d.hdr);
        composite(context.cmd(), context.view(d.hdr), {extent.width, extent.height});
      });
  SceneTextures out = scene;
  out.hdr = composited.hdr;
  return out;
}

}  // namespace clouds::ecs
