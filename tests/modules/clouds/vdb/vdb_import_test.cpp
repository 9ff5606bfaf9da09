// The OpenVDB import (clouds/vdb_import.h): which grid it takes, world units as metres, the
// grid's placement, and a clear error naming the file for each kind of bad file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "clouds/vdb_import.h"
#include "vdb_test_files.h"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / ("clouds_vdb_import_" + name);
}

float ramp(openvdb::Coord c) {
  return 0.25f + 0.01f * float(c.x() + 2 * c.y() + 3 * c.z());
}

std::string importError(const fs::path& file, const clouds::VdbImportOptions& options = {}) {
  clouds::Error error;
  EXPECT_FALSE(clouds::importVdb(file, options, nullptr, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidAsset);
  EXPECT_NE(error.message.find(file.string()), std::string::npos) << error.message;
  return error.message;
}

TEST(VdbImport, TakesTheDensityGridInWorldMetres) {
  const fs::path file = scratch("density.vdb");
  // A float grid before "density": the name decides, not the order.
  vdb_test::write(
      file, {vdb_test::floatGrid("temperature", 1.0, {}, openvdb::Coord(0), openvdb::Coord(2),
                                 [](openvdb::Coord) { return 9.0f; }),
             vdb_test::floatGrid("density", 0.5, {10.0, 200.0, -5.0}, openvdb::Coord(-3, 4, 0),
                                 openvdb::Coord(5, 9, 6), ramp)});
  clouds::VdbImportReport report;
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> v = clouds::importVdb(file, {}, &report, &error);
  ASSERT_TRUE(v) << error.message;
  EXPECT_EQ(report.gridName, "density");
  EXPECT_EQ(report.activeVoxels, 9u * 6u * 7u);
  EXPECT_TRUE(report.warnings.empty());
  // One voxel of clear air around the active box.
  EXPECT_EQ(v->size, glm::uvec3(11, 8, 9));
  EXPECT_FLOAT_EQ(v->voxelMetres, 0.5f);
  // Voxel (0, 0, 0) is index (-4, 3, -1): its centre in world metres.
  EXPECT_NEAR(v->originMetres.x, 10.0f - 2.0f, 1e-5f);
  EXPECT_NEAR(v->originMetres.y, 200.0f + 1.5f, 1e-5f);
  EXPECT_NEAR(v->originMetres.z, -5.0f - 0.5f, 1e-5f);
  const float largest = ramp(openvdb::Coord(5, 9, 6));
  EXPECT_FLOAT_EQ(v->densityMultiplier, largest);
  for (int k = 0; k <= 6; ++k) {
    for (int j = 4; j <= 9; ++j) {
      for (int i = -3; i <= 5; ++i) {
        const glm::uvec3 voxel(unsigned(i + 4), unsigned(j - 3), unsigned(k + 1));
        ASSERT_NEAR(v->field(voxel, clouds::kNvdfProfile) * largest, ramp(openvdb::Coord(i, j, k)),
                    0.5f / 255.0f * largest + 1e-6f);
      }
    }
  }
  EXPECT_EQ(v->field(glm::uvec3(0, 0, 0), clouds::kNvdfProfile), 0.0f);
  fs::remove(file);
}

TEST(VdbImport, TakesTheFirstFloatGridOrTheOneAskedFor) {
  const auto solid = [](openvdb::Coord) { return 1.0f; };
  const fs::path first = scratch("first_float.vdb");
  openvdb::Vec3SGrid::Ptr velocity = openvdb::Vec3SGrid::create();
  velocity->setName("velocity");
  vdb_test::write(first, {velocity, vdb_test::floatGrid("smoke", 1.0, {}, openvdb::Coord(0),
                                                        openvdb::Coord(1), solid)});
  clouds::VdbImportReport report;
  clouds::Error error;
  ASSERT_TRUE(clouds::importVdb(first, {}, &report, &error)) << error.message;
  EXPECT_EQ(report.gridName, "smoke");
  fs::remove(first);

  const fs::path two = scratch("two_floats.vdb");
  vdb_test::write(
      two, {vdb_test::floatGrid("smoke", 1.0, {}, openvdb::Coord(0), openvdb::Coord(1), solid),
            vdb_test::floatGrid("heat", 1.0, {}, openvdb::Coord(0), openvdb::Coord(3), solid)});
  clouds::VdbImportOptions heat;
  heat.gridName = "heat";
  const std::optional<clouds::NvdfVolume> v = clouds::importVdb(two, heat, &report, &error);
  ASSERT_TRUE(v) << error.message;
  EXPECT_EQ(report.gridName, "heat");
  EXPECT_EQ(v->size, glm::uvec3(6));  // heat's 4^3 voxels, not smoke's 2^3
  clouds::VdbImportOptions missing;
  missing.gridName = "density";
  const std::string message = importError(two, missing);
  EXPECT_NE(message.find("no grid named \"density\""), std::string::npos) << message;
  EXPECT_NE(message.find("\"smoke\""), std::string::npos) << message;
  EXPECT_NE(message.find("\"heat\""), std::string::npos) << message;
  fs::remove(two);
}

TEST(VdbImport, ReadsNanAndNegativeValuesAsClearAirAndSaysSo) {
  const fs::path file = scratch("bad_values.vdb");
  vdb_test::write(file, {vdb_test::floatGrid("density", 1.0, {}, openvdb::Coord(0),
                                             openvdb::Coord(3), [](openvdb::Coord c) {
                                               if (c.x() == 0 && c.y() == 0) return std::nanf("");
                                               if (c.x() == 1 && c.y() == 0) return -2.0f;
                                               if (c.x() == 2 && c.y() == 0 && c.z() == 0) {
                                                 return INFINITY;
                                               }
                                               return 1.0f;
                                             })});
  clouds::VdbImportReport report;
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> v = clouds::importVdb(file, {}, &report, &error);
  ASSERT_TRUE(v) << error.message;
  EXPECT_EQ(report.nonFiniteVoxels, 5u);
  EXPECT_EQ(report.negativeVoxels, 4u);
  ASSERT_EQ(report.warnings.size(), 2u);
  EXPECT_NE(report.warnings[0].find(file.string()), std::string::npos);
  EXPECT_NE(report.warnings[0].find("5 NaN or infinite values read as 0"), std::string::npos);
  EXPECT_NE(report.warnings[1].find("4 negative values read as 0"), std::string::npos);
  EXPECT_EQ(v->field(glm::uvec3(1, 1, 1), clouds::kNvdfProfile), 0.0f);  // the NaN voxel
  EXPECT_EQ(v->field(glm::uvec3(2, 1, 1), clouds::kNvdfProfile), 0.0f);  // the negative one
  EXPECT_EQ(v->field(glm::uvec3(1, 2, 1), clouds::kNvdfProfile), 1.0f);
  EXPECT_TRUE(std::isfinite(v->densityMultiplier));
  fs::remove(file);
}

TEST(VdbImport, OneVoxelIsACloud) {
  const fs::path file = scratch("one_voxel.vdb");
  vdb_test::write(file,
                  {vdb_test::floatGrid("density", 2.0, {}, openvdb::Coord(7), openvdb::Coord(7),
                                       [](openvdb::Coord) { return 3.0f; })});
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> v = clouds::importVdb(file, {}, nullptr, &error);
  ASSERT_TRUE(v) << error.message;
  EXPECT_EQ(v->size, glm::uvec3(3));
  EXPECT_EQ(v->field(glm::uvec3(1), clouds::kNvdfProfile), 1.0f);
  EXPECT_LT(v->distanceMetres(glm::uvec3(1)), 0.0f);
  fs::remove(file);
}

TEST(VdbImport, NamesTheFileAndTheProblem) {
  EXPECT_NE(importError("/nonexistent/cloud.vdb").find("no such file"), std::string::npos);

  const fs::path text = scratch("not_a_vdb.vdb");
  std::ofstream(text) << "this is not an OpenVDB file\n";
  EXPECT_NE(importError(text).find("not a readable OpenVDB file"), std::string::npos);
  fs::remove(text);

  const fs::path empty = scratch("empty.vdb");
  vdb_test::write(empty,
                  {vdb_test::floatGrid("density", 1.0, {}, openvdb::Coord(1), openvdb::Coord(0),
                                       [](openvdb::Coord) { return 1.0f; })});
  EXPECT_NE(importError(empty).find("no active voxels"), std::string::npos);
  fs::remove(empty);

  const fs::path zeros = scratch("zeros.vdb");
  vdb_test::write(zeros,
                  {vdb_test::floatGrid("density", 1.0, {}, openvdb::Coord(0), openvdb::Coord(2),
                                       [](openvdb::Coord) { return 0.0f; })});
  EXPECT_NE(importError(zeros).find("holds no cloud"), std::string::npos);
  fs::remove(zeros);

  const fs::path vectors = scratch("vectors.vdb");
  openvdb::Vec3SGrid::Ptr velocity = openvdb::Vec3SGrid::create();
  velocity->setName("density");
  vdb_test::write(vectors, {velocity});
  const std::string vectorMessage = importError(vectors);
  EXPECT_NE(vectorMessage.find("grid \"density\" holds vec3s, not float"), std::string::npos)
      << vectorMessage;
  fs::remove(vectors);

  const fs::path rotated = scratch("rotated.vdb");
  openvdb::FloatGrid::Ptr turned =
      vdb_test::floatGrid("density", 1.0, {}, openvdb::Coord(0), openvdb::Coord(1),
                          [](openvdb::Coord) { return 1.0f; });
  turned->transform().postRotate(0.3, openvdb::math::Y_AXIS);
  vdb_test::write(rotated, {turned});
  EXPECT_NE(importError(rotated).find("transform: voxels must be cubes"), std::string::npos);
  fs::remove(rotated);

  const fs::path huge = scratch("huge.vdb");
  openvdb::FloatGrid::Ptr wide =
      vdb_test::floatGrid("density", 1.0, {}, openvdb::Coord(0), openvdb::Coord(0),
                          [](openvdb::Coord) { return 1.0f; });
  wide->getAccessor().setValueOn(openvdb::Coord(5000, 0, 0), 1.0f);
  vdb_test::write(huge, {wide});
  EXPECT_NE(importError(huge).find("resample it coarser"), std::string::npos);
  fs::remove(huge);
}

}  // namespace
