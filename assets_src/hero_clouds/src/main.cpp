// hero_cloud_bake: turns a hero cloud's recipe into an NVDF at build time, or describes one.
//   hero_cloud_bake <recipe.cloud.json> <out.nvdf>
//   hero_cloud_bake --info <cloud.nvdf>
// Exit codes: 0 success, 1 bad input (the message on stderr names the file and field), 2 usage.
#include <clouds/nvdf.h>
#include <clouds/nvdf_build.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cloud_recipe.h"
#include "recipe_voxeliser.h"

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

void printUsage(std::FILE* out) {
  std::fputs(
      "usage: hero_cloud_bake <recipe.cloud.json> <out.nvdf>\n"
      "       hero_cloud_bake --info <cloud.nvdf>\n"
      "Bakes a hero cloud recipe into an NVDF (voxel fields + signed distance), or reads one\n"
      "back, checks it and prints its size, GPU memory and bounds.\n",
      out);
}

double mebibytes(std::size_t bytes) {
  return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

// "<label>: 70x117x70 voxels of 20 m, 3.28 MiB on the GPU"
std::string describe(const std::string& label, const clouds::NvdfVolume& volume) {
  char text[256];
  std::snprintf(text, sizeof text, "%s: %ux%ux%u voxels of %g m, %.2f MiB on the GPU",
                label.c_str(), volume.size.x, volume.size.y, volume.size.z,
                static_cast<double>(volume.voxelMetres), mebibytes(volume.deviceBytes()));
  return text;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "hero_cloud_bake: %s\n", message.c_str());
  return kExitFailure;
}

int bake(const std::filesystem::path& recipePath, const std::filesystem::path& outPath) {
  const auto start = std::chrono::steady_clock::now();
  const hero_clouds::CloudRecipe recipe = hero_clouds::loadCloudRecipe(recipePath);
  const clouds::VoxelDensityGrid grid = hero_clouds::voxeliseRecipe(recipe);
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> volume =
      clouds::buildNvdf(grid, clouds::NvdfBuildOptions{}, &error);
  if (!volume) return fail(recipePath.string() + ": " + error.message);
  // The build tree's asset folder may not exist yet on a first build.
  if (outPath.has_parent_path()) std::filesystem::create_directories(outPath.parent_path());
  if (!clouds::writeNvdf(outPath, *volume, &error)) return fail(error.message);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::printf("hero_cloud_bake: %s -> %s in %.2f s\n", describe(recipe.name, *volume).c_str(),
              outPath.string().c_str(), seconds.count());
  return 0;
}

int info(const std::filesystem::path& nvdfPath) {
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> volume = clouds::readNvdf(nvdfPath, &error);
  if (!volume) return fail(error.message);
  const glm::vec3 lo = volume->boundsMinMetres();
  const glm::vec3 hi = volume->boundsMaxMetres();
  // An NVDF holds no name, so the file stands for the cloud.
  std::printf("%s, bounds [%.0f, %.0f, %.0f] to [%.0f, %.0f, %.0f] m\n",
              describe(nvdfPath.filename().string(), *volume).c_str(), static_cast<double>(lo.x),
              static_cast<double>(lo.y), static_cast<double>(lo.z), static_cast<double>(hi.x),
              static_cast<double>(hi.y), static_cast<double>(hi.z));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
      printUsage(stdout);
      return 0;
    }
    if (args.size() == 2 && args[0] == "--info" && !args[1].starts_with("-")) {
      return info(args[1]);
    }
    if (args.size() != 2 || args[0].starts_with("-") || args[1].starts_with("-")) {
      printUsage(stderr);
      return kExitUsage;
    }
    return bake(args[0], args[1]);
  } catch (const std::exception& e) {
    // Recipe errors already name the file and field; anything else (I/O) says what it is.
    return fail(e.what());
  }
}
