#include "cloud_recipe.h"

#include <clouds/nvdf.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "recipe_grid.h"
#include "recipe_json.h"

namespace hero_clouds {
namespace {

constexpr NumberRange kPositionMetres{-kMaxRecipeMetres, kMaxRecipeMetres};
constexpr NumberRange kLengthMetres{0.0, kMaxRecipeMetres, true};
constexpr NumberRange kUnit{0.0, 1.0};
constexpr NumberRange kVoxelMetres{static_cast<double>(clouds::kNvdfMinVoxelMetres),
                                   static_cast<double>(clouds::kNvdfMaxVoxelMetres)};
// Blends and core depths beyond 10 km would be wider than any hero cloud.
constexpr NumberRange kBlendMetres{0.0, 10000.0};
constexpr NumberRange kCoreDepthMetres{0.0, 10000.0, true};
constexpr std::size_t kMaxNameLength = 100;
constexpr std::size_t kMaxDescriptionLength = 2000;

const char* const kShapeNames = "sphere, ellipsoid, tube or torus";

SpherePrimitive readSphere(const RecipeFields& fields) {
  SpherePrimitive s;
  s.centreMetres = fields.vec3("centreMetres", kPositionMetres);
  s.radiusMetres = fields.number("radiusMetres", kLengthMetres);
  return s;
}

EllipsoidPrimitive readEllipsoid(const RecipeFields& fields) {
  EllipsoidPrimitive e;
  e.centreMetres = fields.vec3("centreMetres", kPositionMetres);
  e.radiiMetres = fields.vec3("radiiMetres", kLengthMetres);
  return e;
}

TubePrimitive readTube(const RecipeFields& fields) {
  TubePrimitive t;
  t.pointsMetres = fields.vec3List("pointsMetres", kPositionMetres, 2, kMaxTubePoints);
  // One radius per point: the count is the points', so a forgotten radius is caught.
  t.radiiMetres = fields.numberList("radiiMetres", kLengthMetres, t.pointsMetres.size());
  return t;
}

TorusPrimitive readTorus(const RecipeFields& fields) {
  TorusPrimitive t;
  t.centreMetres = fields.vec3("centreMetres", kPositionMetres);
  const glm::dvec3 axis = fields.vec3("axis", kPositionMetres);
  // Any length will do, the direction is what counts; only zero has none.
  if (glm::length(axis) < 1e-9) {
    fields.fail("axis", "must not be [0, 0, 0] (it is the direction the ring faces)");
  }
  t.axis = glm::normalize(axis);
  t.majorRadiusMetres = fields.number("majorRadiusMetres", kLengthMetres);
  t.minorRadiusMetres = fields.number("minorRadiusMetres", kLengthMetres);
  return t;
}

CloudPrimitive readPrimitive(const RecipeFields& fields) {
  const std::string shape = fields.string("shape", 32);
  CloudPrimitive primitive;
  std::string keys;
  if (shape == "sphere") {
    primitive.shape = readSphere(fields);
    keys = "centreMetres, radiusMetres";
  } else if (shape == "ellipsoid") {
    primitive.shape = readEllipsoid(fields);
    keys = "centreMetres, radiiMetres";
  } else if (shape == "tube") {
    primitive.shape = readTube(fields);
    keys = "pointsMetres, radiiMetres";
  } else if (shape == "torus") {
    primitive.shape = readTorus(fields);
    keys = "centreMetres, axis, majorRadiusMetres, minorRadiusMetres";
  } else {
    fields.fail("shape", "unknown shape \"" + shape + "\" (expected " + kShapeNames + ")");
  }
  primitive.detailType = fields.number("detailType", kUnit, 0.5);
  primitive.densityScale = fields.number("densityScale", kUnit, 1.0);
  fields.finish("for a " + shape + ": shape, " + keys + ", detailType, densityScale");
  return primitive;
}

// The NVDF limits (clouds/nvdf.h) apply to the grid the recipe makes, which the author sets
// through voxelMetres; so the message names that field and the grid it gives.
void checkGridFits(const CloudRecipe& recipe, const RecipeFields& fields) {
  const GridLayout grid = planRecipeGrid(recipe);
  const std::string dims = std::to_string(grid.size[0]) + " x " + std::to_string(grid.size[1]) +
                           " x " + std::to_string(grid.size[2]);
  const std::string given = formatNumber(recipe.voxelMetres) + " m voxels give " + dims;
  for (const std::uint64_t side : grid.size) {
    if (side > clouds::kNvdfMaxSide) {
      fields.fail("voxelMetres", given + " voxels; a side may have at most " +
                                     std::to_string(clouds::kNvdfMaxSide) +
                                     ": raise voxelMetres or shrink the cloud");
    }
  }
  if (grid.voxelCount() > static_cast<double>(clouds::kNvdfMaxVoxels)) {
    fields.fail("voxelMetres", given + " = " + formatNumber(grid.voxelCount()) +
                                   " voxels, more than " + std::to_string(clouds::kNvdfMaxVoxels) +
                                   ": raise voxelMetres or shrink the cloud");
  }
}

}  // namespace

CloudRecipe parseCloudRecipe(std::string_view text, const std::string& source) {
  const nlohmann::json root = parseRecipeJson(text, source);
  const RecipeFields fields(root, source, "");
  CloudRecipe recipe;
  recipe.name = fields.string("name", kMaxNameLength);
  recipe.description = fields.string("description", kMaxDescriptionLength, "");
  recipe.voxelMetres = fields.number("voxelMetres", kVoxelMetres);
  recipe.blendMetres = fields.number("blendMetres", kBlendMetres);
  recipe.coreDepthMetres = fields.number("coreDepthMetres", kCoreDepthMetres);
  for (const RecipeFields& entry : fields.objects("primitives", 1, kMaxPrimitives)) {
    recipe.primitives.push_back(readPrimitive(entry));
  }
  fields.finish("name, description, voxelMetres, blendMetres, coreDepthMetres, primitives");
  checkGridFits(recipe, fields);
  return recipe;
}

CloudRecipe loadCloudRecipe(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) failAt(file.string(), "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) failAt(file.string(), "", "cannot read the file");
  return parseCloudRecipe(text.str(), file.string());
}

}  // namespace hero_clouds
