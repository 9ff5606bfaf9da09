#include "runtime.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <thread>

#include "atmosphere/ecs/atmosphere_components.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/ecs/app.h"
#include "engine/ecs/frame_time.h"
#include "engine/gfx/device.h"
#include "engine/gfx/instance.h"
#include "engine/platform/input.h"
#include "engine/platform/shm_blitter.h"
#include "engine/platform/window.h"
#include "engine/render/present_target.h"
#include "engine/render/render_feature.h"
#include "engine/render/shm_window_target.h"
#include "frame_series.h"
#include "game/game_components.h"
#include "game/input_script.h"
#include "game/live_settings.h"
#include "game/scene_hot_reload.h"
#include "render/renderer.h"
#include "scene/scene_description.h"
#include "scene/scene_loader.h"
#include "soak_report.h"

namespace sample {
namespace {

using namespace engine;

// Everything data-driven, loaded and checked before any window or device exists.
struct RunPlan {
  Options options;
  bool windowed = false;
  SceneDescription scene;
  std::optional<InputScript> script;
  std::optional<LoadedTerrain> terrain;
  LoadedHeroClouds heroClouds;
};

// Named GPU times, one list per name in order of first use.
struct TimingSeries {
  std::vector<std::pair<std::string, std::vector<double>>> milliseconds;

  void add(const std::string& name, double ms) {
    auto it = std::find_if(milliseconds.begin(), milliseconds.end(),
                           [&](const auto& entry) { return entry.first == name; });
    if (it == milliseconds.end()) {
      milliseconds.push_back({name, {}});
      it = std::prev(milliseconds.end());
    }
    it->second.push_back(ms);
  }

  // Each pass's mean over `frames` frames, not its median: a pass that runs every few frames
  // costs its share of every frame.
  std::vector<std::pair<std::string, double>> meansPerFrame(std::uint64_t frames) const {
    std::vector<std::pair<std::string, double>> means;
    for (const auto& [name, times] : milliseconds) {
      means.emplace_back(name, std::accumulate(times.begin(), times.end(), 0.0) /
                                   double(std::max<std::uint64_t>(frames, 1)));
    }
    return means;
  }
};

// What the frame loop measured: the frame rate after the warm-up, every frame-graph pass's GPU
// time in each measured frame (timestamps of the latest completed frame), and the clouds
// module's and the atmosphere module's own passes in the frames that ran them (some run every
// few frames).
struct LoopStats {
  std::uint64_t measuredFrames = 0;
  double measuredSeconds = 0.0;
  TimingSeries passes;
  TimingSeries cloudPasses;
  TimingSeries atmospherePasses;

