// The hero cloud authoring tool (assets_src/hero_clouds): recipe reading and its error
// messages, the primitives' signed distances against closed forms, the voxeliser's profile and
// art-field blending, and the shapes of the three shipped clouds.
#include <gtest/gtest.h>

#include <clouds/nvdf.h>
#include <clouds/nvdf_build.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "cloud_recipe.h"
#include "primitive_distance.h"
#include "recipe_grid.h"
#include "recipe_voxeliser.h"

namespace hero_clouds {
namespace {

constexpr const char* kShippedRecipes[] = {"towering_cumulus", "cumulonimbus", "arch"};
constexpr double kMiB = 1024.0 * 1024.0;

CloudRecipe loadShipped(const std::string& name) {
  return loadCloudRecipe(std::string(HERO_CLOUD_SOURCE_DIR) + "/" + name + ".cloud.json");
}

// A recipe of the given primitives (a JSON array's entries) and settings.
std::string recipeText(const std::string& primitives, double voxelMetres = 25.0,
                       double blendMetres = 0.0, double coreDepthMetres = 100.0) {
  return R"({"name": "test", "voxelMetres": )" + std::to_string(voxelMetres) +
         R"(, "blendMetres": )" + std::to_string(blendMetres) + R"(, "coreDepthMetres": )" +
         std::to_string(coreDepthMetres) + R"(, "primitives": [)" + primitives + "]}";
}

// --- Voxel-grid helpers for the shape tests --------------------------------------------------

struct Grid {
  clouds::VoxelDensityGrid voxels;

