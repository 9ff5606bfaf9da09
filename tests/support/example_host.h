#pragma once
// Runs a module's raw-Vulkan example host (its executable path) as a user would: with its own
// validation on, or under the bare validation layer enabled by the loader (no messenger: the
// layer prints to the output, which is returned for the caller to search).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace test {

inline int exitCodeOf(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// `host --validation arguments`: 0 on success, 3 when validation said anything.
inline int runExampleHost(const std::string& host, const std::string& arguments) {
  const std::string command = host + " --validation " + arguments;
  return exitCodeOf(std::system(command.c_str()));
}

// The host without its own validation, the layer added by the loader; `output` is what it
// and the layer printed.
inline int runExampleHostUnderLayer(const std::string& host, const std::string& arguments,
                                    std::string& output) {
  const std::filesystem::path log = std::filesystem::temp_directory_path() /
                                    (std::filesystem::path(host).filename().string() + ".log");
  const std::string command =
      "env -u CLOUDSCAPE_VALIDATION VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation " + host + " " +
      arguments + " > " + log.string() + " 2>&1";
  const int code = exitCodeOf(std::system(command.c_str()));
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  output = text.str();
  return code;
}

inline std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

}  // namespace test
