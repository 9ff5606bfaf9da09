#pragma once
// A long run's resource series (--soak-report FILE): every kSoakInterval frames one CSV row of
// the wall time per frame over the interval, the process's resident host memory, the GPU memory
// the renderer and its modules hold and the pipelines created. A soak test reads it to check
// that nothing grows (tests/sample_game/check_soak.cmake).
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace sample {

class Renderer;

inline constexpr std::uint64_t kSoakInterval = 250;

class SoakReport {
 public:
  // Throws engine::Error naming the file when it cannot be written.
  explicit SoakReport(const std::filesystem::path& file);
  // Call after each frame; writes a row after every kSoakInterval-th.
  void afterFrame(std::uint64_t frame, const Renderer& renderer);

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  std::chrono::steady_clock::time_point intervalStart_;
};

}  // namespace sample