  bool cloud(unsigned x, unsigned y, unsigned z) const {
    const glm::uvec3 s = voxels.size;
    return voxels.density[(std::size_t{z} * s.y + y) * s.x + x] > 0.0f;
  }
  float heightMetres(unsigned y) const {
    return voxels.originMetres.y + voxels.voxelMetres * static_cast<float>(y);
  }
  float xMetres(unsigned x) const {
    return voxels.originMetres.x + voxels.voxelMetres * static_cast<float>(x);
  }
};

struct Extent {
  int lo = -1;  // first and last voxel index with cloud, -1 when none
  int hi = -1;
  int width() const { return lo < 0 ? 0 : hi - lo + 1; }
};

// The cloudy y range of the whole grid.
Extent cloudHeights(const Grid& g) {
  Extent e;
  const glm::uvec3 s = g.voxels.size;
  for (unsigned y = 0; y < s.y; ++y) {
    for (unsigned z = 0; z < s.z; ++z) {
      for (unsigned x = 0; x < s.x; ++x) {
        if (!g.cloud(x, y, z)) continue;
        if (e.lo < 0) e.lo = static_cast<int>(y);
        e.hi = static_cast<int>(y);
      }
    }
  }
  return e;
}

// The cloudy x range over the layers y in [yLo, yHi], along any z.
Extent cloudXs(const Grid& g, unsigned yLo, unsigned yHi) {
  Extent e;
  const glm::uvec3 s = g.voxels.size;
  for (unsigned y = yLo; y <= yHi; ++y) {
    for (unsigned z = 0; z < s.z; ++z) {
      for (unsigned x = 0; x < s.x; ++x) {
        if (!g.cloud(x, y, z)) continue;
        e.lo = e.lo < 0 ? static_cast<int>(x) : std::min(e.lo, static_cast<int>(x));
        e.hi = std::max(e.hi, static_cast<int>(x));
      }
    }
  }
  return e;
}

Grid voxelise(const std::string& name) {
  return Grid{voxeliseRecipe(loadShipped(name))};
}

// --- Shipped recipes -------------------------------------------------------------------------

TEST(HeroCloudRecipes, ShippedRecipesBakeWithinTheMemoryBudget) {
  double totalMiB = 0.0;
  for (const char* name : kShippedRecipes) {
    SCOPED_TRACE(name);
    const CloudRecipe recipe = loadShipped(name);
    const clouds::VoxelDensityGrid grid = voxeliseRecipe(recipe);
    const glm::uvec3 s = grid.size;
    ASSERT_EQ(grid.density.size(), std::size_t{s.x} * s.y * s.z);
    ASSERT_EQ(grid.detailType.size(), grid.density.size());
    ASSERT_EQ(grid.densityScale.size(), grid.density.size());
    // The core is reached, so buildNvdf()'s normalisation keeps the authored profile.
    EXPECT_FLOAT_EQ(*std::max_element(grid.density.begin(), grid.density.end()), 1.0f);
    // No cloud touches the grid's faces (the margin of planRecipeGrid()).
    for (unsigned z = 0; z < s.z; ++z) {
      for (unsigned y = 0; y < s.y; ++y) {
        for (unsigned x = 0; x < s.x; ++x) {
          const bool face =
              x == 0 || y == 0 || z == 0 || x + 1 == s.x || y + 1 == s.y || z + 1 == s.z;
          if (face) {
            ASSERT_EQ(grid.density[(std::size_t{z} * s.y + y) * s.x + x], 0.0f)
                << "voxel " << x << ", " << y << ", " << z;
          }
        }
      }
    }
    clouds::Error error;
    const std::optional<clouds::NvdfVolume> volume =
        clouds::buildNvdf(grid, clouds::NvdfBuildOptions{}, &error);
    ASSERT_TRUE(volume) << error.message;
    EXPECT_EQ(clouds::validateNvdf(*volume), "");
    const double mib = static_cast<double>(volume->deviceBytes()) / kMiB;
    std::printf("%s: %ux%ux%u voxels of %g m, %.2f MiB\n", recipe.name.c_str(), s.x, s.y, s.z,
                static_cast<double>(grid.voxelMetres), mib);
    EXPECT_LE(mib, 6.0);
    totalMiB += mib;
  }
  // The seed budget at Medium is 25.2 MB; the hero clouds take well under half of it.
  EXPECT_LE(totalMiB, 15.0);
}

TEST(HeroCloudRecipes, ToweringCumulusIsTallerThanWide) {
  const Grid g = voxelise("towering_cumulus");
  const glm::uvec3 s = g.voxels.size;
  const Extent height = cloudHeights(g);
  const Extent x = cloudXs(g, 0, s.y - 1);
  ASSERT_GT(height.width(), 0);
  const float heightMetres = static_cast<float>(height.width()) * g.voxels.voxelMetres;
  const float widthMetres = static_cast<float>(x.width()) * g.voxels.voxelMetres;
  EXPECT_GT(heightMetres, widthMetres);
  EXPECT_GE(heightMetres, 1500.0f);
  EXPECT_LE(heightMetres, 2500.0f);
  EXPECT_NEAR(widthMetres, 1200.0f, 300.0f);
}

TEST(HeroCloudRecipes, CumulonimbusAnvilSpreadsDownwind) {
  const Grid g = voxelise("cumulonimbus");
  const Extent height = cloudHeights(g);
  ASSERT_GT(height.width(), 0);
  const int h = height.width();
  const auto anvilFloor = static_cast<unsigned>(height.hi - (h * 15) / 100);
  const auto midHeight = static_cast<unsigned>(height.lo + h / 2);
  const Extent anvil = cloudXs(g, anvilFloor, static_cast<unsigned>(height.hi));
  const Extent tower = cloudXs(g, midHeight, midHeight);
  EXPECT_GE(static_cast<float>(height.width()) * g.voxels.voxelMetres, 8000.0f);
  EXPECT_GE(anvil.width(), 2 * tower.width());
  // Downwind is +x: measured from the tower's axis, the anvil reaches further to +x.
  const float towerAxisMetres = 0.5f * (g.xMetres(static_cast<unsigned>(tower.lo)) +
                                        g.xMetres(static_cast<unsigned>(tower.hi)));
  const float downwind = g.xMetres(static_cast<unsigned>(anvil.hi)) - towerAxisMetres;
  const float upwind = towerAxisMetres - g.xMetres(static_cast<unsigned>(anvil.lo));
  EXPECT_GT(downwind, upwind);
  // The anvil is wispy, the tower billowy: the art fields follow the primitives.
  const CloudRecipe recipe = loadShipped("cumulonimbus");
  const RecipeSample anvilSample = sampleRecipe(recipe, {6000.0, 9200.0, 0.0});
  const RecipeSample towerSample = sampleRecipe(recipe, {100.0, 4500.0, 0.0});
  EXPECT_GT(anvilSample.profile, 0.0f);
  EXPECT_LT(anvilSample.detailType, 0.3f);
  EXPECT_GT(towerSample.detailType, 0.7f);
}

// What no vertical-profile model can make. Such a model (a 2D weather map and, per column, a
// profile over height above the layer's one base altitude, as in Nubis) puts a column's cloud
// on one height interval starting at or near that base, raised only as smoothly as the map
// varies. The arch has columns whose cloud lies above clear air reaching all the way down to
// the base level, while on both sides of them (along x) columns are cloudy from the base up
// past the top of that clear air: an opening through the cloud, closed left, right and above.
TEST(HeroCloudRecipes, ArchHasCloudAboveClearAirNoVerticalProfileCanMake) {
  const Grid g = voxelise("arch");
  const glm::uvec3 s = g.voxels.size;
  const Extent height = cloudHeights(g);
  ASSERT_GT(height.width(), 0);
  const auto base = static_cast<unsigned>(height.lo);
  // Per column: the lowest cloudy voxel, and the highest.
  auto lowestCloud = [&](unsigned x, unsigned z) -> int {
    for (unsigned y = 0; y < s.y; ++y) {
      if (g.cloud(x, y, z)) return static_cast<int>(y);
    }
    return -1;
  };
  auto highestCloud = [&](unsigned x, unsigned z) -> int {
    for (unsigned y = s.y; y-- > 0;) {
      if (g.cloud(x, y, z)) return static_cast<int>(y);
    }
    return -1;
  };
  int archColumns = 0;
  for (unsigned z = 0; z < s.z; ++z) {
    for (unsigned x = 0; x < s.x; ++x) {
      // Cloud above clear air that reaches the lowest cloudy level of the whole cloud (the
      // ground the legs stand on), the gap at least 500 m tall.
      const int gapTop = lowestCloud(x, z);
      if (gapTop < 0) continue;
      if (g.heightMetres(static_cast<unsigned>(gapTop)) - g.heightMetres(base) < 500.0f) continue;
      // On each side along x, a column cloudy at the base whose cloud rises above the gap.
      bool side[2] = {false, false};
      for (unsigned nx = 0; nx < s.x; ++nx) {
        if (nx == x || lowestCloud(nx, z) != static_cast<int>(base)) continue;
        if (highestCloud(nx, z) > gapTop) side[nx > x ? 1 : 0] = true;
      }
      if (side[0] && side[1]) ++archColumns;
    }
  }
  EXPECT_GT(archColumns, 0);
  // The same, seen at one column: the middle of the opening.
  const RecipeSample underBridge = sampleRecipe(loadShipped("arch"), {0.0, 1000.0, 0.0});
  const RecipeSample bridge = sampleRecipe(loadShipped("arch"), {0.0, 2000.0, 0.0});
  EXPECT_EQ(underBridge.profile, 0.0f);
  EXPECT_GT(bridge.profile, 0.9f);
}

// --- Primitives ------------------------------------------------------------------------------

TEST(HeroCloudPrimitives, SphereProfileIsZeroOutsideAndOneAtCoreDepth) {
  // Radius 500 m, core depth 100 m, no blend: profile = clamp((500 - r) / 100, 0, 1).
  const CloudRecipe recipe = parseCloudRecipe(
      recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 500})"),
      "sphere.cloud.json");
  EXPECT_FLOAT_EQ(sampleRecipe(recipe, {700.0, 0.0, 0.0}).profile, 0.0f);
  EXPECT_FLOAT_EQ(sampleRecipe(recipe, {0.0, 500.0, 0.0}).profile, 0.0f);
  EXPECT_NEAR(sampleRecipe(recipe, {0.0, 0.0, 480.0}).profile, 0.2f, 1e-6f);
  EXPECT_NEAR(sampleRecipe(recipe, {-450.0, 0.0, 0.0}).profile, 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(sampleRecipe(recipe, {0.0, -400.0, 0.0}).profile, 1.0f);
  EXPECT_FLOAT_EQ(sampleRecipe(recipe, {0.0, 0.0, 0.0}).profile, 1.0f);
  EXPECT_NEAR(sampleRecipe(recipe, {300.0, 0.0, 400.0}).signedDistanceMetres, 0.0, 1e-9);

  // Every voxel of the grid holds the closed form at its centre.
  const clouds::VoxelDensityGrid grid = voxeliseRecipe(recipe);
  const glm::uvec3 s = grid.size;
  std::size_t index = 0;
  std::size_t inside = 0;
  for (unsigned z = 0; z < s.z; ++z) {
    for (unsigned y = 0; y < s.y; ++y) {
      for (unsigned x = 0; x < s.x; ++x, ++index) {
        const glm::vec3 centre = grid.originMetres + grid.voxelMetres * glm::vec3(x, y, z);
        const float expected = std::clamp((500.0f - glm::length(centre)) / 100.0f, 0.0f, 1.0f);
        ASSERT_NEAR(grid.density[index], expected, 1e-4f) << x << ", " << y << ", " << z;
        if (expected > 0.0f) ++inside;
      }
    }
  }
  // The grid is centred on the sphere and leaves the margin (blend 0 + 2 voxels) around it.
  EXPECT_GT(inside, std::size_t{1000});
  EXPECT_NEAR(grid.originMetres.x + grid.voxelMetres * static_cast<float>(s.x - 1) * 0.5f, 0.0f,
              1e-3f);
  EXPECT_LE(grid.originMetres.x, -550.0f);
}

TorusPrimitive torusOf(const CloudRecipe& recipe) {
  return std::get<TorusPrimitive>(recipe.primitives.at(0).shape);
}

TEST(HeroCloudPrimitives, TorusDistanceMatchesClosedForm) {
  // A ring of radius 800 m and tube 200 m around (10, 20, 30), facing +z; the axis is given
  // unnormalised on purpose.
  const TorusPrimitive torus = torusOf(parseCloudRecipe(
      recipeText(R"({"shape": "torus", "centreMetres": [10, 20, 30], "axis": [0, 0, 2],
                     "majorRadiusMetres": 800, "minorRadiusMetres": 200})"),
      "torus.cloud.json"));
  EXPECT_DOUBLE_EQ(glm::length(torus.axis), 1.0);
  const glm::dvec3 c{10.0, 20.0, 30.0};
  EXPECT_NEAR(torusDistance(torus, c), 600.0, 1e-9);                                 // the hole
  EXPECT_NEAR(torusDistance(torus, c + glm::dvec3{800.0, 0.0, 0.0}), -200.0, 1e-9);  // core
  EXPECT_NEAR(torusDistance(torus, c + glm::dvec3{0.0, 1100.0, 0.0}), 100.0, 1e-9);
  EXPECT_NEAR(torusDistance(torus, c + glm::dvec3{0.0, 0.0, 300.0}),
              std::hypot(800.0, 300.0) - 200.0, 1e-9);
  EXPECT_NEAR(torusDistance(torus, c + glm::dvec3{0.0, -800.0, 150.0}), -50.0, 1e-9);
  // A diagonal point in the ring's plane: 60 m outside the tube.
  EXPECT_NEAR(torusDistance(torus, c + glm::dvec3{1060.0, 0.0, 0.0} * std::sqrt(0.5) +
                                       glm::dvec3{0.0, 1060.0, 0.0} * std::sqrt(0.5)),
              60.0, 1e-9);
  // Its box: the ring spans +-1000 m in x and y, +-200 m in z.
  const BoxMetres box = boundsMetres(torus);
  EXPECT_NEAR(box.minMetres.x, -990.0, 1e-9);
  EXPECT_NEAR(box.maxMetres.y, 1020.0, 1e-9);
  EXPECT_NEAR(box.maxMetres.z, 230.0, 1e-9);
}

