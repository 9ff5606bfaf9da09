// clouds_example_vdb: writes an example OpenVDB cloud, the kind of file Houdini or Blender
// export, for trying the sample's --cloud and the module's import: a float grid "density" of
// billowing lumps, `SIZE` metres across in 8 m voxels, its base at the file's origin.
// Usage: clouds_example_vdb OUT.vdb [SIZE (m), default 900]
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: clouds_example_vdb OUT.vdb [SIZE_METRES]\n");
    return 2;
  }
  const double size = argc == 3 ? std::atof(argv[2]) : 900.0;
  if (!(size >= 50.0 && size <= 5000.0)) {
    std::fprintf(stderr, "clouds_example_vdb: SIZE_METRES must be in [50, 5000]\n");
    return 2;
  }
  constexpr double kVoxelMetres = 8.0;
  const int n = int(std::ceil(size / kVoxelMetres));
  openvdb::initialize();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setTransform(openvdb::math::Transform::createLinearTransform(kVoxelMetres));
  openvdb::FloatGrid::Accessor access = grid->getAccessor();
  // A few overlapping lumps on a flat base, each thinning out to its rim.
  const double lumps[][4] = {{0.5, 0.30, 0.5, 0.30},
                             {0.33, 0.45, 0.45, 0.20},
                             {0.62, 0.52, 0.55, 0.22},
                             {0.5, 0.68, 0.48, 0.18},
                             {0.42, 0.25, 0.68, 0.2}};
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double px = (x + 0.5) / n;
        const double py = (y + 0.5) / n;
        const double pz = (z + 0.5) / n;
        double density = 0.0;
        for (const auto& l : lumps) {
          const double d = std::sqrt((px - l[0]) * (px - l[0]) + (py - l[1]) * (py - l[1]) +
                                     (pz - l[2]) * (pz - l[2]));
          density = std::max(density, 1.0 - d / l[3]);
        }
        density *= py > 0.12 ? 1.0 : py / 0.12;  // a flat base
        if (density > 0.0)
          access.setValue(openvdb::Coord(x, y, z), float(std::min(1.0, 2.5 * density)));
      }
    }
  }
  grid->transform().postTranslate(openvdb::Vec3d(-0.5 * size, 0.0, -0.5 * size));
  try {
    openvdb::io::File out(argv[1]);
    out.write({grid});
    out.close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clouds_example_vdb: %s: %s\n", argv[1], e.what());
    return 1;
  }
  std::printf("%s: %d^3 voxels of %g m\n", argv[1], n, kVoxelMetres);
  return 0;
}
