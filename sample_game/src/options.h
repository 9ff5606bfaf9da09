#pragma once
// The sample's command line.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "clouds/clouds.h"

namespace sample {

// How a window's frames reach the screen.
enum class PresentPath {
  Automatic,     // shared memory for a software device on a local X server, else the swapchain
  Swapchain,     // Vulkan's swapchain (the WSI)
  SharedMemory,  // read back and put through MIT-SHM (engine/render/shm_window_target.h)
};

struct Options {
  bool headless = false;                            // render offscreen, never touch GLFW
  std::uint32_t frames = 0;                         // frames to render; 0 = until the window closes
  std::optional<std::filesystem::path> captureDir;  // write PNG + EXR captures here
  bool captureEveryFrame = false;                   // every frame instead of only the last
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  // Seconds the simulation steps each frame; 0 holds the clock still (wind, weather, lightning,
  // time of day and flight all pause while frames keep rendering); none: the measured frame time.
  std::optional<double> fixedDtSeconds;
  double startSeconds = 0.0;  // the simulation clock at the first frame (uptime), seconds
  bool validation = false;    // Vulkan validation layers (also CLOUDSCAPE_VALIDATION=1)
  std::string device;         // "cpu", "gpu" or a device-name substring
  bool vsync = true;
  PresentPath present = PresentPath::Automatic;
  std::filesystem::path scene;                     // scene JSON; empty: the default scene
  std::optional<std::filesystem::path> terrain;    // fly over this glTF instead of the scene's
  std::optional<std::filesystem::path> heroCloud;  // a user's cloud (.vdb, .nvdf), ahead
  std::optional<std::filesystem::path> script;     // frame-indexed input and events (headless)
  bool describe = false;        // print the frame graph's passes and pipelines, exit
  bool hud = true;              // on-screen help and fps in windowed runs
  bool hudHeadless = false;     // the HUD (and its panel, F2) in headless runs' frames too
  bool hudAsTriangles = false;  // the HUD's backgrounds drawn, not cleared (hud_draw_plan.h)
  std::optional<clouds::Quality> cloudQuality;       // overrides the scene camera's preset
  std::optional<double> frameTargetMilliseconds;     // the governor's target; 0: no governor
  std::optional<std::filesystem::path> soakReport;   // resource series of a long run (CSV)
  std::optional<std::filesystem::path> frameSeries;  // every frame's times and preset (CSV)
  // Where the settings panel saves the scene; given, the run also saves it when it ends.
  std::optional<std::filesystem::path> saveScene;
};

// Parses argv. Returns the options, or an exit code when parsing ended the run (--help, or an
// error already printed with the offending option and value).
struct ParseResult {
  std::optional<Options> options;
  int exitCode = 0;
};
ParseResult parseOptions(int argc, char** argv);

}  // namespace sample