TEST(HeroCloudPrimitives, TubeDistanceMatchesClosedForm) {
  const CloudRecipe recipe = parseCloudRecipe(recipeText(R"({"shape": "tube",
                     "pointsMetres": [[0, 0, 0], [1000, 0, 0], [1000, 1000, 0]],
                     "radiiMetres": [100, 100, 300]})"),
                                              "tube.cloud.json");
  const TubePrimitive& tube = std::get<TubePrimitive>(recipe.primitives.at(0).shape);
  // Along the even first segment the tube is a capsule: distance to the segment minus 100.
  EXPECT_NEAR(tubeDistance(tube, {500.0, 250.0, 0.0}), 150.0, 1e-9);
  EXPECT_NEAR(tubeDistance(tube, {500.0, 0.0, -40.0}), -60.0, 1e-9);
  EXPECT_NEAR(tubeDistance(tube, {-300.0, 0.0, 0.0}), 200.0, 1e-9);  // beyond the round end
  // Beyond the thick end, straight along the second segment: the end sphere of radius 300.
  EXPECT_NEAR(tubeDistance(tube, {1000.0, 1500.0, 0.0}), 200.0, 1e-9);

  // A round cone from radius 300 at (0, 0) to 100 at (0, 1000): its side leans in by
  // sin(a) = (300 - 100) / 1000, with outward normal (cos a, sin a) in (radial, axial), so a
  // point whose nearest surface point lies on the side is dot(p, n) - 300 from it.
  const double sinA = 0.2;
  const double cosA = std::sqrt(1.0 - sinA * sinA);
  EXPECT_NEAR(
      roundConeDistance({500.0, 500.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 1000.0, 0.0}, 300.0, 100.0),
      500.0 * cosA + 500.0 * sinA - 300.0, 1e-9);
  // The same cone around the z axis of a turned frame (radial direction z, axis y).
  EXPECT_NEAR(
      roundConeDistance({0.0, 500.0, -500.0}, {0.0, 0.0, 0.0}, {0.0, 1000.0, 0.0}, 300.0, 100.0),
      500.0 * cosA + 500.0 * sinA - 300.0, 1e-9);
  // One sphere inside the other: the larger sphere.
  EXPECT_NEAR(
      roundConeDistance({0.0, -700.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 500.0, 100.0),
      200.0, 1e-9);
}

