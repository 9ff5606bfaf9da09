// clouds_voxel_opacity: the opacity (1 - transmittance, absorption only) of a hero cloud from
// an OpenVDB or NVDF file, written as an EXR (the opacity in R, G, B and A): as the CPU
// reference integrates it exactly, or with --gpu as the clouds module's march draws it (a hero
// cloud, one frame, every pixel marched, nothing scattered). Its camera and units follow
// OpenVDB's vdb_render, so that
//   vdb_render cloud.vdb out.exr -res WxH -fov F -translate X,Y,Z -lookat X,Y,Z
//              -absorb K,K,K -scatter 0,0,0 -cutoff 0 -step 0.1
// with K = PER_METRE x the voxel size (vdb_render's coefficients are per voxel length) gives the
// same picture in its alpha channel: the outside oracle of the module's VDB import.
#include <clouds/vdb_import.h>
#include <engine/assets/image_io.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "cloud_harness.h"
#include "engine/gfx/device.h"
#include "engine/gfx/instance.h"
#include "nvdf_sampler.h"
#include "voxel_opacity.h"

namespace {

// "X,Y,Z" into a vector; false when it is not three finite numbers.
bool parseTriple(const std::string& text, glm::dvec3& out) {
  double v[3];
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3) return false;
  out = glm::dvec3(v[0], v[1], v[2]);
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

bool parseSize(const std::string& text, glm::uvec2& out) {
  unsigned w = 0;
  unsigned h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &tail) != 2) return false;
  out = glm::uvec2(w, h);
  return w >= 1 && h >= 1 && w <= 8192 && h <= 8192;
}

