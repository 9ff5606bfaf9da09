#pragma once
// The terrain's sunlight map (shaders/terrain_sunlight_map.h) and the "terrain sunlight" pass that
// keeps it: after the clouds' shadow map is made and before the scene is drawn, the rows due
// this frame read the share of the sun that reaches the terrain's surface past the clouds and
// past the terrain itself; the terrain's fragments then read it with one filtered fetch.
//
// Why a map in the terrain's own space rather than the shadow map's lookup per fragment: the
// lookup (cascade selection and blending, the terrain channel's percentage-closer filter) per
// fragment and per vertex cost the scene pass 2.4 ms a frame at 640x360 on lavapipe, the fetch
// about 0.35 ms. The map's texels are the heightfield's (78 m over the default 40 km terrain), as
// fine as the shadow map's finest cascade at every preset up to High, so nothing is lost.
//
// Refresh: the whole map at its first frame and whenever the clouds' map was remade whole (a
// camera cut, a settings or weather change, a sun that turned), else one band of rows per frame,
// the whole map every kRefreshFrames frames. A texel holds the shadow as it was when its band
// was refreshed: at the default wind (12 m/s) a cloud's shadow lags by at most 13 m at 30 fps,
// a sixth of a texel. (A band of 1/32 of the rows costs 0.23 ms a frame, 1/16 0.39 ms.) Each texel
// is a world place, not a camera-relative one, so moving the camera makes no texel stale.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "engine/render/frame_graph.h"
#include "engine/render/scene_components.h"

namespace sample {

// Which rows of the map each frame refreshes (pure bookkeeping, unit-tested): all of them at
// the first frame and when the clouds' map was remade whole, else the next of `frames` bands
// of rows in turn.
class TerrainSunlightSchedule {
 public:
  struct Rows {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  TerrainSunlightSchedule(std::uint32_t rows, std::uint32_t frames);
  Rows next(bool shadowMapRemadeWhole);

 private:
  std::uint32_t rows_;
  std::uint32_t rowsPerBand_;
  std::uint32_t bands_;
  bool filled_ = false;     // the whole map has been made once
  std::uint32_t band_ = 0;  // the band the next partial refresh makes
};

class TerrainSunlight {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R16_SFLOAT;
  // Frames over which the bands refresh the whole map.
  static constexpr std::uint32_t kRefreshFrames = 32;

  // Over the heightfield's grid (`heightfield.view` must stay valid while this lives).
  // Throws engine::Error when the device cannot store or filter kFormat.
  TerrainSunlight(engine::gfx::Device& device,
                  const engine::render::TerrainHeightfield& heightfield, std::uint32_t resolution);

  const engine::gfx::Pipeline& pipeline() const { return pipeline_; }
  // SceneFrame::sunlightMap for a camera at `cameraPosition` (world, m): the camera's place in
  // the map ([0, 1] per axis) and the map's reciprocal size (1/m).
  glm::vec4 placementFor(const glm::dvec3& cameraPosition) const;

  // Imports the map and adds the pass that refreshes the rows due (reading the blackboard's
  // fxcontracts::ecs::CloudShadow, its parameters when the pass executes, as `cameraPosition`);
  // returns the map for the scene to read. Without a cloud shadow map in the frame (the
  // player turned the clouds' shadows off) the map is made lit once, by a pass that then has
  // nothing to do: the graph is rebuilt without it (see spentPass()).
  engine::render::TextureHandle addPass(engine::render::FrameGraph& graph,
                                        const glm::dvec3* cameraPosition);
  // The graph holds a pass that has done its work and records nothing more.
  bool spentPass() const { return litPassInGraph_ && lit_; }

 private:
  engine::render::TextureHandle addLitPass(engine::render::FrameGraph& graph,
                                           engine::render::TextureHandle map);

  engine::render::TerrainHeightfield heightfield_;
  std::uint32_t resolution_;
  engine::gfx::Image image_;
  engine::gfx::Sampler sampler_;
  engine::gfx::Pipeline pipeline_;
  TerrainSunlightSchedule schedule_;
  bool lit_ = true;  // the map holds full sun everywhere
  bool litPassInGraph_ = false;
};

}  // namespace sample
