// OpenVDB -> dense grid -> NVDF. OpenVDB's conventions: an index coordinate (i, j, k) is a
// voxel's centre, the grid's transform takes it to world space, and voxels that are not active
// hold the background (clear air for a cloud).
#include "clouds/vdb_import.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <sstream>

namespace clouds {

namespace {

bool fail(Error* error, std::string message) {
  if (error != nullptr) *error = Error{ErrorCode::InvalidAsset, std::move(message)};
  return false;
}

// The grid the options ask for, or an explanation of why there is none.
openvdb::FloatGrid::Ptr chooseGrid(const openvdb::GridPtrVec& grids, const std::string& wanted,
                                   std::string* problem) {
  std::ostringstream floatNames;
  openvdb::FloatGrid::Ptr firstFloat;
  std::string densityType;  // the value type of a grid named "density" that is not float
  for (const openvdb::GridBase::Ptr& grid : grids) {
    const bool isFloat = grid->isType<openvdb::FloatGrid>();
    if (!wanted.empty() && grid->getName() == wanted) {
      if (isFloat) return openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
      *problem = "grid \"" + wanted + "\" holds " + grid->valueType() + ", not float";
      return nullptr;
    }
    if (!isFloat) {
      if (grid->getName() == "density") densityType = grid->valueType();
      continue;
    }
    floatNames << (firstFloat ? ", \"" : "\"") << grid->getName() << "\"";
    if (!firstFloat) firstFloat = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
    if (wanted.empty() && grid->getName() == "density") {
      return openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
    }
  }
  if (!wanted.empty()) {
    *problem = "no grid named \"" + wanted +
               "\" (float grids: " + (firstFloat ? floatNames.str() : std::string("none")) + ")";
    return nullptr;
  }
  if (!firstFloat) {
    *problem = densityType.empty()
                   ? "no float grid (a cloud's density is a float grid)"
                   : "grid \"density\" holds " + densityType + ", not float, and no grid does";
  }
  return firstFloat;
}

// The voxel edge (m) of a transform that only scales uniformly and translates, else 0 and why.
double uniformVoxelMetres(const openvdb::math::Transform& transform, std::string* problem) {
  if (!transform.isLinear()) {
    *problem = "transform: not linear (frustum or other non-affine maps are not supported)";
    return 0.0;
  }
  const openvdb::Mat4d m = transform.baseMap()->getAffineMap()->getMat4();
  const double scale = m[0][0];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double expected = i == j ? scale : 0.0;
      if (std::abs(m[i][j] - expected) > 1e-6 * std::abs(scale)) {
        *problem =
            "transform: voxels must be cubes on the world's axes (uniform scale and translation: "
            "no rotation, shear or non-uniform scale); resample the grid in the tool that made it";
        return 0.0;
      }
    }
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    *problem = "transform: the voxel size must be positive and finite";
    return 0.0;
  }
  return scale;
}

// Copies the grid's active values into `dense` (voxel (0, 0, 0) at index `lowest`), reading
// non-finite and negative values as 0 and counting them.
void copyActive(const openvdb::FloatGrid& grid, const openvdb::Coord& lowest,
                VoxelDensityGrid& dense, VdbImportReport& report) {
  const auto put = [&](const openvdb::Coord& c, float value) {
    ++report.activeVoxels;
    if (!std::isfinite(value)) {
      ++report.nonFiniteVoxels;
      return;
    }
    if (value < 0.0f) {
      ++report.negativeVoxels;
      return;
    }
    const openvdb::Coord at = c - lowest;
    const std::size_t index =
        (std::size_t(at.z()) * dense.size.y + std::size_t(at.y())) * dense.size.x +
        std::size_t(at.x());
    dense.density[index] = value;
  };
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    if (it.isVoxelValue()) {
      put(it.getCoord(), *it);
      continue;
    }
    openvdb::CoordBBox tile;
    it.getBoundingBox(tile);
    for (auto c = tile.begin(); c; ++c) put(*c, *it);
  }
}

