#include "recipe_grid.h"

#include <algorithm>
#include <cmath>

namespace hero_clouds {

double GridLayout::voxelCount() const {
  return static_cast<double>(size[0]) * static_cast<double>(size[1]) * static_cast<double>(size[2]);
}

glm::dvec3 GridLayout::voxelCentreMetres(std::uint64_t x, std::uint64_t y, std::uint64_t z) const {
  return originMetres + voxelMetres * glm::dvec3(static_cast<double>(x), static_cast<double>(y),
                                                 static_cast<double>(z));
}

BoxMetres recipeBoundsMetres(const CloudRecipe& recipe) {
  BoxMetres box = boundsMetres(recipe.primitives.at(0).shape);
  for (const CloudPrimitive& primitive : recipe.primitives) {
    const BoxMetres b = boundsMetres(primitive.shape);
    box.minMetres = glm::min(box.minMetres, b.minMetres);
    box.maxMetres = glm::max(box.maxMetres, b.maxMetres);
  }
  return box;
}

double gridMarginMetres(const CloudRecipe& recipe) {
  return recipe.blendMetres + 2.0 * recipe.voxelMetres;
}

GridLayout planRecipeGrid(const CloudRecipe& recipe) {
  const BoxMetres box = recipeBoundsMetres(recipe);
  const double margin = gridMarginMetres(recipe);
  const glm::dvec3 extent = box.maxMetres - box.minMetres + 2.0 * margin;
  const glm::dvec3 centre = 0.5 * (box.minMetres + box.maxMetres);
  GridLayout grid;
  grid.voxelMetres = recipe.voxelMetres;
  for (glm::length_t axis = 0; axis < 3; ++axis) {
    // Centres i = 0 .. n - 1 span (n - 1) voxels, which must reach across the whole extent.
    const double spans = std::ceil(extent[axis] / recipe.voxelMetres);
    const auto n = static_cast<std::uint64_t>(spans) + 1;
    grid.size[static_cast<std::size_t>(axis)] = n;
    grid.originMetres[axis] = centre[axis] - 0.5 * static_cast<double>(n - 1) * recipe.voxelMetres;
  }
  return grid;
}

}  // namespace hero_clouds
