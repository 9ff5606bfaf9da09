#pragma once
// A hero cloud's recipe: the human-readable *.cloud.json an artist writes (schema: ../README.md),
// a smooth union of a few primitives, each with its own detail type and density scale. The
// recipe is only read and checked here; recipe_voxeliser turns it into voxels.
#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hero_clouds {

// Every position and length of a recipe lies within this many metres of the cloud's origin: a
// hero cloud is a few kilometres, and the bound keeps every later sum finite.
inline constexpr double kMaxRecipeMetres = 100000.0;
inline constexpr std::size_t kMaxPrimitives = 256;
inline constexpr std::size_t kMaxTubePoints = 256;

struct SpherePrimitive {
  glm::dvec3 centreMetres{0.0};
  double radiusMetres = 0.0;
};

// Axis-aligned in the cloud's frame; a scene turns the whole cloud, not one primitive.
struct EllipsoidPrimitive {
  glm::dvec3 centreMetres{0.0};
  glm::dvec3 radiiMetres{0.0};
};

// A swept curve: the polyline through pointsMetres, with a radius at each point interpolated
// linearly along each segment, i.e. a chain of round cones (at least two points).
struct TubePrimitive {
  std::vector<glm::dvec3> pointsMetres;
  std::vector<double> radiiMetres;  // one per point
};

// The points within minorRadiusMetres of the circle of majorRadiusMetres around centreMetres
// in the plane normal to `axis` (unit length once read).
struct TorusPrimitive {
  glm::dvec3 centreMetres{0.0};
  glm::dvec3 axis{0.0, 1.0, 0.0};
  double majorRadiusMetres = 0.0;
  double minorRadiusMetres = 0.0;
};

using PrimitiveShape =
    std::variant<SpherePrimitive, EllipsoidPrimitive, TubePrimitive, TorusPrimitive>;

struct CloudPrimitive {
  PrimitiveShape shape;
  double detailType = 0.5;    // [0, 1]: 0 wispy, 1 billowy
  double densityScale = 1.0;  // [0, 1]: the share of density this part keeps after erosion
};

struct CloudRecipe {
  std::string name;
  std::string description;  // optional notes of the author; not baked
  double voxelMetres = 0.0;
  // Radius of the polynomial smooth minimum that joins the primitives (0: a plain union).
  double blendMetres = 0.0;
  // Depth below the surface at which the dimensional profile reaches 1.
  double coreDepthMetres = 0.0;
  std::vector<CloudPrimitive> primitives;
};

// Parses and checks a recipe held in `text`; `source` names it in messages. Throws
// std::runtime_error "<source>: <field path>: <reason>" for malformed JSON, a missing,
// mistyped, non-finite, out-of-range or unknown field, an unknown shape, or a grid beyond
// the NVDF limits (clouds/nvdf.h).
CloudRecipe parseCloudRecipe(std::string_view text, const std::string& source);

// Reads and parses a recipe file; messages name the file as given.
CloudRecipe loadCloudRecipe(const std::filesystem::path& file);

}  // namespace hero_clouds
