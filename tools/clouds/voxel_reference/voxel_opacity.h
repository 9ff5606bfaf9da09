#pragma once
// The converged reference of a hero cloud's opacity (1 - transmittance of primary rays,
// absorption only), in double precision: the optical depth along a ray is integrated exactly,
// cell by cell of the voxel lattice (there the filtered density is a polynomial of degree 6 in
// the distance, which 4-point Gauss-Legendre integrates exactly). The camera follows OpenVDB's
// vdb_render so its images can be compared with it.
#include <glm/glm.hpp>
#include <vector>

#include "nvdf_sampler.h"

namespace clouds::reference {

// vdb_render's perspective camera: at `position`, looking at `lookAt` with y up, `fovDegrees`
// the horizontal field of view; pixel (0, 0) at the top left.
struct PinholeCamera {
  glm::dvec3 position{0.0};
  glm::dvec3 lookAt{0.0, 0.0, -1.0};
  double fovDegrees = 44.8;  // vdb_render's default
  glm::uvec2 size{160, 90};

  // The unit direction through the centre of pixel (x, y).
  glm::dvec3 rayDirection(unsigned x, unsigned y) const;
};

// Optical depth (dimensionless) of the ray from `origin` along the unit `direction`, through
// the cloud's density times `extinctionPerMetre`.
double opticalDepth(const NvdfSampler& cloud, glm::dvec3 origin, glm::dvec3 direction,
                    double extinctionPerMetre);

// 1 - exp(-optical depth) per pixel, row 0 at the top.
std::vector<float> opacityImage(const NvdfSampler& cloud, const PinholeCamera& camera,
                                double extinctionPerMetre);

}  // namespace clouds::reference
