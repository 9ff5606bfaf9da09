// Dense grid -> NVDF (clouds/nvdf_build.h): the profile, the two art fields, and the signed
// distance field the march jumps by.
#include "clouds/nvdf_build.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace clouds {

namespace {

constexpr float kFar = std::numeric_limits<float>::infinity();
// sqrt(3): the farthest a point can be from the voxel centres its trilinear filter reads.
constexpr double kTrilinearReachVoxels = 1.7320508075688772;

bool fail(Error* error, std::string message) {
  if (error != nullptr) *error = Error{ErrorCode::InvalidAsset, std::move(message)};
  return false;
}

// One line of Felzenszwalb & Huttenlocher's transform: out[q] = min_p (q - p)^2 + f[p], over a
// line of n squared distances (kFar where nothing is near yet). v, z: scratch of n and n + 1:
// the parabolas of the lower envelope and the boundaries between them.
void squaredDistanceLine(const float* f, float* out, int n, int* v, float* z) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kFar) continue;  // an empty cell is no parabola
    const float fq = f[q] + float(q) * float(q);
    float s = -kFar;
    while (k >= 0) {
      const int p = v[k];
      s = (fq - (f[p] + float(p) * float(p))) / (2.0f * float(q - p));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -kFar : s;
    z[k + 1] = kFar;
  }
  if (k < 0) {
    std::fill(out, out + n, kFar);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < float(q)) ++j;
    const float d = float(q - v[j]);
    out[q] = d * d + f[v[j]];
  }
}

// Applies squaredDistanceLine() along one axis of the grid, in place.
void transformAxis(std::vector<float>& grid, glm::uvec3 size, int axis) {
  const std::size_t n = size[axis];
  const glm::uvec3 stride(1u, size.x, size.x * size.y);
  const int a1 = (axis + 1) % 3;
  const int a2 = (axis + 2) % 3;
  std::vector<float> line(n), out(n), z(n + 1);
  std::vector<int> v(n);
  for (unsigned i = 0; i < size[a1]; ++i) {
    for (unsigned j = 0; j < size[a2]; ++j) {
      const std::size_t base = std::size_t(i) * stride[a1] + std::size_t(j) * stride[a2];
      for (std::size_t q = 0; q < n; ++q) line[q] = grid[base + q * stride[axis]];
      squaredDistanceLine(line.data(), out.data(), int(n), v.data(), z.data());
      for (std::size_t q = 0; q < n; ++q) grid[base + q * stride[axis]] = out[q];
    }
  }
}