  void addPassTimes(std::span<const engine::gfx::TimedScope> scopes) {
    for (const auto& scope : scopes) passes.add(scope.name, scope.milliseconds);
  }
  void addCloudPassTimes(std::span<const ::clouds::PassTiming> timings) {
    for (const auto& timing : timings) cloudPasses.add(timing.name, timing.milliseconds);
  }
  void addAtmospherePassTimes(std::span<const ::atmosphere::PassTiming> timings) {
    for (const auto& timing : timings) atmospherePasses.add(timing.name, timing.milliseconds);
  }
};

constexpr std::uint64_t kWarmUpFrames = 3;  // noise generation and shader JIT happen first
// A run without a display renders this many frames and captures the last: the default Medium
// clouds refresh each trace pixel once in 16 frames, so by the 48th every pixel has been
// traced three times and the picture has converged (the 5th was soft and blotchy).
constexpr std::uint64_t kHeadlessPreviewFrames = 48;

// A window's runs are governed to 30 fps unless the scene or the command line says otherwise;
// headless runs (captures, tests) keep their preset, for deterministic frames.
constexpr double kDefaultFrameTargetMilliseconds = 1000.0 / 30.0;

// The frame target the governor holds, none for a fixed preset (--quality, or a target of 0).
std::optional<double> frameTargetFor(const Options& options, const SceneDescription& scene,
                                     bool windowed) {
  // A scene with hand-tuned knobs keeps its preset unless it asks for a governor itself.
  std::optional<double> target = windowed && !options.describe && !scene.camera.cloudKnobs.any()
                                     ? std::optional(kDefaultFrameTargetMilliseconds)
                                     : std::nullopt;
  if (scene.camera.frameTargetMilliseconds) target = scene.camera.frameTargetMilliseconds;
  if (options.frameTargetMilliseconds) target = options.frameTargetMilliseconds;
  if (options.cloudQuality || (target && *target <= 0.0)) return std::nullopt;
  return target;
}

void logFrameBudget(ecs::World& world) {
  const auto* governor = world.ctx().tryGet<clouds::ecs::CloudGovernorStatus>();
  if (governor == nullptr || !governor->active) return;
  char line[192];
  std::snprintf(line, sizeof(line),
                "cloud frame budget: %.1f ms, the governor chose %s (%llu changes; its last "
                "judgement %.1f ms, %s)",
                governor->targetMilliseconds, ::clouds::qualityName(governor->preset),
                static_cast<unsigned long long>(governor->changes), governor->judgedMilliseconds,
                governor->reason);
  log::info(line);
}

RunPlan planRun(Options options) {
  RunPlan plan;
  plan.windowed = !options.headless && platform::Window::displayAvailable();
  if (!options.headless && !plan.windowed && !options.describe) {
    if (options.frames == 0) options.frames = kHeadlessPreviewFrames;
    if (!options.captureDir) options.captureDir = "out";
    log::info("no display found (DISPLAY/WAYLAND_DISPLAY unset): running headless for " +
              std::to_string(options.frames) + " frames and capturing the last into " +
              options.captureDir->string() +
              (options.frames == kHeadlessPreviewFrames
                   ? " (converged: every cloud pixel traced three times)"
                   : ""));
  }
  if (options.scene.empty()) {
    options.scene = std::filesystem::path(CLOUDSCAPE_ASSET_SOURCE_DIR) / "scenes/default.json";
  }
  plan.scene = loadSceneDescription(options.scene);
  if (options.cloudQuality) {
    plan.scene.camera.cloudQuality = *options.cloudQuality;
    plan.scene.camera.cloudKnobs = {};  // the preset as it is
  }
  plan.scene.camera.frameTargetMilliseconds = frameTargetFor(options, plan.scene, plan.windowed);
  if (options.script) plan.script = InputScript::load(*options.script);
  if (!plan.windowed && options.frames == 0) {
    options.frames = plan.script ? static_cast<std::uint32_t>(plan.script->lastFrame() + 1) : 1;
  }
  if (options.describe) options.frames = 1;
  plan.terrain = loadTerrain(plan.scene, CLOUDSCAPE_DEFAULT_TERRAIN, options.terrain);
  // A user's cloud in a scene without clouds: a layer with none of its own to hold it.
  if (options.heroCloud && !plan.scene.clouds) {
    plan.scene.clouds = CloudDescription{};
    plan.scene.clouds->settings.coverage = 0.0f;
  }
  plan.heroClouds = loadHeroClouds(plan.scene, CLOUDSCAPE_HERO_CLOUD_DIR, options.heroCloud);
  plan.options = std::move(options);
  return plan;
}

// The display the run presents to: a window (its swapchain, or shared memory for a software
// device), or an offscreen image.
std::unique_ptr<render::PresentTarget> createPresentTarget(gfx::Device& device,
                                                           platform::Window* window,
                                                           VkSurfaceKHR surface,
                                                           const RunPlan& plan) {
  if (window == nullptr) {
    return std::make_unique<render::OffscreenTarget>(
        device, VkExtent2D{plan.options.width, plan.options.height});
  }
  const PresentPath path = plan.options.present;
  if (path == PresentPath::SharedMemory || (path == PresentPath::Automatic && device.isCpu())) {
    std::string whyNot;
    if (auto blitter = platform::ShmBlitter::create(*window, &whyNot)) {
      log::info("presenting through MIT-SHM (the device is " + device.name() +
                "; no vertical-blank sync, as in Mesa's software present)");
      return std::make_unique<render::ShmWindowTarget>(device, std::move(blitter));
    }
    if (path == PresentPath::SharedMemory) throw Error("--present shm: " + whyNot);
    log::info("presenting through the swapchain: " + whyNot);
  }
  return std::make_unique<render::SwapchainTarget>(device, surface, plan.options.vsync);
}

std::filesystem::path frameStem(const std::filesystem::path& dir, const char* prefix,
                                std::uint64_t frame) {
  char name[48];
  std::snprintf(name, sizeof(name), "%s_%04llu", prefix, static_cast<unsigned long long>(frame));
  return dir / name;
}

// One frame's input: the window's (and its keys that act outside the game), or the script's
// (headless, or a window run with --script).
// Returns false when the window asked to close.
bool gatherInput(ecs::World& world, platform::Window* window, render::PresentTarget& target,
                 const RunPlan& plan, std::uint64_t frame, platform::InputState& scriptInput,
                 std::uint64_t& screenshots) {
  auto& input = world.ctx().get<platform::InputState>();
  if (window != nullptr) {
    window->pollEvents();
    if (window->shouldClose() || window->input().wasPressed(platform::Key::Escape)) return false;
    target.resize(window->framebufferExtent());
    if (window->minimized()) std::this_thread::sleep_for(std::chrono::milliseconds(16));
    if (window->input().wasPressed(platform::Key::M)) {
      window->setMouseCaptured(!window->input().mouseCaptured);
    }
    input = window->input();
    if (plan.script) {
      // A scripted window (the windowed smoke test): the script is the player's hands, over
      // the same swapchain, HUD and present as a player's run.
      scriptInput.beginFrame();
      plan.script->apply(frame, scriptInput, world);
      input = scriptInput;
    }
    if (input.wasPressed(platform::Key::F12)) {
      world.ctx().get<CaptureRequest>().stem =
          frameStem("screenshots", "screenshot", screenshots++);
    }
    return true;
  }
  scriptInput.beginFrame();  // the script's "keyboard": keys stay down until released
  if (plan.script) plan.script->apply(frame, scriptInput, world);
  input = scriptInput;
  return true;
}

LoopStats runFrames(ecs::App& app, const Renderer& renderer, platform::Window* window,
                    render::PresentTarget& target, const RunPlan& plan) {
  ecs::World& world = app.world();
  const Options& options = plan.options;
  auto& time = world.ctx().get<ecs::FrameTime>();
  platform::InputState scriptInput;
  std::uint64_t screenshots = 0;
  auto last = std::chrono::steady_clock::now();
  auto measureStart = last;
  LoopStats stats;
  std::optional<SoakReport> soak;
  if (options.soakReport) soak.emplace(*options.soakReport);
  std::optional<FrameSeries> series;
  if (options.frameSeries) series.emplace(*options.frameSeries);
  for (std::uint64_t frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
    if (!gatherInput(world, window, target, plan, frame, scriptInput, screenshots)) break;
    const auto now = std::chrono::steady_clock::now();
    const double measured = std::chrono::duration<double>(now - last).count();
    last = now;
    const double dt = options.fixedDtSeconds ? *options.fixedDtSeconds
                                             : (frame == 0 ? 0.0 : std::min(measured, 0.25));
    time = frame == 0 ? ecs::FrameTime{dt, options.startSeconds, 0} : time.next(dt);
    if (frame > 0)
      world.ctx().emplaceOrReplace<ecs::WallFrameTime>(measured * 1000.0, frame - 1, true);
    const bool lastFrame = options.frames != 0 && frame + 1 == options.frames;
    if (options.captureDir && (options.captureEveryFrame || (lastFrame && !plan.script))) {
      world.ctx().get<CaptureRequest>().stem = frameStem(*options.captureDir, "frame", frame);
    }
    app.runFrame();
    if (soak) soak->afterFrame(frame, renderer);
    if (series) series->afterFrame(frame, measured * 1000.0, world);
    if (frame + 1 == kWarmUpFrames) measureStart = std::chrono::steady_clock::now();
    if (frame + 1 > kWarmUpFrames) {
      ++stats.measuredFrames;
      stats.addPassTimes(renderer.lastGpuTimings());
      if (const auto* clouds = world.ctx().tryGet<clouds::ecs::CloudStatus>()) {
        stats.addCloudPassTimes(clouds->passTimings);
      }
      if (const auto* air = world.ctx().tryGet<atmosphere::ecs::AtmosphereStatus>()) {
        stats.addAtmospherePassTimes(air->passTimings);
      }
    }
    if (world.ctx().get<ExitRequest>().requested) break;
  }
  stats.measuredSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - measureStart).count();
  return stats;
}

std::string joined(const std::vector<std::string>& names, const char* quote, const char* comma) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : comma) + (quote + n + quote);
  return out;
}

