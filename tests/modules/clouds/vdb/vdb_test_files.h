#pragma once
// OpenVDB files for the import's tests, written with OpenVDB itself.
#include <openvdb/openvdb.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vdb_test {

// A float grid named `name` with cubic voxels of `voxelMetres`, voxel (0, 0, 0) at `translation`
// (metres), whose voxels in [lo, hi] (index space) are active with value(i, j, k).
openvdb::FloatGrid::Ptr floatGrid(const std::string& name, double voxelMetres,
                                  openvdb::Vec3d translation, openvdb::Coord lo, openvdb::Coord hi,
                                  const std::function<float(openvdb::Coord)>& value);

void write(const std::filesystem::path& file, const openvdb::GridPtrVec& grids);

// A cloud of smoke to render: a lumpy ball of density (noise-modulated, 0 at its rim, all voxels
// of its box active), `voxels` across, voxel 0.5 m, off the origin.
openvdb::FloatGrid::Ptr smokeCloud(int voxels);

}  // namespace vdb_test
