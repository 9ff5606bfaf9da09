#include "renderer.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "components.h"
#include "engine/core/log.h"
#include "engine/ecs/frame_time.h"
#include "engine/render/camera_math.h"

namespace sample {

using namespace engine;

Renderer::Renderer(gfx::Device& device, render::PresentTarget& target, VkExtent2D maxExtent)
    : device_(device),
      target_(target),
      ring_(device),
      tonemapper_(device, kHdrFormat, target.format()),
      firstFrame_(device, kHdrFormat, kDepthFormat),
      clouds_(device, maxExtent, kDepthFormat, /*noiseSeed=*/1, gfx::FrameRing::kFramesInFlight),
      capture_(device) {
  clouds_.settings().coverage = 0.62f;
  const gfx::Pipeline* pipelines[] = {&tonemapper_.pipeline(), &firstFrame_.sky(),
                                      &firstFrame_.pattern()};
  const double ms = gfx::warmUpPipelines(device, pipelines);
  log::info("pipelines warmed up in " + std::to_string(static_cast<int>(ms)) + " ms");
}

Renderer::~Renderer() { finish(); }

void Renderer::rebuildGraph(VkExtent2D extent) {
  graph_ = std::make_unique<render::FrameGraph>(&device_);
  render::FrameGraph& graph = *graph_;
  targetHandle_ = graph.importTexture("present target", target_.describe());

  render::TextureDesc hdrDesc;
  hdrDesc.extent = {extent.width, extent.height, 1};
  hdrDesc.format = kHdrFormat;
  const render::TextureHandle hdr = addSkyGradientPass(graph, firstFrame_, hdrDesc, &params_);
  const SceneTargets scene = addTestPatternPass(graph, firstFrame_, hdr, kDepthFormat, &params_);
  const clouds::ecs::CloudPassOutputs clouds =
      clouds::ecs::addCloudPasses(graph, clouds_, scene.depth, scene.hdr);
  const render::TextureHandle display =
      render::addTonemapPass(graph, tonemapper_, clouds.hdr, targetHandle_, &tonemap_);
  capture_.addToGraph(graph, clouds.hdr, display);
  graph.compile();
  graphExtent_ = extent;
}

void Renderer::updateParams(ecs::World& world, VkExtent2D extent) {
  const auto& time = world.ctx().get<ecs::FrameTime>();
  FlightCamera camera;
  world.view<const FlightCamera>().each([&](const FlightCamera& c) { camera = c; });
  SunLight sun;
  world.view<const SunLight>().each([&](const SunLight& s) { sun = s; });

  const float aspect = static_cast<float>(extent.width) / static_cast<float>(extent.height);
  const glm::vec3 forward = glm::vec3(forwardOf(camera));
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, forward);
  const float tanY = std::tan(camera.verticalFovRadians * 0.5f);
  params_.sky.cameraRight = glm::vec4(right, tanY * aspect);
  params_.sky.cameraUp = glm::vec4(up, tanY);
  params_.sky.cameraForward = glm::vec4(forward, 0.0f);
  params_.sky.sunDirection = glm::vec4(glm::vec3(directionOf(sun)), 20.0f * sun.illuminance);
  params_.sky.extent = {extent.width, extent.height};
  params_.sky.timeSeconds = static_cast<float>(time.elapsedSeconds);

  // The pattern lives near the origin; render it camera-relative like everything else.
  const glm::mat4 view = render::lookTo(glm::vec3(camera.position), forward, {0, 1, 0});
  const glm::mat4 projection =
      render::perspectiveReversedZ(camera.verticalFovRadians, aspect, 0.1f);
  params_.pattern.viewProjection = projection * view;
  params_.pattern.params = glm::vec4(static_cast<float>(time.elapsedSeconds), 0, 0, 0);

  clouds::FrameInputs& in = clouds_.frameInputs();
  in.previousView = in.view;
  in.previousProjection = in.projection;
  in.previousCameraPosition = in.cameraPosition;
  in.view = view;
  in.projection = projection;
  in.cameraPosition = camera.position;
  in.sunDirection = glm::vec3(directionOf(sun));
  in.sunIlluminance = glm::vec3(10.0f, 9.6f, 9.0f) * sun.illuminance;
  in.ambientTop = glm::vec3(0.35f, 0.5f, 0.85f);
  in.ambientBottom = glm::vec3(0.25f, 0.27f, 0.3f);
  in.timeSeconds = time.elapsedSeconds;
  in.reset = time.frameIndex == 0;
}

void Renderer::renderFrame(ecs::World& world) {
  gfx::FrameRing::Frame& frame = ring_.begin();
  if (!target_.acquire(frame.slot)) {
    ring_.submit();  // nothing to draw into (minimized): keep the ring's bookkeeping going
    return;
  }
  const VkExtent2D extent = target_.extent();
  if (!graph_ || extent.width != graphExtent_.width || extent.height != graphExtent_.height) {
    rebuildGraph(extent);
  }
  graph_->updateImportedTexture(targetHandle_, target_.image(), target_.view());
  updateParams(world, extent);

  auto& request = world.ctx().get<CaptureRequest>();
  const bool capturing = request.stem.has_value();
  if (capturing) {
    capture_.arm(*request.stem);
    request.stem.reset();
  }
  graph_->execute(frame);
  ring_.submit(target_.submitWaits(), target_.submitSignals());
  target_.present();
  if (capturing) {
    ring_.drain();
    if (auto png = capture_.writePending()) log::info("captured " + png->string());
  }
}

void Renderer::finish() {
  ring_.drain();
  capture_.writePending();
}

std::vector<const char*> Renderer::passNames() const {
  return graph_ ? graph_->executionOrder() : std::vector<const char*>{};
}

}  // namespace sample
