#include "atmosphere_feature.h"

#include <algorithm>
#include <cstring>

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere/ecs/atmosphere_frame.h"
#include "engine/core/log.h"
#include "engine/ecs/module.h"
#include "engine/render/scene_components.h"

namespace atmosphere::ecs {

using namespace engine::render;

namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

bool sameImages(const atmosphere::Outputs& a, const atmosphere::Outputs& b) {
  return a.environment.image == b.environment.image &&
         a.aerialPerspective.image == b.aerialPerspective.image;
}

bool sameParameters(const atmosphere::Parameters& a, const atmosphere::Parameters& b) {
  return std::memcmp(&a, &b, sizeof(a)) == 0;
}

}  // namespace

AtmosphereFeature::AtmosphereFeature(engine::ecs::World& world, const RenderDevice& device)
    : world_(world), device_(*device.device), framesInFlight_(device.framesInFlight) {
  if (device.hdrFormat != kColorFormat) {
    throw engine::ecs::ModuleUnsupported("the atmosphere draws into an RGBA16F scene colour");
  }
  atmosphere::CreateInfo info;
  engine::render::describeDevice(device_, info);
  info.colorFormat = kColorFormat;
  info.depthFormat = device.depthFormat;
  info.maxRenderExtent = device.maxExtent;
  info.maxFramesInFlight = device.framesInFlight;
  info.reversedZ = true;
  info.skyPassColorFormat = kColorFormat;  // the sky is drawn in the renderer's scene pass
  info.passTimings = true;  // a few timestamps: where its time goes, for HUD and logs
  atmosphere::Error error;
  context_ = atmosphere::Context::create(info, &error);
  if (!context_) {
    throw engine::ecs::ModuleUnsupported("the atmosphere module cannot run on this device: " +
                                         error.message + " (" + errorCodeName(error.code) + ")");
  }
  parameters_ = atmosphereParameters(world_);
  publishParameters();
}

AtmosphereFeature::~AtmosphereFeature() {
  // The module's objects may still be used by frames in flight. A destructor must not throw:
  // a device lost only now is reported and teardown goes on.
  try {
    device_.waitIdle();
  } catch (const engine::Error& error) {
    engine::log::error(std::string("AtmosphereFeature teardown: ") + error.what());
  }
}

void AtmosphereFeature::publishParameters() {
  if (published_ && sameParameters(*published_, parameters_)) return;
  world_.ctx().emplaceOrReplace<GroundAlbedo>(GroundAlbedo{parameters_.groundAlbedo});
  world_.ctx().emplaceOrReplace<SunTransmittance>(
      SunTransmittance{[parameters = parameters_](double altitude, const glm::dvec3& sun) {
        return atmosphere::sunTransmittance(parameters, altitude, sun);
      }});
  published_ = parameters_;
}

void AtmosphereFeature::publishMeasurements(std::uint64_t completedFrame) {
  auto& status = world_.ctx().get<AtmosphereStatus>();
  status.memory = context_->memoryUsage();
  status.passTimings = context_->passTimings(completedFrame);
  const atmosphere::SkyLighting sky = context_->skyLighting(completedFrame);
  if (sky.valid) {
    status.sky = sky;
    world_.ctx().emplaceOrReplace<SkyLight>(skyLightFrom(sky));
  }
}

bool AtmosphereFeature::prepare(VkExtent2D extent, std::uint64_t frameIndex) {
  // The slot about to be reused holds the latest completed frame's measurements.
  if (frameIndex >= framesInFlight_) publishMeasurements(frameIndex - framesInFlight_);
  parameters_ = atmosphereParameters(world_);
  settings_ = atmosphereSettings(world_);
  publishParameters();
  atmosphere::Error error;
  prepared_ = context_->prepare(parameters_, settings_, extent, &error);
  if (!prepared_) {
    reportError(error);
    dispatched_ = false;  // no sky from an earlier frame's dispatch
  }
  // A change rebuilds the graph: with the atmosphere's passes, or without them until prepare()
  // succeeds again.
  return !sameImages(usableOutputs(), imported_);
}

atmosphere::Outputs AtmosphereFeature::usableOutputs() const {
  return prepared_ ? context_->outputs() : atmosphere::Outputs{};
}

void AtmosphereFeature::finish(std::uint64_t lastFrameIndex) {
  publishMeasurements(lastFrameIndex);
}

void AtmosphereFeature::reportError(const atmosphere::Error& error) {
  world_.ctx().get<AtmosphereStatus>().lastError = error.message;
  // Parameters are validated when a scene loads, so this is a bug or the device out of memory:
  // worth seeing once. The frame goes on without the atmosphere's passes; tried again next frame.
  if (!errorLogged_) {
    engine::log::error(error.message + " (" + errorCodeName(error.code) + ")");
  }
  errorLogged_ = true;
}

bool AtmosphereFeature::publishesEntry(std::type_index entry) const {
  return entry == typeid(fxcontracts::ecs::SkyRadiance) ||
         entry == typeid(fxcontracts::ecs::AerialPerspective);
}