std::string describe(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Empty when the grid can be built, else "<field>: <reason>".
std::string checkGrid(const VoxelDensityGrid& g, const NvdfBuildOptions& o) {
  for (int a = 0; a < 3; ++a) {
    if (g.size[a] < 1 || g.size[a] > kNvdfMaxSide) {
      return std::string("size.") + "xyz"[a] + ": must be in [1, " + std::to_string(kNvdfMaxSide) +
             "] voxels, got " + std::to_string(g.size[a]);
    }
  }
  const std::uint64_t count = std::uint64_t{g.size.x} * g.size.y * g.size.z;
  if (count > kNvdfMaxVoxels) {
    return "size: " + std::to_string(count) + " voxels, more than the " +
           std::to_string(kNvdfMaxVoxels) + " an NVDF holds";
  }
  if (!(g.voxelMetres >= kNvdfMinVoxelMetres && g.voxelMetres <= kNvdfMaxVoxelMetres)) {
    return "voxelMetres: must be in [0.01, 1000], got " + describe(g.voxelMetres);
  }
  if (g.density.size() != count) {
    return "density: holds " + std::to_string(g.density.size()) + " values for " +
           std::to_string(count) + " voxels";
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (!(g.density[i] >= 0.0f && g.density[i] <= std::numeric_limits<float>::max())) {
      return "density[" + std::to_string(i) + "]: must be finite and >= 0, got " +
             describe(g.density[i]);
    }
  }
  const std::pair<const std::vector<float>*, const char*> optional[2] = {
      {&g.detailType, "detailType"}, {&g.densityScale, "densityScale"}};
  for (const auto& [values, name] : optional) {
    if (values->empty()) continue;
    if (values->size() != count) {
      return std::string(name) + ": holds " + std::to_string(values->size()) + " values for " +
             std::to_string(count) + " voxels (or leave it empty)";
    }
    for (std::size_t i = 0; i < count; ++i) {
      if (!((*values)[i] >= 0.0f && (*values)[i] <= 1.0f)) {
        return std::string(name) + "[" + std::to_string(i) + "]: must be in [0, 1], got " +
               describe((*values)[i]);
      }
    }
  }
  if (!(o.defaultDetailType >= 0.0f && o.defaultDetailType <= 1.0f)) {
    return "options.defaultDetailType: must be in [0, 1], got " + describe(o.defaultDetailType);
  }
  if (!(o.defaultDensityScale >= 0.0f && o.defaultDensityScale <= 1.0f)) {
    return "options.defaultDensityScale: must be in [0, 1], got " + describe(o.defaultDensityScale);
  }
  if (!(o.sdfRangeVoxels >= 1.0f && o.sdfRangeVoxels <= 4096.0f)) {
    return "options.sdfRangeVoxels: must be in [1, 4096], got " + describe(o.sdfRangeVoxels);
  }
  return {};
}

std::uint8_t unorm8(float value) {
  return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// snorm16 of `metres` over `range`, rounded down: the stored distance never exceeds the true one.
std::int16_t conservativeSnorm16(double metres, double range) {
  const double code = std::floor(metres / range * 32767.0);
  return std::int16_t(std::clamp(code, -32767.0, 32767.0));
}

}  // namespace

std::vector<float> distanceToNearest(const std::vector<bool>& inside, glm::uvec3 size) {
  std::vector<float> grid(inside.size());
  for (std::size_t i = 0; i < inside.size(); ++i) grid[i] = inside[i] ? 0.0f : kFar;
  for (int axis = 0; axis < 3; ++axis) transformAxis(grid, size, axis);
  for (float& d : grid) d = d == kFar ? kFar : std::sqrt(d);
  return grid;
}

std::optional<NvdfVolume> buildNvdf(const VoxelDensityGrid& grid, const NvdfBuildOptions& options,
                                    Error* error) {
  if (const std::string problem = checkGrid(grid, options); !problem.empty()) {
    fail(error, "VoxelDensityGrid." + problem);
    return std::nullopt;
  }
  const float largest = *std::max_element(grid.density.begin(), grid.density.end());
  if (!(largest > 0.0f)) {
    fail(error, "VoxelDensityGrid.density: the grid holds no cloud (every value is 0)");
    return std::nullopt;
  }

  NvdfVolume v;
  v.size = grid.size;
  v.voxelMetres = grid.voxelMetres;
  v.originMetres = grid.originMetres;
  v.densityMultiplier = largest;
  v.sdfRangeMetres = options.sdfRangeVoxels * grid.voxelMetres;
  const std::size_t count = v.voxelCount();
  v.fields.resize(count * kNvdfChannels);
  std::vector<bool> cloudy(count);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint8_t* voxel = &v.fields[i * kNvdfChannels];
    voxel[kNvdfProfile] = unorm8(grid.density[i] / largest);
    voxel[kNvdfDetailType] =
        unorm8(grid.detailType.empty() ? options.defaultDetailType : grid.detailType[i]);
    voxel[kNvdfDensityScale] =
        unorm8(grid.densityScale.empty() ? options.defaultDensityScale : grid.densityScale[i]);
    voxel[kNvdfReserved] = 0;
    cloudy[i] = voxel[kNvdfProfile] > 0;
  }

  // Outside: the distance to the nearest cloudy voxel centre, less twice the filter's reach (a
  // filtered distance can read one reach more than the point's own, and a point that close to
  // a cloudy centre may read some of its profile). Inside: minus the distance to clear air.
  std::vector<bool> clear(count);
  for (std::size_t i = 0; i < count; ++i) clear[i] = !cloudy[i];
  const std::vector<float> toCloud = distanceToNearest(cloudy, grid.size);
  const std::vector<float> toClear = distanceToNearest(clear, grid.size);
  const double voxel = grid.voxelMetres;
  const double range = v.sdfRangeMetres;
  v.signedDistance.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double metres = cloudy[i] ? -double(std::min(toClear[i], 1e9f)) * voxel
                                    : (double(toCloud[i]) - 2.0 * kTrilinearReachVoxels) * voxel;
    v.signedDistance[i] = conservativeSnorm16(metres, range);
  }
  return v;
}

}  // namespace clouds