TEST(HeroCloudPrimitives, EllipsoidEstimateIsExactOnAxesAndBoundedInside) {
  const EllipsoidPrimitive disc{{0.0, 0.0, 0.0}, {4500.0, 450.0, 3200.0}};
  // On a principal axis Quilez's estimate is exact outside.
  EXPECT_NEAR(ellipsoidDistance(disc, {0.0, 550.0, 0.0}), 100.0, 1e-9);
  EXPECT_NEAR(ellipsoidDistance(disc, {4600.0, 0.0, 0.0}), 100.0, 1e-9);
  EXPECT_NEAR(ellipsoidDistance(disc, {0.0, 0.0, 0.0}), -450.0, 1e-9);
  // Near the rim of the flat disc the depth stays below the half-thickness there (206 m),
  // where the estimate alone reads 500 m.
  const double rimDepth = -ellipsoidDistance(disc, {4000.0, 0.0, 0.0});
  EXPECT_GT(rimDepth, 150.0);
  EXPECT_LE(rimDepth, 450.0 * std::sqrt(1.0 - (4000.0 / 4500.0) * (4000.0 / 4500.0)) + 1e-9);
  // With equal radii it is the sphere, exactly.
  const EllipsoidPrimitive round{{5.0, 6.0, 7.0}, {300.0, 300.0, 300.0}};
  const SpherePrimitive sphere{{5.0, 6.0, 7.0}, 300.0};
  for (const glm::dvec3 p : {glm::dvec3{100.0, 50.0, -20.0}, glm::dvec3{400.0, -100.0, 90.0},
                             glm::dvec3{5.0, 6.0, 250.0}}) {
    EXPECT_NEAR(ellipsoidDistance(round, p), sphereDistance(sphere, p), 1e-9);
  }
}

