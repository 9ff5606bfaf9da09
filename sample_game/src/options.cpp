#include "options.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>

namespace sample {

ParseResult parseOptions(int argc, char** argv) {
  Options options;
  CLI::App cli{"cloudscape sample: fly over terrain under Nubis-style volumetric clouds"};
  cli.add_flag("--headless", options.headless,
               "Render offscreen without a window (the default when no display is available)");
  cli.add_option("--frames", options.frames, "Frames to render, then exit (0: until closed)")
      ->check(CLI::Range(0u, 1000000u));
  std::string captureDir;
  cli.add_option("--capture", captureDir, "Write captured frames (PNG + EXR) into this folder");
  cli.add_flag("--capture-all", options.captureEveryFrame,
               "Capture every frame instead of only the last");
  cli.add_option("--width", options.width, "Render width in pixels")->check(CLI::Range(16u, 7680u));
  cli.add_option("--height", options.height, "Render height in pixels")
      ->check(CLI::Range(16u, 4320u));
  // CLI::Range lets NaN through (every comparison with it is false).
  const auto finiteNumber = [](const std::string& value) {
    return std::isfinite(std::strtod(value.c_str(), nullptr))
               ? std::string()
               : "must be a finite number, got " + value;
  };
  double fixedDt = 0.0;
  CLI::Option* fixedDtOption =
      cli.add_option("--fixed-dt", fixedDt,
                     "Fixed simulation step in seconds (deterministic runs; 0 pauses the clock)")
          ->check(CLI::Range(0.0, 3600.0))
          ->check(finiteNumber);
  cli.add_option("--start-time", options.startSeconds,
                 "Simulation clock at the first frame in seconds (1e6: as after 11.6 days)")
      ->check(CLI::Range(0.0, 1e9))
      ->check(finiteNumber);
  cli.add_flag("--validation", options.validation, "Enable Vulkan validation layers");
  cli.add_option("--device", options.device, "Vulkan device: cpu, gpu or a name substring");
  std::string scene;
  cli.add_option("--scene", scene, "Scene JSON (default: assets_src/scenes/default.json)");
  std::string terrain;
  cli.add_option("--terrain", terrain, "Fly over this .gltf/.glb instead of the scene's terrain");
  std::string heroCloud;
  cli.add_option("--cloud", heroCloud,
                 "Place this hero cloud (OpenVDB .vdb, world units as metres, or .nvdf) in front "
                 "of the camera's start");
  std::string script;
  cli.add_option("--script", script,
                 "Frame-indexed input/events script (JSON): a headless run's input, or a "
                 "window's in place of the player's (tests)");
  cli.add_flag("--describe", options.describe,
               "Print the frame graph's passes and the pipelines created, then exit");
  std::string quality;
  cli.add_option("--quality", quality,
                 "Cloud quality preset: low, medium, high, ultra or reference (default: the "
                 "scene's, else medium)")
      ->check([](const std::string& name) {
        clouds::Quality parsed{};
        return clouds::parseQuality(name, &parsed)
                   ? std::string()
                   : "unknown quality '" + name + "' (low, medium, high, ultra, reference)";
      });
  double frameTarget = 0.0;
  CLI::Option* frameTargetOption =
      cli.add_option("--frame-target-ms", frameTarget,
                     "Milliseconds a frame (wall clock, nine frames in ten): a governor picks the "
                     "cloud preset that holds it "
                     "(0: none; default 33.3 in a window, none headless; --quality fixes the "
                     "preset instead)")
          ->check(CLI::Range(0.0, 1e5))
          ->check(finiteNumber);
  std::string soakReport;
  cli.add_option("--soak-report", soakReport,
                 "Write host and GPU memory, pipelines and frame time every 250 frames (CSV)");
  std::string frameSeries;
  cli.add_option("--frame-series", frameSeries,
                 "Write every frame's wall and GPU time and cloud preset (CSV)");
  std::string saveScene;
  cli.add_option("--save-scene", saveScene,
                 "Where the settings panel (F2) saves the scene; given, the scene as it is at "
                 "the end of the run is saved there too (default: edited_scene.json)");
  bool noHud = false;
  cli.add_flag("--no-hud", noHud, "Hide the on-screen help and frame rate");
  cli.add_flag("--hud-headless", options.hudHeadless,
               "Draw the HUD in headless runs too (scripts can press F1 and F2; for captures)");
  cli.add_flag("--hud-as-triangles", options.hudAsTriangles,
               "Draw the HUD's opaque backgrounds as ImGui's triangles, not as clears (tests: "
               "both make the same pixels)");
  bool noVsync = false;
  cli.add_flag("--no-vsync", noVsync, "Present without waiting for vertical blank");
  std::string present = "auto";
  cli.add_option("--present", present,
                 "How a window's frames reach it: swapchain, shm (read back, put through "
                 "MIT-SHM), or auto (shm for a software device on a local X server)")
      ->check(CLI::IsMember({"auto", "swapchain", "shm"}));
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return ParseResult{std::nullopt, cli.exit(e)};
  }
  if (fixedDtOption->count() > 0) options.fixedDtSeconds = fixedDt;
  if (frameTargetOption->count() > 0) options.frameTargetMilliseconds = frameTarget;
  if (!captureDir.empty()) options.captureDir = captureDir;
  if (!scene.empty()) options.scene = scene;
  if (!terrain.empty()) options.terrain = terrain;
  if (!heroCloud.empty()) options.heroCloud = heroCloud;
  if (!script.empty()) options.script = script;
  if (!soakReport.empty()) options.soakReport = soakReport;
  if (!frameSeries.empty()) options.frameSeries = frameSeries;
  if (!saveScene.empty()) options.saveScene = saveScene;
  if (!quality.empty()) {
    clouds::Quality parsed{};
    clouds::parseQuality(quality, &parsed);
    options.cloudQuality = parsed;
  }
  options.vsync = !noVsync;
  options.present = present == "swapchain" ? PresentPath::Swapchain
                    : present == "shm"     ? PresentPath::SharedMemory
                                           : PresentPath::Automatic;
  options.hud = !noHud;
  return ParseResult{options, 0};
}

}  // namespace sample