// The module's march on the device: the hero cloud alone (a layer of no coverage) at the
// camera, one frame of every pixel marched to its end (no early exit), absorption only; the
// opacity is one less the transmittance output. Validation on: any message fails the run.
// Returns the opacity per pixel, row 0 at the top; empty (and the reason on stderr) on failure.
std::vector<float> gpuOpacity(const clouds::NvdfVolume& volume,
                              const clouds::reference::PinholeCamera& camera,
                              double extinctionPerMetre) {
  engine::gfx::InstanceDesc instanceDesc;
  instanceDesc.validation = true;
  engine::gfx::Instance instance(instanceDesc);
  engine::gfx::Device device(instance, engine::gfx::DeviceDesc{});
  const VkExtent2D extent{camera.size.x, camera.size.y};
  clouds::tools::CloudHarness harness(device, extent);
  const clouds::NvdfVolume* assets[] = {&volume};
  clouds::Error error;
  if (!harness.context().setHeroCloudAssets(assets, &error)) {
    std::fprintf(stderr, "clouds_voxel_opacity: %s\n", error.message.c_str());
    return {};
  }
  // The harness's camera: yaw 0 looks along -z, counter-clockwise from above; its field of
  // view is vertical.
  const glm::dvec3 forward = glm::normalize(camera.lookAt - camera.position);
  clouds::tools::CloudView view;
  view.position = camera.position;
  view.yawDegrees = glm::degrees(std::atan2(-forward.x, -forward.z));
  view.pitchDegrees = glm::degrees(std::asin(forward.y));
  const double halfWidth = std::tan(camera.fovDegrees * std::numbers::pi / 360.0);
  view.verticalFovDegrees = float(
      glm::degrees(2.0 * std::atan(halfWidth * double(camera.size.y) / double(camera.size.x))));
  view.heroClouds.push_back(clouds::HeroCloud{});
  clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  settings.coverage = 0.0f;
  settings.albedo = 0.0f;
  settings.extinctionPerMetre = float(extinctionPerMetre);
  settings.densityMultiplier = 1.0f;
  settings.transmittanceCutoff = 0.0f;
  settings.maxDistanceMetres = 1e7f;
  // The grid's density as it is, linear in its values: what vdb_render integrates.
  settings.heroDetail = clouds::HeroDetail::Off;
  const clouds::tools::CloudFrame frame = harness.render(view, settings, extent);
  if (instance.validationMessageCount() > 0) {
    std::fprintf(stderr, "clouds_voxel_opacity: %u Vulkan validation message(s)\n",
                 instance.validationMessageCount());
    return {};
  }
  std::vector<float> opacity;
  for (const glm::vec4& p : frame.radiance) opacity.push_back(1.0f - p.a);
  return opacity;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"clouds_voxel_opacity: a hero cloud's opacity, integrated exactly on the CPU"};
  std::string vdbFile;
  std::string nvdfFile;
  std::string gridName;
  std::string position = "0,0,0";
  std::string lookAt = "0,0,-1";
  std::string size = "160x90";
  double fovDegrees = 44.8;
  double extinctionPerMetre = 0.1;
  std::string output;
  auto* source = cli.add_option_group("source", "the cloud");
  source->add_option("--vdb", vdbFile, "OpenVDB file (world units are metres)");
  source->add_option("--nvdf", nvdfFile, "NVDF file (clouds/nvdf.h)");
  source->require_option(1);
  cli.add_option("--grid", gridName, "The VDB's float grid (default: \"density\", else the first)");
  cli.add_option("--camera-position", position, "Camera position X,Y,Z (m)");
  cli.add_option("--look-at", lookAt, "Point the camera looks at X,Y,Z (m), y up");
  cli.add_option("--fov-degrees", fovDegrees, "Horizontal field of view (degrees)")
      ->check(CLI::Range(0.1, 179.0));
  cli.add_option("--size", size, "Image size WxH (pixels)");
  cli.add_option("--extinction", extinctionPerMetre, "Extinction per metre per unit of density")
      ->check(CLI::Range(0.0, 1e6));
  cli.add_option("--opacity", output, "Output EXR")->required();
  bool gpu = false;
  cli.add_flag("--gpu", gpu,
               "Draw it with the clouds module's march on the Vulkan device (lavapipe by "
               "default), under validation, instead of the exact CPU integral");
  CLI11_PARSE(cli, argc, argv);

  clouds::reference::PinholeCamera camera;
  camera.fovDegrees = fovDegrees;
  if (!parseTriple(position, camera.position) || !parseTriple(lookAt, camera.lookAt) ||
      !parseSize(size, camera.size) || glm::length(camera.lookAt - camera.position) == 0.0) {
    std::fprintf(stderr,
                 "clouds_voxel_opacity: --camera-position and --look-at take X,Y,Z (two different "
                 "points), --size WxH (1 to 8192)\n");
    return 2;
  }

  clouds::Error error;
  std::optional<clouds::NvdfVolume> volume;
  if (!vdbFile.empty()) {
    clouds::VdbImportOptions options;
    options.gridName = gridName;
    clouds::VdbImportReport report;
    volume = clouds::importVdb(vdbFile, options, &report, &error);
    for (const std::string& warning : report.warnings) {
      std::fprintf(stderr, "warning: %s\n", warning.c_str());
    }
  } else {
    volume = clouds::readNvdf(nvdfFile, &error);
  }
  if (!volume) {
    std::fprintf(stderr, "clouds_voxel_opacity: %s\n", error.message.c_str());
    return 1;
  }

  std::vector<float> opacity;
  if (gpu) {
    try {
      opacity = gpuOpacity(*volume, camera, extinctionPerMetre);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "clouds_voxel_opacity: %s\n", e.what());
    }
    if (opacity.empty()) return 1;
  } else {
    opacity = clouds::reference::opacityImage(clouds::reference::NvdfSampler(*volume), camera,
                                              extinctionPerMetre);
  }
  engine::assets::ImageRgba32f image;
  image.width = camera.size.x;
  image.height = camera.size.y;
  image.pixels.reserve(4 * opacity.size());
  for (const float o : opacity) image.pixels.insert(image.pixels.end(), {o, o, o, o});
  try {
    engine::assets::writeExr(output, image);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clouds_voxel_opacity: %s\n", e.what());
    return 1;
  }
  return 0;
}
