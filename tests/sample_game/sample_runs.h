#pragma once
// Running the sample binary from a test, as a user would: its exit code, what it prints, fresh
// output folders, and the test and shipped scenes' paths.
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"

namespace sample_tests {

// The sample's exit code (-1 when it did not exit normally) with `arguments`.
int runSample(const std::string& arguments);
// What the sample prints where `redirection` sends it to the pipe (e.g. "2>/dev/null": its
// stdout; "2>&1 >/dev/null": its stderr).
std::string runSampleCapturing(const std::string& arguments, const char* redirection);
// Its stdout (stderr discarded), and its stderr (stdout discarded).
std::string runSampleOutput(const std::string& arguments);
std::string runSampleErrors(const std::string& arguments);
// An empty folder of that name under the system's temporary folder (not created).
std::filesystem::path freshDir(const char* name);
// The scene `sceneJson` written to `dir`/scene.json (an existing folder; the files it names
// relative to it beside it) and run headless under validation, `frames` frames at a fixed
// 0.05 s step, `width` x `height`, without the HUD: its last frame (HDR), captured in `dir`/out.
engine::assets::ImageRgba32f renderLastFrame(const std::filesystem::path& dir,
                                             const std::string& sceneJson, unsigned frames,
                                             unsigned width, unsigned height);
// A test scene's path (tests/sample_game/scenes/<name>).
std::string scene(const char* name);
// The text of a shipped scene (assets_src/scenes/<name>), for a test to edit.
std::string shippedSceneText(const char* name);

}  // namespace sample_tests
