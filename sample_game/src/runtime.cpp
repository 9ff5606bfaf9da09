#include "runtime.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "camera_controls.h"
#include "components.h"
#include "engine/core/log.h"
#include "engine/ecs/app.h"
#include "engine/ecs/frame_time.h"
#include "engine/gfx/device.h"
#include "engine/gfx/instance.h"
#include "engine/platform/input.h"
#include "engine/platform/window.h"
#include "engine/render/present_target.h"
#include "renderer.h"

namespace sample {
namespace {

using namespace engine;

char frameStemBuffer[32];
std::filesystem::path frameStem(const std::filesystem::path& dir, std::uint64_t frame) {
  std::snprintf(frameStemBuffer, sizeof(frameStemBuffer), "frame_%04llu",
                static_cast<unsigned long long>(frame));
  return dir / frameStemBuffer;
}

void populateWorld(ecs::World& world) {
  world.ctx().emplace<ecs::FrameTime>();
  world.ctx().emplace<platform::InputState>();
  world.ctx().emplace<CaptureRequest>();
  const ecs::Entity player = world.create();
  FlightCamera camera;
  camera.pitchRadians = 0.05;
  world.emplace<FlightCamera>(player, camera);
  const ecs::Entity sun = world.create();
  world.emplace<SunLight>(sun, SunLight{});
}

}  // namespace

int run(Options options) {
  const bool windowed = !options.headless && platform::Window::displayAvailable();
  if (!options.headless && !windowed) {
    log::info("no display found (DISPLAY/WAYLAND_DISPLAY unset): running headless");
    if (options.frames == 0) options.frames = 5;
    if (!options.captureDir) options.captureDir = "out";
  }
  if (!windowed && options.frames == 0) options.frames = 1;

  std::unique_ptr<platform::Window> window;
  gfx::InstanceDesc instanceDesc;
  instanceDesc.appName = "cloudscape sample";
  instanceDesc.validation = options.validation || gfx::validationRequestedByEnvironment();
  if (windowed) {
    window = std::make_unique<platform::Window>(
        platform::WindowDesc{"cloudscape", options.width, options.height});
    instanceDesc.extensions = window->requiredInstanceExtensions();
  }
  gfx::Instance instance(instanceDesc);
  VkSurfaceKHR surface = window ? window->createSurface(instance.vk()) : VK_NULL_HANDLE;

  int exitCode = 0;
  {
    gfx::Device device(instance, gfx::DeviceDesc{surface, options.device});
    std::unique_ptr<render::PresentTarget> target;
    render::SwapchainTarget* swapchainTarget = nullptr;
    if (window) {
      auto swapchain = std::make_unique<render::SwapchainTarget>(device, surface, options.vsync);
      swapchainTarget = swapchain.get();
      target = std::move(swapchain);
    } else {
      target = std::make_unique<render::OffscreenTarget>(
          device, VkExtent2D{options.width, options.height});
    }

    ecs::App app;
    populateWorld(app.world());
    installCameraControls(app.scheduler());
    Renderer renderer(device, *target, VkExtent2D{std::max(options.width, 3840u),
                                                  std::max(options.height, 2160u)});
    app.scheduler().add(ecs::Phase::Render, "render frame",
                        [&renderer](ecs::World& world) { renderer.renderFrame(world); });

    auto& time = app.world().ctx().get<ecs::FrameTime>();
    auto& input = app.world().ctx().get<platform::InputState>();
    auto& capture = app.world().ctx().get<CaptureRequest>();
    auto last = std::chrono::steady_clock::now();
    std::uint64_t screenshot = 0;
    for (std::uint64_t frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
      if (window) {
        window->pollEvents();
        if (window->shouldClose() || window->input().wasPressed(platform::Key::Escape)) break;
        swapchainTarget->resize(window->framebufferExtent());
        if (window->minimized()) {
          std::this_thread::sleep_for(std::chrono::milliseconds(16));
        }
        input = window->input();
        if (input.wasPressed(platform::Key::F12)) {
          capture.stem = frameStem("screenshots", screenshot++);
        }
      }
      const auto now = std::chrono::steady_clock::now();
      const double measured = std::chrono::duration<double>(now - last).count();
      last = now;
      const double dt = options.fixedDtSeconds > 0.0 ? options.fixedDtSeconds
                                                     : (frame == 0 ? 0.0 : measured);
      time = frame == 0 ? ecs::FrameTime{dt, 0.0, 0} : time.next(dt);
      const bool lastFrame = options.frames != 0 && frame + 1 == options.frames;
      if (options.captureDir && (options.captureEveryFrame || lastFrame)) {
        capture.stem = frameStem(*options.captureDir, frame);
      }
      app.runFrame();
    }
    renderer.finish();
    std::string passes;
    for (const char* name : renderer.passNames()) passes += std::string(passes.empty() ? "" : ", ") + name;
    log::info("frame graph passes: " + passes);
    if (options.captureDir) {
      std::printf("captured frames are in %s\n",
                  std::filesystem::absolute(*options.captureDir).string().c_str());
    }
  }
  if (window) window->destroySurface();
  if (instance.validationEnabled() && instance.validationMessageCount() > 0) {
    log::error(std::to_string(instance.validationMessageCount()) +
               " Vulkan validation message(s): failing the run");
    exitCode = 3;
  }
  return exitCode;
}

}  // namespace sample
