#pragma once
// Hero clouds from OpenVDB files: a float grid (the one named "density", else the first float
// grid, or the one asked for), its world units taken as metres, made into the module's NVDF.
// Errors never throw: nullopt and clouds::Error (InvalidAsset) naming the file and what is wrong.
#include "clouds/nvdf_build.h"

#include <filesystem>
#include <string>
#include <vector>

namespace clouds {

struct VdbImportOptions {
  std::string
      gridName;  // empty: "density" if the file has a float grid of that name, else the first
  NvdfBuildOptions build;  // detail type and density scale for every voxel, SDF range
};

// What an import found and did, for the tool to print.
struct VdbImportReport {
  std::string gridName;
  std::size_t activeVoxels = 0;
  std::size_t nonFiniteVoxels = 0;    // NaN or infinite values, read as 0
  std::size_t negativeVoxels = 0;     // values below 0, read as 0
  std::vector<std::string> warnings;  // one line each, naming the file
};

// The active voxels of the grid as a dense grid (one voxel of clear air around them, so the
// cloud fades out inside its box as OpenVDB's background does).
std::optional<VoxelDensityGrid> readVdbDensity(const std::filesystem::path& file,
                                               const VdbImportOptions& options,
                                               VdbImportReport* report, Error* error);

// readVdbDensity() then buildNvdf().
std::optional<NvdfVolume> importVdb(const std::filesystem::path& file,
                                    const VdbImportOptions& options, VdbImportReport* report,
                                    Error* error);

}  // namespace clouds
