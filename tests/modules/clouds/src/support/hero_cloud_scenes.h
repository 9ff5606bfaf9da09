#pragma once
// The hero-cloud tests' scenes: a lumpy test cumulus, its placement ahead of the camera, the
// canonical views (outside at noon, grazing towards the sun, inside, with the layer), and the
// comparison of a GPU frame with the CPU reference of the same frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "cloud_harness.h"
#include "clouds/clouds.h"
#include "clouds/nvdf_build.h"
#include "context_access.h"
#include "cpu_reference.h"
#include "hero_clouds.h"
#include "hero_light_volume.h"

namespace test {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;

// A lumpy cumulus 1.2 km wide and 1 km tall in 25 m voxels, its base centred on its frame's
// origin.
inline const clouds::NvdfVolume& cumulus() {
  static const clouds::NvdfVolume volume = [] {
    clouds::VoxelDensityGrid grid;
    grid.size = glm::uvec3(48, 40, 48);
    grid.voxelMetres = 25.0f;
    grid.originMetres = glm::vec3(-23.5f * 25.0f, 0.0f, -23.5f * 25.0f);
    grid.density.resize(std::size_t(48) * 40 * 48);
    grid.detailType.resize(grid.density.size());
    for (unsigned z = 0; z < 48; ++z) {
      for (unsigned y = 0; y < 40; ++y) {
        for (unsigned x = 0; x < 48; ++x) {
          const glm::vec3 p = (glm::vec3(x, y, z) - glm::vec3(23.5f, 16.0f, 23.5f)) / 20.0f;
          const float lumps = 0.15f * std::sin(3.0f * p.x) * std::sin(2.5f * p.y + 1.0f) *
                              std::sin(3.5f * p.z + 2.0f);
          const float inside = 1.0f - glm::length(p * glm::vec3(1.0f, 1.15f, 1.0f)) + lumps;
          const std::size_t i = (std::size_t(z) * 40 + y) * 48 + x;
          grid.density[i] = std::clamp(inside * 3.0f, 0.0f, 1.0f);
          grid.detailType[i] = float(y) / 39.0f;
        }
      }
    }
    clouds::Error error;
    std::optional<clouds::NvdfVolume> built = clouds::buildNvdf(grid, {}, &error);
    EXPECT_TRUE(built) << error.message;
    return *built;
  }();
  return volume;
}

// The cumulus, half as large again, 2.5 km ahead of a camera at the origin looking along -z,
// its base at 1.5 km.
inline clouds::HeroCloud aheadOfTheCamera() {
  clouds::HeroCloud cloud;
  cloud.positionMetres = {0.0, 1500.0, -2500.0};
  cloud.scale = 1.5f;
  cloud.yawRadians = 0.4f;
  return cloud;
}

// Settings whose layer holds no cloud: the picture is the hero cloud's.
inline clouds::Settings heroOnly() {
  clouds::Settings s;
  s.coverage = 0.0f;
  return s;
}

struct HeroView {
  const char* name;
  CloudView view;
  clouds::Settings settings;
};

inline std::vector<HeroView> heroViews() {
  std::vector<HeroView> views;
  CloudView noon;
  noon.position = {0.0, 2100.0, 0.0};
  noon.yawDegrees = 0.0;
  noon.pitchDegrees = 0.0;
  noon.sunElevationDegrees = 80.0;
  noon.heroClouds = {aheadOfTheCamera()};
  views.push_back({"outside at noon", noon, heroOnly()});
  CloudView grazing = noon;
  grazing.sunElevationDegrees = 4.0;
  grazing.sunAzimuthDegrees = 10.0;
  grazing.sunIlluminance = {9.0f, 5.0f, 2.5f};
  views.push_back({"grazing towards the sun", grazing, heroOnly()});
  CloudView inside = noon;
  inside.position = {30.0, 2100.0, -2450.0};
  inside.yawDegrees = 30.0;
  views.push_back({"inside", inside, heroOnly()});
  CloudView layer = noon;
  layer.position = {0.0, 800.0, 0.0};
  layer.pitchDegrees = 14.0;
  views.push_back({"with the layer", layer, clouds::Settings{}});
  return views;
}

class Assets {
 public:
  explicit Assets(clouds::Context& context) : context_(context) {
    const clouds::NvdfVolume* list[] = {&cumulus()};
    clouds::Error error;
    EXPECT_TRUE(context_.setHeroCloudAssets(list, &error)) << error.message;
  }
  ~Assets() { context_.setHeroCloudAssets({}, nullptr); }