std::string timingList(const std::vector<std::pair<std::string, double>>& timings) {
  std::string out;
  for (const auto& [name, ms] : timings) {
    char entry[96];
    std::snprintf(entry, sizeof(entry), "%s%s %.2f ms", out.empty() ? "" : ", ", name.c_str(), ms);
    out += entry;
  }
  return out;
}

void printDescription(ecs::App& app, const Renderer& renderer, const RunPlan& plan) {
  std::vector<std::string> modules;
  for (auto m : app.installedModules()) modules.emplace_back(m);
  // The weather's schedule, by its states' names, and its regions: a scene without them has
  // none to run.
  std::vector<std::string> weather;
  std::vector<std::string> regions;
  app.world().view<const clouds::ecs::CloudWeather>().each([&](const clouds::ecs::CloudWeather& w) {
    weather = w.keyNames;
    for (const clouds::ecs::RegionalWeather& r : w.regions) regions.push_back(r.name);
  });
  std::printf(
      "{\"scene\": \"%s\", \"passes\": [%s], \"pipelines\": [%s], \"modules\": [%s], "
      "\"shadow casters\": [%s], \"weather\": [%s], \"weather regions\": [%s]}\n",
      plan.scene.name.c_str(), joined(renderer.passNames(), "\"", ", ").c_str(),
      joined(renderer.pipelineNames(), "\"", ", ").c_str(), joined(modules, "\"", ", ").c_str(),
      joined(renderer.shadowCasters(), "\"", ", ").c_str(), joined(weather, "\"", ", ").c_str(),
      joined(regions, "\"", ", ").c_str());
}

