#pragma once
// The terrain on the GPU: one vertex and index buffer, the triangles sorted into a grid of
// chunks with bounding boxes so each frame draws only the chunks in the view frustum, and a
// depth-tested (reversed-Z) graphics pipeline lit by the sun and sky and hazed by the
// atmosphere's aerial perspective, or by distance fog in scenes without one.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "engine/assets/gltf_loader.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"

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
  // `aerialPerspective`: hazed by a feature's aerial perspective (else by the fog).
  TerrainRenderer(engine::gfx::Device& device, const engine::assets::MeshData& mesh,
                  VkFormat hdrFormat, VkFormat depthFormat, bool aerialPerspective);

  const engine::gfx::Pipeline& pipeline() const { return pipeline_; }
  bool hazedByAerialPerspective() const { return aerialPerspective_; }
  VkSampler hazeSampler() const { return sampler_.vk(); }
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
  std::vector<IndexRange> visible_;  // this frame's draws; capacity reserved once
  std::size_t visibleCount_ = 0;
  bool aerialPerspective_ = false;
  engine::gfx::Sampler sampler_;  // the aerial perspective's: linear, clamped
  engine::gfx::Pipeline pipeline_;
};

}  // namespace sample
