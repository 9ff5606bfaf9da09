#pragma once
// Turning a dense voxel grid into an NVDF (clouds/nvdf.h): what the authoring tools
// (assets_src/hero_clouds) and the OpenVDB import (clouds::vdb) share, and what a host that
// makes its own clouds calls. CPU only; no Vulkan.
#include "clouds/nvdf.h"

#include <optional>
#include <vector>

namespace clouds {

// A cloud as dense voxels in its own frame (metres, y up), voxel (0, 0, 0)'s centre at
// originMetres, x fastest, then y, then z.
struct VoxelDensityGrid {
  glm::uvec3 size{0u};
  float voxelMetres = 0.0f;
  glm::vec3 originMetres{0.0f};
  // The source's density (any unit, >= 0, finite): becomes the dimensional profile, scaled so
  // the largest value is 1 (NvdfVolume::densityMultiplier keeps the scale).
  std::vector<float> density;
  // Optional per-voxel fields in [0, 1]; empty: every voxel takes the default below.
  std::vector<float> detailType;
  std::vector<float> densityScale;
};

struct NvdfBuildOptions {
  float defaultDetailType = 0.5f;
  float defaultDensityScale = 1.0f;
  // Signed distances are kept up to this many voxels from the surface (the longest jump the
  // march can take at once; beyond, it jumps this far and asks again).
  float sdfRangeVoxels = 64.0f;
};

// The NVDF of a grid: the profile (density over its largest value, unorm8 rounded to nearest),
// the given or default detail type and density scale, and a signed distance field exact to the
// voxel lattice (a Euclidean distance transform of the voxels with cloud), made conservative
// for trilinear sampling: wherever the filtered distance reads d > 0, the filtered profile is 0
// within d. On bad input (sizes, non-finite or negative values, an empty grid): nullopt and
// ErrorCode::InvalidAsset naming the field.
std::optional<NvdfVolume> buildNvdf(const VoxelDensityGrid& grid, const NvdfBuildOptions& options,
                                    Error* error);

// The Euclidean distance (in voxels) from each voxel centre to the nearest voxel whose
// `inside` flag is set (x fastest); +infinity everywhere when none is. Exact (Felzenszwalb &
// Huttenlocher's separable transform of squared distances), linear in the voxel count.
std::vector<float> distanceToNearest(const std::vector<bool>& inside, glm::uvec3 size);

}  // namespace clouds