TEST(HeroCloudVoxeliser, SmoothMinimumJoinsWithinTheBlendOnly) {
  EXPECT_DOUBLE_EQ(smoothMinimum(10.0, 30.0, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(smoothMinimum(10.0, 300.0, 100.0), 10.0);        // far apart: the minimum
  EXPECT_DOUBLE_EQ(smoothMinimum(50.0, 50.0, 100.0), 50.0 - 25.0);  // equal: min - blend / 4
}

TEST(HeroCloudVoxeliser, ArtFieldsFollowTheNearestPrimitive) {
  // Two spheres 2 km apart: a wispy, thin one and a billowy, dense one; blend 60 m.
  const CloudRecipe recipe = parseCloudRecipe(
      recipeText(R"({"shape": "sphere", "centreMetres": [-1000, 0, 0], "radiusMetres": 400,
                     "detailType": 0.1, "densityScale": 0.3},
                    {"shape": "sphere", "centreMetres": [1000, 0, 0], "radiusMetres": 400,
                     "detailType": 0.9})",
                 25.0, 60.0, 100.0),
      "pair.cloud.json");
  const RecipeSample wispy = sampleRecipe(recipe, {-1000.0, 0.0, 0.0});
  const RecipeSample billowy = sampleRecipe(recipe, {1000.0, 0.0, 0.0});
  EXPECT_NEAR(wispy.detailType, 0.1f, 1e-6f);
  EXPECT_NEAR(wispy.densityScale, 0.3f, 1e-6f);
  EXPECT_NEAR(billowy.detailType, 0.9f, 1e-6f);
  EXPECT_NEAR(billowy.densityScale, 1.0f, 1e-6f);  // the default
  // Half way, both are as near: the average.
  const RecipeSample middle = sampleRecipe(recipe, {0.0, 0.0, 0.0});
  EXPECT_NEAR(middle.detailType, 0.5f, 1e-6f);
  EXPECT_NEAR(middle.densityScale, 0.65f, 1e-6f);

  // A small billowy puff overlapping a big wispy body: deep inside the puff it wins, deep in
  // the body away from the puff the body wins, and the voxels agree with the samples.
  const CloudRecipe overlap = parseCloudRecipe(
      recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 800,
                     "detailType": 0.2},
                    {"shape": "sphere", "centreMetres": [0, 850, 0], "radiusMetres": 300,
                     "detailType": 1.0})",
                 50.0, 60.0, 100.0),
      "overlap.cloud.json");
  EXPECT_GT(sampleRecipe(overlap, {0.0, 850.0, 0.0}).detailType, 0.99f);
  EXPECT_LT(sampleRecipe(overlap, {0.0, -500.0, 0.0}).detailType, 0.21f);
  const clouds::VoxelDensityGrid grid = voxeliseRecipe(overlap);
  const GridLayout layout = planRecipeGrid(overlap);
  ASSERT_EQ(grid.size, glm::uvec3(layout.size[0], layout.size[1], layout.size[2]));
  const glm::uvec3 voxel{grid.size.x / 2, grid.size.y / 3, grid.size.z / 2};
  const RecipeSample atCentre =
      sampleRecipe(overlap, layout.voxelCentreMetres(voxel.x, voxel.y, voxel.z));
  const std::size_t index = (std::size_t{voxel.z} * grid.size.y + voxel.y) * grid.size.x + voxel.x;
  EXPECT_FLOAT_EQ(grid.detailType[index], atCentre.detailType);
  EXPECT_FLOAT_EQ(grid.densityScale[index], atCentre.densityScale);
  EXPECT_FLOAT_EQ(grid.density[index], atCentre.profile);
}