bool AtmosphereFeature::readsEntry(std::type_index entry) const {
  return entry == typeid(fxcontracts::ecs::CloudShadow);
}

void AtmosphereFeature::describeHaze(fxcontracts::ecs::AerialPerspective& haze) const {
  haze.slices = imported_.aerialPerspective.extent.depth;
  haze.rangeMetres = imported_.aerialPerspectiveRangeMetres;
  haze.rayleighScatteringPerMetre = parameters_.rayleighScatteringPerMetre;
  haze.mieScatteringPerMetre = parameters_.mieScatteringPerMetre;
  haze.miePhaseG = parameters_.miePhaseG;
}

void AtmosphereFeature::dispatch(
    VkCommandBuffer cmd, VkExtent2D extent, std::uint64_t frameIndex, VkImageView shadowView,
    const fxcontracts::ecs::CloudShadowParameterBlock* shadowParameters) {
  atmosphere::FrameInputs inputs = atmosphereFrameInputs(world_, cmd, extent, frameIndex);
  if (shadowView != VK_NULL_HANDLE && shadowParameters != nullptr) {
    inputs.cloudShadow.view = shadowView;
    inputs.cloudShadow.layout = VK_IMAGE_LAYOUT_GENERAL;
    std::copy(shadowParameters->begin(), shadowParameters->end(),
              std::begin(inputs.cloudShadow.parameters));
  }
  atmosphere::Error error;
  dispatched_ = context_->dispatch(inputs, parameters_, settings_, &error);
  if (dispatched_) {
    world_.ctx().get<AtmosphereStatus>().lastError.clear();
  } else {
    reportError(error);
  }
}

void AtmosphereFeature::drawSkyInScenePass(VkCommandBuffer cmd) {
  if (!dispatched_) return;  // reported; the sky's pixels keep the pass's clear colour
  atmosphere::Error error;
  if (!context_->drawSky(cmd, &error)) reportError(error);
}

SceneTextures AtmosphereFeature::addPassesBeforeScene(FrameGraph& graph,
                                                      const SceneTextures& scene) {
  imported_ = usableOutputs();
  if (imported_.environment.image == VK_NULL_HANDLE) return scene;  // prepare() failed
  // The module keeps its outputs in GENERAL between frames and synchronises its own writes.
  const ResourceState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  auto import = [&](const char* name, const atmosphere::OutputImage& image, VkImageType type) {
    ImportedTexture texture;
    texture.image = image.image;
    texture.view = image.view;
    texture.desc.extent = image.extent;
    texture.desc.format = image.format;
    texture.desc.type = type;
    texture.initial = general;
    texture.final = general;
    return graph.importTexture(name, texture);
  };
  const TextureHandle environment = import("sky radiance", imported_.environment, VK_IMAGE_TYPE_2D);
  const TextureHandle froxels =
      import("aerial perspective", imported_.aerialPerspective, VK_IMAGE_TYPE_3D);

  const auto* cloudShadow = graph.blackboard().find<fxcontracts::ecs::CloudShadow>();
  struct DispatchData {
    TextureHandle environment, froxels, cloudShadow;
  };
  const DispatchData& made = graph.addPass<DispatchData>(
      "atmosphere", PassType::Compute,
      [&](PassBuilder& builder, DispatchData& d) {
        d.environment = builder.write(environment, Access::StorageWrite);
        d.froxels = builder.write(froxels, Access::StorageWrite);
        if (cloudShadow != nullptr) {
          d.cloudShadow = builder.read(cloudShadow->map, Access::SampledReadGeneral);
        }
        builder.sideEffect();  // the sky's measurement, read back by the host
      },
      [this, extent = scene.extent](const DispatchData& d, PassContext& context) {
        // The map's parameters as its pass (ordered before this one) wrote them this frame.
        VkImageView shadowView = VK_NULL_HANDLE;
        const fxcontracts::ecs::CloudShadowParameterBlock* shadowParameters = nullptr;
        if (d.cloudShadow.valid()) {
          shadowView = context.view(d.cloudShadow);
          shadowParameters = &context.blackboard().get<fxcontracts::ecs::CloudShadow>().parameters;
        }
        dispatch(context.cmd(), extent, context.frameIndex(), shadowView, shadowParameters);
        // This frame's parameters (prepare() read them from the world) for the haze's readers.
        describeHaze(context.blackboard().get<fxcontracts::ecs::AerialPerspective>());
      });

  // The sky itself is drawn in the renderer's scene pass, after its geometry, where only the
  // pixels the geometry left empty are shaded (drawSkyInScenePass).
  graph.blackboard().put(fxcontracts::ecs::SkyRadiance{made.environment});
  fxcontracts::ecs::AerialPerspective haze;
  haze.volume = made.froxels;
  describeHaze(haze);
  graph.blackboard().put(haze);
  return scene;
}

SceneTextures AtmosphereFeature::addPasses(FrameGraph& /*graph*/, const SceneTextures& scene) {
  return scene;  // the renderer hazed its geometry with the aerial perspective
}

}  // namespace atmosphere::ecs
