// The outside oracle: OpenVDB's own renderer (vdb_render, absorption only), the module's import
// with the CPU reference (clouds_voxel_opacity) and with the module's march on the device
// (clouds_voxel_opacity --gpu) draw the same cloud's opacity from the same cameras; they must
// agree within 0.01 mean absolute difference. Both commands run as a user
// would run them, and a wrong convention (extinction per voxel instead of per metre, the cloud
// half a voxel off) shows as a larger difference.
#include <gtest/gtest.h>

#include <engine/assets/image_io.h>
#include <cmath>
#include <cstdlib>

#include "clouds/vdb_import.h"
#include "nvdf_sampler.h"
#include "vdb_test_files.h"
#include "voxel_opacity.h"

namespace {

namespace fs = std::filesystem;

constexpr double kVoxelMetres = 0.5;  // vdb_test::smokeCloud's
constexpr double kExtinction = 0.12;  // per metre per unit of density
constexpr const char* kSize = "160x90";

struct View {
  const char* name;
  const char* position;
  const char* lookAt;
  double fovDegrees;
};

// The smoke cloud spans x 12..36, y 150..174, z -7..17 (m).
constexpr View kViews[] = {
    {"outside", "24,162,45", "24,162,5", 50.0},
    {"grazing", "62,171,33", "24,165,5", 40.0},
    {"inside", "26,163,5", "0,160,-20", 70.0},
};

glm::dvec3 parse(const char* text) {
  glm::dvec3 v;
  std::sscanf(text, "%lf,%lf,%lf", &v.x, &v.y, &v.z);
  return v;
}

int run(const std::string& command) {
  const int status = std::system((command + " > /dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The alpha channel of an EXR.
std::vector<float> alphaOf(const fs::path& file) {
  const engine::assets::ImageRgba32f image = engine::assets::readImage(file);
  std::vector<float> alpha;
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) alpha.push_back(image.pixels[i]);
  return alpha;
}

double meanAbsoluteDifference(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) sum += std::abs(double(a[i]) - b[i]);
  return sum / double(std::max<std::size_t>(a.size(), 1));
}

double mean(const std::vector<float>& a) {
  double sum = 0.0;
  for (const float v : a) sum += v;
  return sum / double(a.size());
}

class VdbRenderOracle : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = fs::temp_directory_path() / "clouds_vdb_oracle";
    fs::create_directories(folder_);
    vdb_test::write(folder_ / "smoke.vdb", {vdb_test::smokeCloud(48)});
  }
  static fs::path folder_;
};
fs::path VdbRenderOracle::folder_;

TEST_F(VdbRenderOracle, OpacityMatchesOpenVdbsRenderer) {
  const fs::path vdb = folder_ / "smoke.vdb";
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> volume = clouds::importVdb(vdb, {}, nullptr, &error);
  ASSERT_TRUE(volume) << error.message;

  for (const View& view : kViews) {
    SCOPED_TRACE(view.name);
    const fs::path theirs = folder_ / (std::string(view.name) + "_vdb_render.exr");
    const fs::path ours = folder_ / (std::string(view.name) + "_ours.exr");
    const std::string fov = std::to_string(view.fovDegrees);
    // vdb_render's absorption is per voxel length; a fine step makes its sum converge, and
    // -cutoff 0 keeps it from dropping thin density and ending rays early.
    const std::string k = std::to_string(kExtinction * kVoxelMetres);
    ASSERT_EQ(run(std::string(VDB_RENDER) + " " + vdb.string() + " " + theirs.string() + " -res " +
                  kSize + " -fov " + fov + " -translate " + view.position + " -lookat " +
                  view.lookAt + " -absorb " + k + "," + k + "," + k +
                  " -scatter 0,0,0 -cutoff 0 -step 0.05 -compression none -cpus 2"),
              0);
    ASSERT_EQ(
        run(std::string(VOXEL_OPACITY) + " --vdb " + vdb.string() + " --camera-position " +
            view.position + " --look-at " + view.lookAt + " --fov-degrees " + fov + " --size " +
            kSize + " --extinction " + std::to_string(kExtinction) + " --opacity " + ours.string()),
        0);
    // The module's own march, on the device.
    const fs::path marched = folder_ / (std::string(view.name) + "_march.exr");
    ASSERT_EQ(run(std::string(VOXEL_OPACITY) + " --gpu --vdb " + vdb.string() +
                  " --camera-position " + view.position + " --look-at " + view.lookAt +
                  " --fov-degrees " + fov + " --size " + kSize + " --extinction " +
                  std::to_string(kExtinction) + " --opacity " + marched.string() + " 2>&1"),
              0);
    const std::vector<float> reference = alphaOf(theirs);
    const std::vector<float> mine = alphaOf(ours);
    const std::vector<float> march = alphaOf(marched);
    const double difference = meanAbsoluteDifference(mine, reference);
    const double marchDifference = meanAbsoluteDifference(march, reference);
    std::printf(
        "%s: mean opacity %.3f (vdb_render %.3f), mean |difference| %.4f; the march's "
        "%.4f\n",
        view.name, mean(mine), mean(reference), difference, marchDifference);
    EXPECT_GT(mean(reference), 0.1);  // the cloud fills a good part of the picture
    EXPECT_LT(difference, 0.01);
    EXPECT_LT(marchDifference, 0.01);

    // Negative controls, drawn in process with the same camera: each wrong convention is seen.
    clouds::reference::PinholeCamera camera;
    camera.position = parse(view.position);
    camera.lookAt = parse(view.lookAt);
    camera.fovDegrees = view.fovDegrees;
    camera.size = glm::uvec2(160, 90);
    const clouds::reference::NvdfSampler cloud(*volume);
    const double perVoxel = meanAbsoluteDifference(
        clouds::reference::opacityImage(cloud, camera, kExtinction * kVoxelMetres), reference);
    clouds::NvdfVolume shifted = *volume;
    shifted.originMetres += glm::vec3(float(kVoxelMetres) * 0.5f);
    const double halfVoxelOff =
        meanAbsoluteDifference(clouds::reference::opacityImage(
                                   clouds::reference::NvdfSampler(shifted), camera, kExtinction),
                               reference);
    std::printf("%s: negative controls: extinction per voxel %.4f, half a voxel off %.4f\n",
                view.name, perVoxel, halfVoxelOff);
    EXPECT_GT(perVoxel, 0.01);
    EXPECT_GT(halfVoxelOff, difference);
  }
}

}  // namespace
