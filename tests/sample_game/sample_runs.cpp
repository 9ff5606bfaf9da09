#include "sample_runs.h"

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>

namespace sample_tests {

int runSample(const std::string& arguments) {
  const std::string command = std::string(SAMPLE_GAME_EXE) + " " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string runSampleCapturing(const std::string& arguments, const char* redirection) {
  const std::string command = std::string(SAMPLE_GAME_EXE) + " " + arguments + " " + redirection;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 512> buffer{};
  while (pipe && std::fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr)
    out += buffer.data();
  return out;
}

std::string runSampleOutput(const std::string& arguments) {
  return runSampleCapturing(arguments, "2>/dev/null");
}

std::string runSampleErrors(const std::string& arguments) {
  return runSampleCapturing(arguments, "2>&1 >/dev/null");
}

std::filesystem::path freshDir(const char* name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "cloudscape_sample_tests" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

engine::assets::ImageRgba32f renderLastFrame(const std::filesystem::path& dir,
                                             const std::string& sceneJson, unsigned frames,
                                             unsigned width, unsigned height) {
  const std::filesystem::path file = dir / "scene.json";
  std::ofstream(file) << sceneJson;
  const std::string arguments = "--headless --validation --frames " + std::to_string(frames) +
                                " --fixed-dt 0.05 --width " + std::to_string(width) + " --height " +
                                std::to_string(height) + " --no-hud --scene " + file.string() +
                                " --capture " + (dir / "out").string();
  EXPECT_EQ(runSample(arguments), 0) << arguments;
  char last[32];
  std::snprintf(last, sizeof(last), "frame_%04u.exr", frames - 1);
  return engine::assets::readImage(dir / "out" / last);
}

std::string scene(const char* name) {
  return std::string(SAMPLE_TEST_DIR) + "/scenes/" + name;
}

std::string shippedSceneText(const char* name) {
  std::ifstream in(std::filesystem::path(SAMPLE_ASSET_DIR) / "scenes" / name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace sample_tests
