#include "render/renderer.h"

#include "clouds/ecs/cloud_frame.h"
#include "clouds/ecs/lightning.h"
#include "fxcontracts/ecs/frame_entries.h"

#include "render/scene_pass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/ecs/frame_time.h"
#include "engine/gfx/upload.h"
#include "engine/render/camera_math.h"
#include "engine/render/exposure.h"
#include "engine/render/gpu_frame_time.h"
#include "engine/render/scene_components.h"
#include "game/water.h"
#include "render/hud.h"
#include "render/terrain_renderer.h"
#include "render/water_renderer.h"
#include "scene/scene_loader.h"

namespace sample {

using namespace engine;

Renderer::Renderer(gfx::Device& device, render::PresentTarget& target, ecs::World& world,
                   const RendererOptions& options)
    : device_(device),
      target_(target),
      options_(options),
      ring_(device),
      tonemapper_(device, kHdrFormat, target.format()),
      capture_(device) {
  std::vector<const gfx::Pipeline*> pipelines = {&tonemapper_.pipeline()};
  if (const auto* features = world.ctx().tryGet<render::RenderFeatures>()) {
    features_ = features->features;
  }
  // A feature that draws the sky also hazes: the terrain reads its aerial perspective.
  std::copy_if(features_.begin(), features_.end(), std::back_inserter(skyDrawers_),
               [](const render::RenderFeature* f) { return f->drawsSky(); });
  const bool featureSky = !skyDrawers_.empty();
  if (!featureSky) {
    sky_ = std::make_unique<SkyPass>(device, kHdrFormat);
    pipelines.push_back(&sky_->pipeline());
  }
  const bool cloudShadows = anyFeature(
      [](const render::RenderFeature* f) { return f->publishes<fxcontracts::ecs::CloudShadow>(); });
  // A storm's flashes light the ground and the water: their variants with that code (none
  // without).
  bool storm = false;
  world.view<const clouds::ecs::LightningStorm>().each(
      [&](const clouds::ecs::LightningStorm&) { storm = true; });
  if (const auto* mesh = world.ctx().tryGet<TerrainMesh>()) {
    terrain_ =
        std::make_unique<TerrainRenderer>(device, *mesh->mesh, kHdrFormat, kDepthFormat, featureSky,
                                          cloudShadows, storm, mesh->closeDetail);
    terrainMaterials_ = terrainMaterialsFor(*mesh->mesh, mesh->snowlineMetres);
    for (const gfx::Pipeline* pipeline : terrain_->pipelines()) pipelines.push_back(pipeline);
    // Under shadow-casting clouds the terrain is lit through its sunlight map, made over its
    // heightfield; mountains also shade the clouds and themselves when the heightfield goes to
    // the clouds' shadow map (a terrain that casts shadows). Without a map, neither is made.
    if (cloudShadows) {
      heightfield_ = std::make_unique<TerrainHeightfieldImage>(device, *mesh->mesh);
      sunlight_ = std::make_unique<TerrainSunlight>(device, heightfield_->description(),
                                                    TerrainHeightfieldImage::kResolution);
      pipelines.push_back(&sunlight_->pipeline());
      if (mesh->castsShadows) {
        world.ctx().emplaceOrReplace<render::TerrainHeightfield>(heightfield_->description());
        world_ = &world;
      }
    }
  }
  // A lake or sea: hazed and lit like the terrain (through its sunlight map under shadow-casting
  // clouds), its bed the terrain's extent.
  if (world.ctx().tryGet<WaterSurface>() != nullptr) {
    water_ = std::make_unique<WaterRenderer>(device, kHdrFormat, kDepthFormat, featureSky,
                                             sunlight_ != nullptr, storm);
    for (const gfx::Pipeline* pipeline : water_->pipelines()) pipelines.push_back(pipeline);
    waterBed_ = glm::vec4(1.0f, 1.0f, -1.0f, -1.0f);  // none
    if (const auto* mesh = world.ctx().tryGet<TerrainMesh>()) {
      waterBed_ = glm::vec4(mesh->mesh->boundsMin.x, mesh->mesh->boundsMin.z,
                            mesh->mesh->boundsMax.x, mesh->mesh->boundsMax.z);
    }
  }
  if (options.hud) {
    hud_ = std::make_unique<Hud>(device, target.format(), options.hudClears);
    pipelines.push_back(&hud_->pipeline());
  }
  const auto start = std::chrono::steady_clock::now();
  const double ms = gfx::warmUpPipelines(device, pipelines);
  // The features build their pipelines and size their resources for the first frame now,
  // outside any recording (each frame prepares them again: cheap when nothing changed).
  // (A window's swapchain may not exist yet: then the first frame prepares them.)
  const VkExtent2D first = target.extent();
  if (first.width > 0 && first.height > 0) {
    for (render::RenderFeature* feature : features_) feature->prepare(first, 0);
  }
  const double featureMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() -
      ms;
  log::info("pipelines warmed up in " + std::to_string(static_cast<int>(ms)) +
            " ms, render features prepared in " + std::to_string(static_cast<int>(featureMs)) +
            " ms");
}

Renderer::~Renderer() {
  // Also runs while an error unwinds the frame loop, so it must not throw (e.g. a device lost
  // only now): reported, and teardown goes on.
  try {
    finish();
  } catch (const engine::Error& error) {
    log::error(std::string("renderer teardown: ") + error.what());
  }
  // The heightfield goes with the renderer: nothing may read its view afterwards.
  if (world_) world_->ctx().emplaceOrReplace<render::TerrainHeightfield>();
}

render::TextureHandle Renderer::importNoHaze(render::FrameGraph& graph) {
  constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  const gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
  if (!noHaze_) {
    noHaze_ = std::make_unique<gfx::Image>(
        device_, gfx::ImageDesc{VK_IMAGE_TYPE_3D,
                                kFormat,
                                {1, 1, 1},
                                1,
                                1,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                "no haze"});
    const std::uint16_t texel[4] = {0, 0, 0, 0x3C00};  // half floats: no light, transmittance 1
    gfx::uploadToImage(device_, *noHaze_, std::as_bytes(std::span(texel)), general);
  }
  render::ImportedTexture texture;
  texture.image = noHaze_->vk();
  texture.view = noHaze_->view();
  texture.desc.extent = {1, 1, 1};
  texture.desc.format = kFormat;
  texture.desc.type = VK_IMAGE_TYPE_3D;
  texture.initial = {general.layout, general.stages, general.access};
  texture.final = texture.initial;
  return graph.importTexture("no haze", texture);
}

void Renderer::rebuildGraph(VkExtent2D extent) {
  graph_ = std::make_unique<render::FrameGraph>(&device_);
  render::FrameGraph& graph = *graph_;
  targetHandle_ = graph.importTexture("present target", target_.describe());

  render::TextureDesc hdrDesc;
  hdrDesc.extent = {extent.width, extent.height, 1};
  hdrDesc.format = kHdrFormat;
  // What the scene reads, made before it: a feature's sky and its light, or the renderer's own
  // gradient sky.
  render::SceneTextures scene;
  scene.extent = extent;
  // A cloud shadow map is made only for a frame that receives it.
  if ((terrain_ && terrain_->shadowedByClouds()) || anyFeature([](const render::RenderFeature* f) {
        return f->reads<fxcontracts::ecs::CloudShadow>();
      })) {
    graph.blackboard().put(fxcontracts::ecs::CloudShadowWanted{});
  }
  // What shadows the frame, then what the scene reads (the sky and its haze may read shadows).
  for (render::RenderFeature* feature : features_) scene = feature->addShadowPasses(graph, scene);
  const render::TextureHandle sunlight =
      sunlight_ ? sunlight_->addPass(graph, &cameraPosition_) : render::TextureHandle{};
  for (render::RenderFeature* feature : features_) {
    scene = feature->addPassesBeforeScene(graph, scene);
  }
  if (sky_) scene.hdr = addSkyPass(graph, *sky_, hdrDesc, &sceneFrame_);
  const bool hazed = (terrain_ && terrain_->hazedByAerialPerspective()) ||
                     (water_ && water_->hazedByAerialPerspective());
  if (hazed && !graph.blackboard().has<fxcontracts::ecs::AerialPerspective>()) {
    fxcontracts::ecs::AerialPerspective noHaze;
    noHaze.volume = importNoHaze(graph);
    noHaze.slices = 1;
    noHaze.rangeMetres = 1.0f;
    graph.blackboard().put(noHaze);
  }
  // The scene's surfaces, and a feature's sky behind them: a graphics pass whenever one exists.
  if (terrain_ || water_ || !skyDrawers_.empty()) {
    const SceneTargets targets =
        addScenePass(graph, {terrain_.get(), water_.get()}, scene, sunlight, skyDrawers_,
                     kHdrFormat, kDepthFormat, &sceneFrame_);
    scene.hdr = targets.hdr;
    scene.depth = targets.depth;
  }
  for (render::RenderFeature* feature : features_) scene = feature->addPasses(graph, scene);
  const render::TextureHandle hdr = scene.hdr;
  render::TonemapOverlay overlay;
  if (hud_) {
    overlay = [hud = hud_.get()](render::PassContext& context) {
      hud->record(context.cmd(), context.descriptors(), context.device());
    };
  }
  render::TextureHandle display =
      render::addTonemapPass(graph, tonemapper_, hdr, targetHandle_, &tonemap_, std::move(overlay));
  capture_.addToGraph(graph, hdr, display);
  target_.addToGraph(graph, display);  // last: it reads what the frame drew
  graph.compile();
  graphExtent_ = extent;
}

void Renderer::updateFrameConstants(ecs::World& world, VkExtent2D extent) {
  render::Camera camera;
  world.view<const render::Camera>().each([&](const render::Camera& c) { camera = c; });
  render::Sun sun;
  world.view<const render::Sun>().each([&](const render::Sun& s) { sun = s; });
  // The ground's ambient: the sky as its cover (clouds) makes it, when an effect measures that.
  const auto* covered = world.ctx().tryGet<render::CoveredSkyLight>();
  const render::SkyLight sky = covered ? covered->light : world.ctx().get<render::SkyLight>();
  const render::Fog fog = world.ctx().get<render::Fog>();
  // The terrain is lit by the sun as it reaches the ground through the scene's air.
  const glm::vec3 sunAtGround =
      render::sunIlluminanceAt(sun, world.ctx().tryGet<render::SunTransmittance>(), 0.0);

  const float aspect = float(extent.width) / float(extent.height);
  const glm::mat4 view = render::viewRotation(camera);
  const glm::mat4 projection = render::projectionOf(camera, aspect);
  const glm::vec3 forward = glm::vec3(render::forwardOf(camera));
  const glm::vec3 up = glm::vec3(render::upOf(camera));
  const glm::vec3 right = glm::normalize(glm::cross(forward, up));
  const float tanY = std::tan(camera.verticalFovRadians * 0.5f);

  shaders::SceneFrame& f = sceneFrame_.data;
  f.viewProjection = projection * view;
  f.cameraPosition = glm::vec4(glm::vec3(camera.position), 0.0f);
  f.cameraRight = glm::vec4(right, tanY * aspect);
  f.cameraUp = glm::vec4(up, tanY);
  f.cameraForward = glm::vec4(forward, 0.0f);
  f.sunDirection = glm::vec4(glm::vec3(sun.direction), 8.0f);
  f.sunIlluminance = glm::vec4(sunAtGround, 0.0f);
  f.skyZenith = glm::vec4(sky.zenith, 0.0f);
  f.skyHorizon = glm::vec4(sky.horizon, 0.0f);
  f.skyGround = glm::vec4(sky.ground, 0.0f);
  // y, z: the aerial perspective's range and slices, filled by the scene pass (scene_pass.h).
  f.fog = glm::vec4(fog.densityPerMetre, 0.0f, 0.0f, 0.0f);
  f.sunAboveAir = glm::vec4(sun.illuminance, 0.0f);
  f.extent = glm::uvec4(extent.width, extent.height, 0u, 0u);
  f.terrain = terrainMaterials_;
  cameraPosition_ = camera.position;
  if (sunlight_) f.sunlightMap = sunlight_->placementFor(camera.position);
  // The brightest flash in progress lights the ground (none without a storm).
  f.flash = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  f.flashRadiance = glm::vec4(0.0f);
  const std::vector<clouds::LightningFlash> flashes = clouds::ecs::lightningFlashes(world, 1);
  if (!flashes.empty()) {
    f.flash =
        glm::vec4(glm::vec3(flashes[0].positionMetres - camera.position), flashes[0].radiusMetres);
    f.flashRadiance = glm::vec4(flashes[0].radiance, 0.0f);
  }
  if (terrain_) terrain_->setFlashing(!flashes.empty());
  if (water_) water_->setFlashing(!flashes.empty());
  // The water as the scene has it now (a reloaded scene file may move its level).
  if (const auto* water = water_ ? world.ctx().tryGet<WaterSurface>() : nullptr) {
    const float height = float(camera.position.y - water->levelMetres);
    f.water = glm::vec4(float(water->levelMetres), float(water->clarity),
                        shaders::waterBedReachMetres(float(water->clarity), height), 0.0f);
    f.waterColour = glm::vec4(water->colour, 0.0f);
    f.waterBed = waterBed_;
    const shaders::WaterPhases phases =
        shaders::waterPhasesAt(glm::dvec2(camera.position.x, camera.position.z),
                               world.ctx().get<ecs::FrameTime>().elapsedSeconds);
    f.waterPhases = phases.first;
    f.waterPhasesHigh = phases.second;
  }
  sceneFrame_.reflectsCoveredSky = covered != nullptr;
  tonemap_.exposure = render::exposureScale(world.ctx().get<render::Exposure>().ev100);

  if (terrain_) terrain_->cull(f.viewProjection, camera.position);
}

std::optional<std::filesystem::path> Renderer::takeCaptureRequest(ecs::World& world) {
  std::optional<std::filesystem::path> stem;
  for (const CaptureFrame& e : captureReader_.read(world.events<CaptureFrame>())) {
    stem = options_.captureDirectory / e.name;
  }
  auto& request = world.ctx().get<CaptureRequest>();
  if (request.stem) stem = std::exchange(request.stem, std::nullopt);
  return stem;
}

void Renderer::publishGpuFrameTime(ecs::World& world, std::uint64_t frameIndex) const {
  // begin() retired the frame that used this slot: the latest completed one.
  if (frameIndex < gfx::FrameRing::kFramesInFlight) return;
  render::GpuFrameTime time;
  for (const gfx::TimedScope& scope : ring_.lastTimings()) time.milliseconds += scope.milliseconds;
  time.frameIndex = frameIndex - gfx::FrameRing::kFramesInFlight;
  time.measured = true;
  world.ctx().emplaceOrReplace<render::GpuFrameTime>(time);
}

void Renderer::renderFrame(ecs::World& world) {
  gfx::FrameRing::Frame& frame = ring_.begin();
  const std::optional<std::filesystem::path> captureStem = takeCaptureRequest(world);
  if (!target_.acquire(frame.slot)) {
    ring_.submit();  // nothing to draw into (minimized): keep the ring's bookkeeping going
    return;
  }
  const VkExtent2D extent = target_.extent();
  bool rebuild =
      !graph_ || extent.width != graphExtent_.width || extent.height != graphExtent_.height;
  for (render::RenderFeature* feature : features_) rebuild |= feature->prepare(extent, frame.index);
  rebuild |= sunlight_ && sunlight_->spentPass();
  if (rebuild) rebuildGraph(extent);
  graph_->updateImportedTexture(targetHandle_, target_.image(), target_.view());
  updateFrameConstants(world, extent);
  sceneFrame_.slice = frame.constants->push(sceneFrame_.data);
  publishGpuFrameTime(world, frame.index);
  if (hud_) hud_->prepare(world, extent, ring_.lastTimings(), frame);
  if (captureStem) capture_.arm(*captureStem);
  graph_->execute(frame);
  ring_.submit(target_.submitWaits(), target_.submitSignals());
  target_.present();
  if (captureStem) {
    ring_.drain();
    if (auto png = capture_.writePending()) log::info("captured " + png->string());
  }
}

void Renderer::finish() {
  ring_.drain();
  capture_.writePending();
  if (ring_.framesBegun() > 0) {
    for (render::RenderFeature* feature : features_) feature->finish(ring_.framesBegun() - 1);
  }
}

std::vector<std::string> Renderer::passNames() const {
  std::vector<std::string> names;
  if (graph_) {
    for (const char* name : graph_->executionOrder()) names.emplace_back(name);
  }
  return names;
}

std::vector<std::string> Renderer::shadowCasters() const {
  std::vector<std::string> casters;
  if (anyFeature([](const render::RenderFeature* f) {
        return f->publishes<fxcontracts::ecs::CloudShadow>();
      })) {
    casters.emplace_back("clouds");
  }
  if (world_ != nullptr) casters.emplace_back("terrain");  // its heightfield went to the map
  return casters;
}

std::vector<std::pair<std::string, std::uint64_t>> Renderer::gpuMemory() const {
  std::vector<std::pair<std::string, std::uint64_t>> memory = {
      {"renderer", device_.memory().stats().usedBytes}};
  for (const render::RenderFeature* feature : features_) {
    memory.emplace_back(feature->name(), feature->gpuMemoryBytes());
  }
  return memory;
}

std::vector<std::string> Renderer::pipelineNames() const {
  std::vector<std::string> names = {tonemapper_.pipeline().name()};
  if (sky_) names.push_back(sky_->pipeline().name());
  if (terrain_) {
    for (const gfx::Pipeline* pipeline : terrain_->pipelines()) names.push_back(pipeline->name());
  }
  if (sunlight_) names.push_back(sunlight_->pipeline().name());
  if (water_) {
    for (const gfx::Pipeline* pipeline : water_->pipelines()) names.push_back(pipeline->name());
  }
  if (hud_) names.push_back(hud_->pipeline().name());
  for (const render::RenderFeature* feature : features_) {
    std::string name = std::string(feature->name()) + " module";
    const std::vector<std::string> effects = feature->effects();
    for (std::size_t i = 0; i < effects.size(); ++i) name += (i == 0 ? " (" : ", ") + effects[i];
    if (!effects.empty()) name += ")";
    names.push_back(name);
  }
  return names;
}

}  // namespace sample