// --- Errors ----------------------------------------------------------------------------------

struct BadRecipe {
  const char* what;
  std::string text;
  std::string fieldPath;  // must appear right after "bad.cloud.json: "
  std::string reason;     // must appear somewhere after it
};

const std::string kSphere =
    R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 400})";

std::vector<BadRecipe> badRecipes() {
  return {
      {"malformed JSON", R"({"name": "x", "voxelMetres": 20,,})", "voxelMetres",
       "not valid JSON: parse error at line 1"},
      {"not an object", "[1, 2]", "", "must be a JSON object, got array"},
      {"missing primitives",
       R"({"name": "x", "voxelMetres": 20, "blendMetres": 0, "coreDepthMetres": 100})",
       "primitives", "missing"},
      {"no primitives", recipeText(""), "primitives", "must have 1 to 256 entries, got 0"},
      {"unknown shape", recipeText(kSphere + R"(, {"shape": "cube", "centreMetres": [0, 0, 0]})"),
       "primitives[1].shape", "unknown shape \"cube\""},
      {"unknown key in a primitive",
       recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 400,
                      "detailtype": 0.3})"),
       "primitives[0].detailtype", "unknown key"},
      {"unknown key at the root",
       R"({"name": "x", "voxelMetres": 20, "blendMetres": 0, "coreDepthMetres": 100,
           "coreDepthMeters": 100, "primitives": [)" +
           kSphere + "]}",
       "coreDepthMeters", "unknown key"},
      {"negative radius", recipeText(kSphere + R"(, {"shape": "sphere", "centreMetres": [0, 0, 0],
                                   "radiusMetres": -3})"),
       "primitives[1].radiusMetres", "must be in (0, 100000], got -3"},
      {"zero tube radius", recipeText(R"({"shape": "tube", "pointsMetres": [[0, 0, 0], [0, 900, 0]],
                      "radiiMetres": [200, 0]})"),
       "primitives[0].radiiMetres[1]", "must be in (0, 100000], got 0"},
      {"a radius short", recipeText(R"({"shape": "tube", "pointsMetres": [[0, 0, 0], [0, 9, 0]],
                                        "radiiMetres": [200]})"),
       "primitives[0].radiiMetres", "must have 2 entries, got 1"},
      {"huge radius",
       recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 1e30})"),
       "primitives[0].radiusMetres", "got 1e+30"},
      {"overflowing number",
       recipeText(R"({"shape": "sphere", "centreMetres": [0, 1e400, 0], "radiusMetres": 4})"),
       "primitives[0].centreMetres[1]", "number overflow"},
      {"NaN", recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, NaN], "radiusMetres": 4})"),
       "primitives[0].centreMetres[2]", "not valid JSON"},
      {"number as a string",
       R"({"name": "x", "voxelMetres": "20", "blendMetres": 0, "coreDepthMetres": 100,
           "primitives": [)" +
           kSphere + "]}",
       "voxelMetres", "must be a number, got string"},
      {"detail type above 1",
       recipeText(R"({"shape": "sphere", "centreMetres": [0, 0, 0], "radiusMetres": 400,
                      "detailType": 1.5})"),
       "primitives[0].detailType", "must be in [0, 1], got 1.5"},
      {"centre of two numbers",
       recipeText(R"({"shape": "ellipsoid", "centreMetres": [0, 0], "radiiMetres": [1, 2, 3]})"),
       "primitives[0].centreMetres", "must be an array of 3 numbers"},
      {"torus without an axis direction",
       recipeText(R"({"shape": "torus", "centreMetres": [0, 0, 0], "axis": [0, 0, 0],
                      "majorRadiusMetres": 800, "minorRadiusMetres": 200})"),
       "primitives[0].axis", "must not be [0, 0, 0]"},
      {"voxels too small", recipeText(kSphere, 0.001), "voxelMetres",
       "must be in [0.01, 1000], got 0.001"},
      {"voxels too large", recipeText(kSphere, 2000.0), "voxelMetres",
       "must be in [0.01, 1000], got 2000"},
      // 800 m of sphere in 0.5 m voxels: 1609 voxels a side.
      {"a side too long", recipeText(kSphere, 0.5), "voxelMetres", "a side may have at most 1024"},
      // 800 m in 1 m voxels: 805 a side, 5.2e8 voxels in all.
      {"too many voxels", recipeText(kSphere, 1.0), "voxelMetres", "more than 67108864"},
      {"empty name",
       R"({"name": "", "voxelMetres": 20, "blendMetres": 0, "coreDepthMetres": 100,
           "primitives": [)" +
           kSphere + "]}",
       "name", "must have 1 to 100 characters"},
      {"zero core depth", recipeText(kSphere, 20.0, 0.0, 0.0), "coreDepthMetres",
       "must be in (0, 10000], got 0"},
  };
}