 private:
  clouds::Context& context_;
};

// The cumulus's atlas, packed once.
inline const clouds::detail::HeroAtlasLayout& cumulusAtlas() {
  static const clouds::detail::HeroAtlasLayout layout = [] {
    const clouds::NvdfVolume* list[] = {&cumulus()};
    return clouds::detail::packHeroAtlas(list);
  }();
  return layout;
}

// The cumulus's atlas as the CPU reference reads it, with `uniforms` placing it.
inline clouds::tools::CpuHeroClouds cumulusOnTheCpu(
    const clouds::shader::HeroCloudUniforms& uniforms) {
  const clouds::detail::HeroAtlasLayout& layout = cumulusAtlas();
  clouds::tools::CpuHeroClouds heroes;
  heroes.atlas = layout.texels;
  heroes.extent = glm::uvec3(layout.extent.width, layout.extent.height, layout.extent.depth);
  heroes.uniforms = uniforms;
  return heroes;
}

// `cloud` (the cumulus) placed for a camera at `camera`, its light volume's slot assigned, as
// the CPU reference's textures (no layer's: add them for a march).
inline clouds::tools::CpuTextures cumulusPlaced(const clouds::HeroCloud& cloud,
                                                const glm::dvec3& camera = glm::dvec3(0.0)) {
  const clouds::detail::HeroAtlasLayout& layout = cumulusAtlas();
  const clouds::HeroCloud clouds[] = {cloud};
  clouds::shader::HeroCloudUniforms block =
      clouds::detail::heroCloudUniforms(layout.assets, clouds, camera);
  clouds::detail::HeroLightSlots slots;
  slots.assign(block, glm::vec3(0.0f, 1.0f, 0.0f));
  block.count.z = clouds::detail::heroLightSlotExtentCode(layout.assets);
  clouds::tools::CpuTextures textures;
  textures.heroes = cumulusOnTheCpu(block);
  return textures;
}

inline clouds::tools::CpuTextures withHeroes(clouds::tools::CpuTextures textures,
                                             const clouds::Context::Impl& impl) {
  std::vector<std::uint8_t> noise = std::move(textures.heroes.noise);
  textures.heroes = cumulusOnTheCpu(impl.lastHeroClouds());
  textures.heroes.noise = std::move(noise);
  return textures;
}

// The CPU reference of the frame `harness` last rendered (`gpu`), and the PSNR between them.
struct CpuComparison {
  CloudFrame cpu;
  double psnr = 0.0;
};
inline CpuComparison againstTheCpu(clouds::tools::CloudHarness& harness,
                                   const clouds::Context::Impl& impl, const CloudFrame& gpu,
                                   const clouds::Settings& settings) {
  const clouds::tools::CpuTextures textures =
      withHeroes(clouds::tools::readTextures(harness), impl);
  CpuComparison c;
  c.cpu = clouds::tools::renderCpuReference(textures, impl.lastUniforms(), settings,
                                            harness.lastDepth());
  float peak = 1.0f;
  for (const glm::vec4& p : c.cpu.radiance) peak = std::max({peak, p.r, p.g, p.b});
  c.psnr = clouds::tools::psnr(gpu.radiance, c.cpu.radiance, peak);
  return c;
}

}  // namespace test
