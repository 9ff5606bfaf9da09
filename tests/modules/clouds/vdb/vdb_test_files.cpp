#include "vdb_test_files.h"

#include <openvdb/io/File.h>

#include <cmath>

namespace vdb_test {

openvdb::FloatGrid::Ptr floatGrid(const std::string& name, double voxelMetres,
                                  openvdb::Vec3d translation, openvdb::Coord lo, openvdb::Coord hi,
                                  const std::function<float(openvdb::Coord)>& value) {
  openvdb::initialize();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setName(name);
  openvdb::math::Transform::Ptr transform =
      openvdb::math::Transform::createLinearTransform(voxelMetres);
  transform->postTranslate(translation);
  grid->setTransform(transform);
  openvdb::FloatGrid::Accessor access = grid->getAccessor();
  for (auto c = openvdb::CoordBBox(lo, hi).begin(); c; ++c) access.setValueOn(*c, value(*c));
  return grid;
}

void write(const std::filesystem::path& file, const openvdb::GridPtrVec& grids) {
  openvdb::io::File out(file.string());
  out.write(grids);
  out.close();
}

openvdb::FloatGrid::Ptr smokeCloud(int voxels) {
  const double r = 0.5 * voxels;
  return floatGrid("density", 0.5, openvdb::Vec3d(12.0, 150.0, -7.0), openvdb::Coord(0),
                   openvdb::Coord(voxels - 1), [r](openvdb::Coord c) {
                     const double x = c.x() - r + 0.5;
                     const double y = c.y() - r + 0.5;
                     const double z = c.z() - r + 0.5;
                     const double lumps = 1.0 + 0.25 * std::sin(0.7 * x) * std::sin(0.5 * y + 1.0) *
                                                    std::sin(0.6 * z + 2.0);
                     const double rim = 1.0 - std::sqrt(x * x + y * y + z * z) / (0.9 * r * lumps);
                     return float(rim > 0.0 ? 2.0 * std::pow(rim, 0.7) : 0.0);
                   });
}

}  // namespace vdb_test
