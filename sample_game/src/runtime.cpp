#include "runtime.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_renderer.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/ecs/app.h"
#include "engine/ecs/frame_time.h"
#include "engine/gfx/device.h"
#include "engine/gfx/instance.h"
#include "engine/platform/input.h"
#include "engine/platform/window.h"
#include "engine/render/present_target.h"
#include "game/game_components.h"
#include "game/input_script.h"
#include "render/renderer.h"
#include "scene/scene_description.h"
#include "scene/scene_loader.h"

namespace sample {
namespace {

using namespace engine;

std::filesystem::path frameStem(const std::filesystem::path& dir, const char* prefix,
                                std::uint64_t frame) {
  char name[48];
  std::snprintf(name, sizeof(name), "%s_%04llu", prefix, static_cast<unsigned long long>(frame));
  return dir / name;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out;
}

}  // namespace

int run(Options options) {
  const bool windowed = !options.headless && platform::Window::displayAvailable();
  if (!options.headless && !windowed && !options.describe) {
    log::info("no display found (DISPLAY/WAYLAND_DISPLAY unset): running headless");
    if (options.frames == 0) options.frames = 5;
    if (!options.captureDir) options.captureDir = "out";
  }
  if (options.scene.empty()) options.scene = std::filesystem::path(CLOUDSCAPE_ASSET_SOURCE_DIR) / "scenes/default.json";
  SceneDescription scene = loadSceneDescription(options.scene);
  if (options.cloudQuality) scene.camera.cloudQuality = *options.cloudQuality;
  std::optional<InputScript> script;
  if (options.script) script = InputScript::load(*options.script);
  if (!windowed && options.frames == 0) {
    options.frames = script ? static_cast<std::uint32_t>(script->lastFrame() + 1) : 1;
  }
  if (options.describe) options.frames = 1;

  // Everything data-driven is loaded and checked before any window or device exists.
  ecs::App app;
  populateScene(app, scene, CLOUDSCAPE_DEFAULT_TERRAIN, options.terrain);

  std::unique_ptr<platform::Window> window;
  gfx::InstanceDesc instanceDesc;
  instanceDesc.appName = "cloudscape sample";
  instanceDesc.validation = options.validation || gfx::validationRequestedByEnvironment();
  if (windowed) {
    window = std::make_unique<platform::Window>(
        platform::WindowDesc{"cloudscape: " + scene.name, options.width, options.height});
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
      target = std::make_unique<render::OffscreenTarget>(device, VkExtent2D{options.width, options.height});
    }

    RendererOptions rendererOptions;
    rendererOptions.maxExtent = {std::max(options.width, 3840u), std::max(options.height, 2160u)};
    rendererOptions.captureDirectory = options.captureDir.value_or("out");
    rendererOptions.hud = windowed && options.hud;
    Renderer renderer(device, *target, app.world(), rendererOptions);
    app.scheduler().add(ecs::Phase::Render, "render frame",
                        [&renderer](ecs::World& world) { renderer.renderFrame(world); });

    ecs::World& world = app.world();
    auto& time = world.ctx().get<ecs::FrameTime>();
    auto& input = world.ctx().get<platform::InputState>();
    auto& capture = world.ctx().get<CaptureRequest>();
    auto& exit = world.ctx().get<ExitRequest>();
    platform::InputState scriptInput;  // the script's "keyboard": keys stay down until released
    auto last = std::chrono::steady_clock::now();
    auto measureStart = last;
    std::uint64_t measuredFrames = 0;
    constexpr std::uint64_t kWarmUpFrames = 3;  // noise generation and JIT happen first
    std::uint64_t screenshot = 0;
    for (std::uint64_t frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
      if (window) {
        window->pollEvents();
        if (window->shouldClose() || window->input().wasPressed(platform::Key::Escape)) break;
        swapchainTarget->resize(window->framebufferExtent());
        if (window->minimized()) std::this_thread::sleep_for(std::chrono::milliseconds(16));
        if (window->input().wasPressed(platform::Key::M)) {
          window->setMouseCaptured(!window->input().mouseCaptured);
        }
        input = window->input();
        if (input.wasPressed(platform::Key::F12)) {
          capture.stem = frameStem("screenshots", "screenshot", screenshot++);
        }
      } else {
        scriptInput.beginFrame();
        if (script) script->apply(frame, scriptInput, world);
        input = scriptInput;
      }
      const auto now = std::chrono::steady_clock::now();
      const double measured = std::chrono::duration<double>(now - last).count();
      last = now;
      const double dt = options.fixedDtSeconds > 0.0 ? options.fixedDtSeconds
                                                     : (frame == 0 ? 0.0 : std::min(measured, 0.25));
      time = frame == 0 ? ecs::FrameTime{dt, 0.0, 0} : time.next(dt);
      const bool lastFrame = options.frames != 0 && frame + 1 == options.frames;
      if (options.captureDir && (options.captureEveryFrame || (lastFrame && !script))) {
        capture.stem = frameStem(*options.captureDir, "frame", frame);
      }
      app.runFrame();
      if (frame + 1 == kWarmUpFrames) measureStart = std::chrono::steady_clock::now();
      if (frame + 1 > kWarmUpFrames) ++measuredFrames;
      if (exit.requested) break;
    }
    renderer.finish();
    if (measuredFrames > 0) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - measureStart).count();
      char line[160];
      std::snprintf(line, sizeof(line),
                    "frame rate: %.2f fps (%.1f ms per frame) over %llu frames after %llu warm-up",
                    double(measuredFrames) / seconds, seconds * 1000.0 / double(measuredFrames),
                    static_cast<unsigned long long>(measuredFrames),
                    static_cast<unsigned long long>(kWarmUpFrames));
      log::info(line);
    }
    if (options.describe) {
      std::printf("{\"scene\": \"%s\", \"passes\": [%s], \"pipelines\": [%s], \"modules\": [%s]}\n",
                  scene.name.c_str(), joined(renderer.passNames()).c_str(),
                  joined(renderer.pipelineNames()).c_str(),
                  joined([&] {
                    std::vector<std::string> modules;
                    for (auto m : app.installedModules()) modules.emplace_back(m);
                    return modules;
                  }()).c_str());
    } else {
      std::string passes;
      for (const auto& name : renderer.passNames()) passes += (passes.empty() ? "" : ", ") + name;
      log::info("frame graph passes: " + passes);
      std::string timings;
      for (const auto& scope : renderer.lastGpuTimings()) {
        char entry[96];
        std::snprintf(entry, sizeof(entry), "%s%s %.2f ms", timings.empty() ? "" : ", ", scope.name,
                      scope.milliseconds);
        timings += entry;
      }
      log::info("GPU time of the last frame: " + timings);
      const auto* clouds = world.ctx().tryGet<clouds::ecs::CloudRendererRef>();
      if (clouds != nullptr && clouds->renderer != nullptr) {
        const ::clouds::FrameReport r = clouds->renderer->context().lastFrameReport();
        log::info("clouds, last frame: trace " + std::to_string(r.traceExtent.width) + "x" +
                  std::to_string(r.traceExtent.height) + ", 1 in " +
                  std::to_string(r.tileSize * r.tileSize) + " pixels marched, " +
                  (r.historyUsed ? std::string("history reprojected")
                                 : "no history: " + std::string(r.resetReason)));
        std::string cloudPasses;
        for (const auto& p : clouds->renderer->context().passTimings(time.frameIndex)) {
          char entry[96];
          std::snprintf(entry, sizeof(entry), "%s%s %.2f ms", cloudPasses.empty() ? "" : ", ",
                        p.name, p.milliseconds);
          cloudPasses += entry;
        }
        if (!cloudPasses.empty()) log::info("clouds passes, last frame: " + cloudPasses);
      }
    }
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