// "GPU memory: renderer 12.0 MiB, clouds 15.1 MiB (total 27.1 MiB)".
void logMemory(const Renderer& renderer) {
  std::vector<std::pair<std::string, double>> parts;
  double total = 0.0;
  for (const auto& [name, bytes] : renderer.gpuMemory()) {
    parts.emplace_back(name, double(bytes) / (1024.0 * 1024.0));
    total += parts.back().second;
  }
  std::string line = "GPU memory:";
  for (std::size_t i = 0; i < parts.size(); ++i) {
    char entry[96];
    std::snprintf(entry, sizeof(entry), "%s %s %.2f MiB", i == 0 ? "" : ",", parts[i].first.c_str(),
                  parts[i].second);
    line += entry;
  }
  char sum[48];
  std::snprintf(sum, sizeof(sum), " (total %.2f MiB)", total);
  log::info(line + sum);
}

void logRun(ecs::World& world, const Renderer& renderer, const LoopStats& stats) {
  if (stats.measuredFrames > 0) {
    char line[160];
    std::snprintf(line, sizeof(line),
                  "frame rate: %.2f fps (%.1f ms per frame) over %llu frames after %llu warm-up",
                  double(stats.measuredFrames) / stats.measuredSeconds,
                  stats.measuredSeconds * 1000.0 / double(stats.measuredFrames),
                  static_cast<unsigned long long>(stats.measuredFrames),
                  static_cast<unsigned long long>(kWarmUpFrames));
    log::info(line);
  }
  log::info("frame graph passes: " + joined(renderer.passNames(), "", ", "));
  logMemory(renderer);
  std::vector<std::pair<std::string, double>> gpu;
  for (const auto& scope : renderer.lastGpuTimings())
    gpu.emplace_back(scope.name, scope.milliseconds);
  log::info("GPU time of the last frame: " + timingList(gpu));
  if (!stats.passes.milliseconds.empty()) {
    std::vector<std::pair<std::string, double>> medians;
    double total = 0.0;
    for (auto [name, times] : stats.passes.milliseconds) {
      std::nth_element(times.begin(), times.begin() + std::ptrdiff_t(times.size() / 2),
                       times.end());
      medians.emplace_back(name, times[times.size() / 2]);
      total += medians.back().second;
    }
    char sum[64];
    std::snprintf(sum, sizeof(sum), " (sum %.2f ms)", total);
    log::info("GPU time per pass, median of the measured frames: " + timingList(medians) + sum);
  }
  const auto air = stats.atmospherePasses.meansPerFrame(stats.measuredFrames);
  if (!air.empty()) log::info("atmosphere passes, mean per measured frame: " + timingList(air));
  logFrameBudget(world);
  const auto* clouds = world.ctx().tryGet<clouds::ecs::CloudStatus>();
  if (clouds == nullptr) return;
  const ::clouds::FrameReport& r = clouds->report;
  const std::string marched = r.tileSize == 0
                                  ? std::string("nothing marched")
                                  : "trace " + std::to_string(r.traceExtent.width) + "x" +
                                        std::to_string(r.traceExtent.height) + ", 1 in " +
                                        std::to_string(r.tileSize * r.tileSize) + " pixels marched";
  log::info("clouds, last frame: " + marched + ", " +
            (r.historyUsed ? std::string("history reprojected")
                           : "no history: " + std::string(r.resetReason)));
  std::vector<std::pair<std::string, double>> passes;
  for (const auto& p : clouds->passTimings) passes.emplace_back(p.name, p.milliseconds);
  if (!passes.empty()) log::info("clouds passes, last frame: " + timingList(passes));
  const auto means = stats.cloudPasses.meansPerFrame(stats.measuredFrames);
  if (!means.empty()) {
    log::info("clouds passes, mean per measured frame: " + timingList(means));
  }
  char memory[96];
  std::snprintf(memory, sizeof(memory), "clouds GPU memory: %.1f MiB",
                double(clouds->memory.totalBytes()) / (1024.0 * 1024.0));
  log::info(memory);
}

}  // namespace

