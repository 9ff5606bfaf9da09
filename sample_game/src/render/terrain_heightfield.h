#pragma once
// The terrain's surface as a heightfield image on the GPU (R32F, sampled linearly), made once
// from the mesh: what the clouds module walks to find where mountains hide the sun (from the
// clouds, and from the terrain itself through the cloud shadow map). Published to the world as
// engine::render::TerrainHeightfield while it lives.
#include "engine/assets/gltf_loader.h"
#include "engine/gfx/resources.h"
#include "engine/render/scene_components.h"

namespace sample {

class TerrainHeightfieldImage {
 public:
  // Texels per side: 512 over the default 40 km terrain is 78 m, the finest shadow cascade's
  // texel at Medium.
  static constexpr std::uint32_t kResolution = 512;

  TerrainHeightfieldImage(engine::gfx::Device& device, const engine::assets::MeshData& mesh);
  const engine::render::TerrainHeightfield& description() const { return description_; }

 private:
  engine::gfx::Image image_;
  engine::render::TerrainHeightfield description_;
};

}  // namespace sample
