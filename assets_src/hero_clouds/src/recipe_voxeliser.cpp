#include "recipe_voxeliser.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "primitive_distance.h"
#include "recipe_grid.h"

namespace hero_clouds {
namespace {

// sampleRecipe() with the per-primitive distances kept in caller-owned storage, so voxelising
// a million points allocates once.
RecipeSample sampleInto(const CloudRecipe& recipe, glm::dvec3 p, std::span<double> distances) {
  double blended = 0.0;
  double nearest = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < recipe.primitives.size(); ++i) {
    const double d = signedDistanceMetres(recipe.primitives[i].shape, p);
    distances[i] = d;
    blended = i == 0 ? d : smoothMinimum(blended, d, recipe.blendMetres);
    nearest = std::min(nearest, d);
  }
  const double falloff = std::max(recipe.blendMetres, recipe.voxelMetres);
  double weightSum = 0.0;
  double detailType = 0.0;
  double densityScale = 0.0;
  for (std::size_t i = 0; i < recipe.primitives.size(); ++i) {
    const double w = std::exp(-(distances[i] - nearest) / falloff);  // 1 for the nearest
    weightSum += w;
    detailType += w * recipe.primitives[i].detailType;
    densityScale += w * recipe.primitives[i].densityScale;
  }
  RecipeSample sample;
  sample.signedDistanceMetres = blended;
  sample.profile = static_cast<float>(std::clamp(-blended / recipe.coreDepthMetres, 0.0, 1.0));
  sample.detailType = static_cast<float>(std::clamp(detailType / weightSum, 0.0, 1.0));
  sample.densityScale = static_cast<float>(std::clamp(densityScale / weightSum, 0.0, 1.0));
  return sample;
}

}  // namespace

double smoothMinimum(double a, double b, double blend) {
  if (blend <= 0.0) return std::min(a, b);
  const double h = std::max(blend - std::abs(a - b), 0.0) / blend;
  return std::min(a, b) - h * h * blend * 0.25;
}

RecipeSample sampleRecipe(const CloudRecipe& recipe, glm::dvec3 pointMetres) {
  std::vector<double> distances(recipe.primitives.size());
  return sampleInto(recipe, pointMetres, distances);
}

clouds::VoxelDensityGrid voxeliseRecipe(const CloudRecipe& recipe) {
  const GridLayout layout = planRecipeGrid(recipe);
  clouds::VoxelDensityGrid grid;
  // parseCloudRecipe() bounded every side by clouds::kNvdfMaxSide, so these fit.
  grid.size =
      glm::uvec3(static_cast<glm::uint>(layout.size[0]), static_cast<glm::uint>(layout.size[1]),
                 static_cast<glm::uint>(layout.size[2]));
  grid.voxelMetres = static_cast<float>(layout.voxelMetres);
  grid.originMetres = glm::vec3(layout.originMetres);
  const auto count = static_cast<std::size_t>(layout.voxelCount());
  grid.density.resize(count);
  grid.detailType.resize(count);
  grid.densityScale.resize(count);
  std::vector<double> distances(recipe.primitives.size());
  std::size_t index = 0;  // x fastest, then y, then z
  for (std::uint64_t z = 0; z < layout.size[2]; ++z) {
    for (std::uint64_t y = 0; y < layout.size[1]; ++y) {
      for (std::uint64_t x = 0; x < layout.size[0]; ++x, ++index) {
        const RecipeSample s = sampleInto(recipe, layout.voxelCentreMetres(x, y, z), distances);
        grid.density[index] = s.profile;
        grid.detailType[index] = s.detailType;
        grid.densityScale[index] = s.densityScale;
      }
    }
  }
  return grid;
}

}  // namespace hero_clouds