int run(Options commandLine) {
  const RunPlan plan = planRun(std::move(commandLine));
  const Options& options = plan.options;

  std::unique_ptr<platform::Window> window;
  gfx::InstanceDesc instanceDesc;
  instanceDesc.appName = "cloudscape sample";
  instanceDesc.validation = options.validation || gfx::validationRequestedByEnvironment();
  if (plan.windowed) {
    window = std::make_unique<platform::Window>(
        platform::WindowDesc{"cloudscape: " + plan.scene.name, options.width, options.height});
    instanceDesc.extensions = window->requiredInstanceExtensions();
  }
  gfx::Instance instance(instanceDesc);
  const platform::Surface surface =
      window ? window->createSurface(instance.vk()) : platform::Surface{};
  {
    gfx::Device device(instance, gfx::DeviceDesc{surface.vk(), options.device});
    const std::unique_ptr<render::PresentTarget> target =
        createPresentTarget(device, window.get(), surface.vk(), plan);

    RendererOptions rendererOptions;
    rendererOptions.maxExtent = {std::max(options.width, 3840u), std::max(options.height, 2160u)};
    rendererOptions.captureDirectory = options.captureDir.value_or("out");
    rendererOptions.hud = (plan.windowed && options.hud) || options.hudHeadless;
    rendererOptions.hudClears = !options.hudAsTriangles;
    // Declared after the device: the modules' GPU objects go before it does.
    ecs::App app;
    app.world().ctx().emplace<render::RenderDevice>(
        render::RenderDevice{&device, Renderer::kHdrFormat, Renderer::kDepthFormat,
                             gfx::FrameRing::kFramesInFlight, rendererOptions.maxExtent});
    populateScene(app, plan.scene, plan.terrain, plan.heroClouds);
    app.world().ctx().emplace<LiveScene>(LiveScene{
        plan.scene, options.saveScene.value_or("edited_scene.json"), {}, {}, {}, plan.scene});
    installSceneHotReload(app.scheduler(), plan.scene);
    Renderer renderer(device, *target, app.world(), rendererOptions);
    app.scheduler().add(ecs::Phase::Render, "render frame",
                        [&renderer](ecs::World& world) { renderer.renderFrame(world); });

    const LoopStats stats = runFrames(app, renderer, window.get(), *target, plan);
    renderer.finish();
    if (options.saveScene && !saveLiveScene(app.world())) return 4;
    if (options.describe) {
      printDescription(app, renderer, plan);
    } else {
      logRun(app.world(), renderer, stats);
    }
    if (options.captureDir) {
      std::printf("captured frames are in %s\n",
                  std::filesystem::absolute(*options.captureDir).string().c_str());
    }
  }
  if (instance.validationEnabled() && instance.validationMessageCount() > 0) {
    log::error(std::to_string(instance.validationMessageCount()) +
               " Vulkan validation message(s): failing the run");
    return 3;
  }
  return 0;
}

}  // namespace sample
