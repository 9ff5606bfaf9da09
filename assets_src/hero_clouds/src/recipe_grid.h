#pragma once
// Where a recipe's voxels lie: the box of its primitives grown by a margin, cut into voxels of
// voxelMetres. Shared by the recipe reader (which refuses grids beyond the NVDF limits) and
// the voxeliser.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "cloud_recipe.h"
#include "primitive_distance.h"

namespace hero_clouds {

struct GridLayout {
  // Voxels along x, y, z. 64-bit: a rejected recipe may ask for far more than any grid holds.
  std::array<std::uint64_t, 3> size{0, 0, 0};
  glm::dvec3 originMetres{0.0};  // voxel (0, 0, 0)'s centre
  double voxelMetres = 0.0;

  double voxelCount() const;  // a double, so that it cannot overflow
  glm::dvec3 voxelCentreMetres(std::uint64_t x, std::uint64_t y, std::uint64_t z) const;
};

// The union of the primitives' boxes.
BoxMetres recipeBoundsMetres(const CloudRecipe& recipe);

// Room left around the primitives' box: the smooth union can bulge out of the primitives by
// up to blendMetres / 4, and two more voxels keep trilinear filtering and the distance field's
// edge off the cloud. So no cloud touches the grid's edge.
double gridMarginMetres(const CloudRecipe& recipe);

// The voxel centres cover the box grown by the margin, centred on it.
GridLayout planRecipeGrid(const CloudRecipe& recipe);

}  // namespace hero_clouds
