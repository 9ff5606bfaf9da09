#include "sample_runs.h"

#include <sys/wait.h>

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

std::string scene(const char* name) {
  return std::string(SAMPLE_TEST_DIR) + "/scenes/" + name;
}

std::string shippedSceneText(const char* name) {
  std::ifstream in(std::filesystem::path(SAMPLE_ASSET_DIR) / "scenes" / name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace sample_tests
