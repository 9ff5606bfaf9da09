#pragma once
// The terrain on the GPU: one vertex and index buffer, the triangles sorted into a grid of
// chunks with bounding boxes so each frame draws only the chunks in the view frustum, and a
// depth-tested (reversed-Z) graphics pipeline lit by the sun (through the clouds' shadow map
// in scenes whose clouds cast shadows) and sky, and hazed by the atmosphere's aerial
// perspective, or by distance fog in scenes without one.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "bindings.h"
#include "engine/assets/gltf_loader.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "render/scene_surface.h"
#include "render/terrain_materials.h"
#include "render/terrain_texture.h"
#include "terrain_material.h"

namespace sample {

inline constexpr std::size_t kTerrainLods = 3;

struct IndexRange {
  std::uint32_t firstIndex = 0;
  std::uint32_t indexCount = 0;
};

struct TerrainChunk {
  std::array<IndexRange, kTerrainLods> lods{};  // 0 full detail, then coarser
  glm::vec3 boundsMin{0.0f};
  glm::vec3 boundsMax{0.0f};
};

// Sorts triangles into a grid x grid of chunks by centroid and builds coarser levels of detail
// for each by vertex clustering (Rossignac & Borrel 1993: vertices snapped to a global grid of
// `lodCellMetres[l]` collapse onto one representative; degenerate triangles vanish). The grid
// is global, so neighbouring chunks at the same level agree along their border. Works for any
// mesh (pure; tested). Writes all levels' indices into `indices`.
std::vector<TerrainChunk> buildChunks(const engine::assets::MeshData& mesh,
                                      std::vector<std::uint32_t>& indices, std::uint32_t grid,
                                      const std::array<float, kTerrainLods>& lodCellMetres);

// Level of detail for a chunk at `distanceMetres` from the camera.
std::size_t lodForDistance(float distanceMetres);

// True when the box may be visible: tests it against the six planes of `viewProjection`
// (camera-relative world -> clip, reversed-Z with an infinite far plane).
bool boxInFrustum(const glm::mat4& viewProjection, const glm::vec3& boundsMin,
                  const glm::vec3& boundsMax);

class TerrainRenderer {
 public:
  // Descriptor bindings of the terrain pipeline (shaders/bindings.h).
  static constexpr std::uint32_t kFrameBinding = engine::shaders::kTerrainFrameBinding;
  static constexpr std::uint32_t kHazeBinding = engine::shaders::kTerrainHazeBinding;
  static constexpr std::uint32_t kSunlightBinding = engine::shaders::kTerrainSunlightBinding;
  static constexpr std::uint32_t kBaseColourBinding = engine::shaders::kTerrainBaseColourBinding;
  // Specialization constants: 1 lights the terrain with the brightest flash in progress; 1
  // colours it with the mesh's base colour texture (a user's glTF that has one); 1 gives it its
  // close-up detail (TerrainDescription::closeDetail).
  static constexpr std::uint32_t kLightningConstant = 0;
  static constexpr std::uint32_t kTexturedConstant = 1;
  static constexpr std::uint32_t kCloseDetailConstant = 2;

  // `aerialPerspective`: hazed by a feature's aerial perspective (else by the fog).
  // `cloudShadows`: lit through the clouds and past the terrain's own shadow as the terrain's
  // sunlight map (TerrainSunlight) holds them.
  // `lightning`: a storm's flashes light it (SceneFrame::flash): a second pipeline, the variant
  // with that code, drawn with in the frames with a flash in progress (setFlashing()).
  // `closeDetail`: the ground's close-up detail (else its code is compiled out).
  TerrainRenderer(engine::gfx::Device& device, const engine::assets::MeshData& mesh,
                  VkFormat hdrFormat, VkFormat depthFormat, bool aerialPerspective,
                  bool cloudShadows, bool lightning, bool closeDetail);

  // This frame's pipeline: the lightning variant only while a flash is in progress, so that a
  // storm costs the terrain nothing between its flashes.
  const engine::gfx::Pipeline& pipeline() const { return pipelines_.current(); }
  // Every pipeline it may draw with (to warm up and to describe).
  std::vector<const engine::gfx::Pipeline*> pipelines() const { return pipelines_.all(); }
  // Whether this frame has a flash in progress (SceneFrame::flashRadiance is not 0).
  void setFlashing(bool flashing) { pipelines_.setFlashing(flashing); }
  bool hazedByAerialPerspective() const { return aerialPerspective_; }
  bool shadowedByClouds() const { return cloudShadows_; }
  // Linear, clamped: the aerial perspective's and the sunlight map's.
  VkSampler linearSampler() const { return sampler_.vk(); }
  // The mesh's base colour texture (or its one-texel stand-in) and its trilinear sampler.
  const TerrainTexture& baseColour() const { return baseColour_; }
  // Frustum culling for this frame (camera-relative view-projection and camera position).
  void cull(const glm::mat4& viewProjection, const glm::dvec3& cameraPosition);
  void draw(VkCommandBuffer cmd) const;
  std::size_t chunkCount() const { return chunks_.size(); }
  std::size_t visibleChunkCount() const { return visibleCount_; }
  std::uint64_t visibleTriangles() const;

 private:
  engine::gfx::Buffer vertices_;
  engine::gfx::Buffer indices_;
  std::vector<TerrainChunk> chunks_;
  struct VisibleChunk {
    float distance = 0.0f;  // m, from the camera to the chunk's box
    IndexRange range;
  };
  std::vector<VisibleChunk> visible_;  // this frame's draws, nearest first; sized once
  std::size_t visibleCount_ = 0;
  bool aerialPerspective_ = false;
  bool cloudShadows_ = false;
  TerrainTexture baseColour_;
  engine::gfx::Sampler sampler_;
  FlashVariants pipelines_;
};

}  // namespace sample
