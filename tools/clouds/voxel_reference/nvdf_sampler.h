#pragma once
// An NVDF (clouds/nvdf.h) read back as continuous fields, in double precision: the CPU
// reference's view of a hero cloud. Trilinear between voxel centres, as the GPU filters; the
// profile and density read 0 beyond the outermost voxels (clear air), the signed distance
// clamps to the edge.
#include <clouds/nvdf.h>

#include <glm/glm.hpp>

namespace clouds::reference {

class NvdfSampler {
 public:
  explicit NvdfSampler(const NvdfVolume& volume);

  // Fields at a point of the cloud's frame (metres).
  double profile(glm::dvec3 positionMetres) const;
  // One field channel, filtered (0 beyond the grid).
  double field(glm::dvec3 positionMetres, NvdfChannel channel) const;
  // profile x density scale x densityMultiplier, each field filtered on its own as the GPU's
  // texture does: the density the noise erodes (with erosion off, the source grid's density).
  double density(glm::dvec3 positionMetres) const;
  double signedDistanceMetres(glm::dvec3 positionMetres) const;

  // The voxel lattice: index coordinates (voxel centres at integers) of a point.
  glm::dvec3 toIndex(glm::dvec3 positionMetres) const;
  const NvdfVolume& volume() const { return volume_; }

 private:
  // Trilinear blend of `value(voxel)` around index coordinate `c` (`value` decides what a corner
  // outside the grid reads).
  template <typename Value>
  double trilinear(glm::dvec3 c, Value value) const;

  const NvdfVolume& volume_;
};

}  // namespace clouds::reference