std::optional<VoxelDensityGrid> readGrid(const openvdb::FloatGrid& grid, const std::string& at,
                                         VdbImportReport& report, Error* error) {
  std::string problem;
  const double voxelMetres = uniformVoxelMetres(grid.transform(), &problem);
  if (voxelMetres == 0.0) {
    fail(error, at + problem);
    return std::nullopt;
  }
  const openvdb::CoordBBox active = grid.evalActiveVoxelBoundingBox();
  if (active.empty()) {
    fail(error, at + "no active voxels (the grid is empty)");
    return std::nullopt;
  }
  // One voxel of clear air on each side.
  const openvdb::Coord lowest = active.min() - openvdb::Coord(1);
  const openvdb::Coord extent = active.dim() + openvdb::Coord(2);
  VoxelDensityGrid dense;
  for (std::size_t a = 0; a < 3; ++a) {
    if (std::int64_t(extent[a]) > std::int64_t(kNvdfMaxSide)) {
      fail(error, at + "size: " + std::to_string(extent[a] - 2) + " active voxels along " +
                      "xyz"[a] + ", more than the " + std::to_string(kNvdfMaxSide - 2) +
                      " a hero cloud holds; resample it coarser");
      return std::nullopt;
    }
    dense.size[int(a)] = unsigned(extent[a]);
  }
  const std::uint64_t count = std::uint64_t{dense.size.x} * dense.size.y * dense.size.z;
  if (count > kNvdfMaxVoxels) {
    fail(error, at + "size: " + std::to_string(count) +
                    " voxels in the active box, more than the " + std::to_string(kNvdfMaxVoxels) +
                    " a hero cloud holds; resample it coarser");
    return std::nullopt;
  }
  dense.voxelMetres = float(voxelMetres);
  const openvdb::Vec3d origin = grid.transform().indexToWorld(lowest);
  dense.originMetres = glm::vec3(float(origin.x()), float(origin.y()), float(origin.z()));
  dense.density.assign(std::size_t(count), 0.0f);
  copyActive(grid, lowest, dense, report);

  if (report.nonFiniteVoxels > 0) {
    report.warnings.push_back(at + std::to_string(report.nonFiniteVoxels) +
                              " NaN or infinite values read as 0");
  }
  if (report.negativeVoxels > 0) {
    report.warnings.push_back(at + std::to_string(report.negativeVoxels) +
                              " negative values read as 0");
  }
  if (const float background = grid.background(); background != 0.0f) {
    std::ostringstream text;
    text << at << "background " << background << " read as 0 (clear air outside the active voxels)";
    report.warnings.push_back(text.str());
  }
  return dense;
}

}  // namespace

std::optional<VoxelDensityGrid> readVdbDensity(const std::filesystem::path& file,
                                               const VdbImportOptions& options,
                                               VdbImportReport* report, Error* error) {
  VdbImportReport scratch;
  VdbImportReport& out = report != nullptr ? *report : scratch;
  out = VdbImportReport{};
  const std::string name = file.string();
  std::error_code code;
  if (!std::filesystem::is_regular_file(file, code)) {
    fail(error, name + ": no such file");
    return std::nullopt;
  }
  openvdb::GridPtrVecPtr grids;
  try {
    openvdb::initialize();
    openvdb::io::File vdb(name);
    vdb.open(false);  // read the grids now, not on demand from a mapped file
    grids = vdb.getGrids();
    vdb.close();
  } catch (const std::exception& e) {
    fail(error, name + ": not a readable OpenVDB file: " + e.what());
    return std::nullopt;
  }
  std::string problem;
  const openvdb::FloatGrid::Ptr grid = chooseGrid(*grids, options.gridName, &problem);
  if (!grid) {
    fail(error, name + ": " + problem);
    return std::nullopt;
  }
  out.gridName = grid->getName();
  return readGrid(*grid, name + ": grid \"" + out.gridName + "\": ", out, error);
}

std::optional<NvdfVolume> importVdb(const std::filesystem::path& file,
                                    const VdbImportOptions& options, VdbImportReport* report,
                                    Error* error) {
  const std::optional<VoxelDensityGrid> grid = readVdbDensity(file, options, report, error);
  if (!grid) return std::nullopt;
  std::optional<NvdfVolume> volume = buildNvdf(*grid, options.build, error);
  if (!volume && error != nullptr) error->message = file.string() + ": " + error->message;
  return volume;
}

}  // namespace clouds