TEST(HeroCloudRecipeErrors, NameTheFileTheFieldAndTheReason) {
  for (const BadRecipe& bad : badRecipes()) {
    SCOPED_TRACE(bad.what);
    try {
      parseCloudRecipe(bad.text, "bad.cloud.json");
      ADD_FAILURE() << "accepted";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      const std::string prefix =
          bad.fieldPath.empty() ? "bad.cloud.json: " : "bad.cloud.json: " + bad.fieldPath + ": ";
      EXPECT_TRUE(message.starts_with(prefix)) << message;
      EXPECT_NE(message.find(bad.reason, prefix.size()), std::string::npos) << message;
    }
  }
}

TEST(HeroCloudRecipeErrors, MissingFileNamesIt) {
  try {
    loadCloudRecipe("/nonexistent/dir/missing.cloud.json");
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("/nonexistent/dir/missing.cloud.json: "))
        << e.what();
  }
}

TEST(HeroCloudRecipeErrors, DefaultsApplyOnlyWhereAllowed) {
  const CloudRecipe recipe = parseCloudRecipe(recipeText(kSphere), "defaults.cloud.json");
  ASSERT_EQ(recipe.primitives.size(), 1u);
  EXPECT_EQ(recipe.primitives[0].detailType, 0.5);
  EXPECT_EQ(recipe.primitives[0].densityScale, 1.0);
  EXPECT_EQ(recipe.description, "");
}

}  // namespace
}  // namespace hero_clouds
