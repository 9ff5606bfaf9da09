#include "soak_report.h"

#include <unistd.h>

#include <cstdio>

#include "engine/core/error.h"
#include "render/renderer.h"

namespace sample {
namespace {

// Resident set size of this process (KiB), from /proc/self/statm (its second field, in pages).
std::uint64_t residentKib() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return 0;
  unsigned long long size = 0;
  unsigned long long resident = 0;
  const int read = std::fscanf(statm, "%llu %llu", &size, &resident);
  std::fclose(statm);
  if (read != 2) return 0;
  return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) / 1024u;
}

}  // namespace

SoakReport::SoakReport(const std::filesystem::path& file)
    : file_(file), out_(file), intervalStart_(std::chrono::steady_clock::now()) {
  if (!out_) throw engine::Error(file.string() + ": cannot write the soak report");
  out_ << "frame,ms_per_frame,host_resident_kib,gpu_bytes,pipelines\n";
}

void SoakReport::afterFrame(std::uint64_t frame, const Renderer& renderer) {
  if ((frame + 1) % kSoakInterval != 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double msPerFrame =
      std::chrono::duration<double, std::milli>(now - intervalStart_).count() /
      static_cast<double>(kSoakInterval);
  intervalStart_ = now;
  std::uint64_t gpuBytes = 0;
  for (const auto& [name, bytes] : renderer.gpuMemory()) gpuBytes += bytes;
  char row[160];
  std::snprintf(row, sizeof(row), "%llu,%.3f,%llu,%llu,%zu\n",
                static_cast<unsigned long long>(frame + 1), msPerFrame,
                static_cast<unsigned long long>(residentKib()),
                static_cast<unsigned long long>(gpuBytes), renderer.pipelineNames().size());
  out_ << row << std::flush;
  if (!out_) throw engine::Error(file_.string() + ": writing the soak report failed");
}

}  // namespace sample
