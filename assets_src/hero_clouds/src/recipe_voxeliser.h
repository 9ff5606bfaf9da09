#pragma once
// A recipe as the dense voxel grid clouds::buildNvdf() turns into an NVDF.
//
// Shape: each primitive's signed distance (primitive_distance.h), joined by Quilez's polynomial
// smooth minimum of radius blendMetres, applied primitive by primitive in recipe order.
// Profile: saturate(-distance / coreDepthMetres), 0 on the surface and 1 from coreDepthMetres
// inside; buildNvdf() then divides by the largest value (1 unless no voxel is that deep).
// Detail type and density scale: the primitives' values averaged with weights
//   w_i = exp(-(d_i - d_min) / falloff),  falloff = max(blendMetres, voxelMetres),
// so the primitive the point is deepest in (or nearest to) dominates, and values change
// smoothly across a blend instead of stepping where two primitives meet. The falloff never
// drops below a voxel, so a plain union (blendMetres 0) still has no one-voxel seams.
#include <clouds/nvdf_build.h>

#include <glm/glm.hpp>

#include "cloud_recipe.h"

namespace hero_clouds {

struct RecipeSample {
  double signedDistanceMetres = 0.0;  // of the blended union; negative inside
  float profile = 0.0f;               // [0, 1], before buildNvdf()'s normalisation
  float detailType = 0.0f;            // [0, 1]
  float densityScale = 0.0f;          // [0, 1]
};

// The fields at one point of the cloud's frame (metres).
RecipeSample sampleRecipe(const CloudRecipe& recipe, glm::dvec3 pointMetres);

// Quilez's quadratic smooth minimum: min(a, b) less at most blend / 4 where |a - b| < blend;
// the plain minimum for blend 0.
double smoothMinimum(double a, double b, double blend);

// Every voxel centre of planRecipeGrid(recipe) sampled; density is the profile, detailType and
// densityScale are filled. The recipe must have passed parseCloudRecipe()'s checks.
clouds::VoxelDensityGrid voxeliseRecipe(const CloudRecipe& recipe);

}  // namespace hero_clouds
