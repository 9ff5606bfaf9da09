#include "render/terrain_renderer.h"

#include "render/scene_surface.h"
#include "render/terrain_sunlight.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "engine/gfx/upload.h"
#include "sample_shaders/terrain.frag.spv.h"
#include "sample_shaders/terrain.vert.spv.h"
#include "sample_shaders/terrain_hazed.frag.spv.h"
#include "sample_shaders/terrain_hazed.vert.spv.h"
#include "sample_shaders/terrain_hazed_shadowed.frag.spv.h"
#include "sample_shaders/terrain_hazed_shadowed.vert.spv.h"
#include "sample_shaders/terrain_shadowed.frag.spv.h"
#include "sample_shaders/terrain_shadowed.vert.spv.h"

namespace sample {

using namespace engine;

namespace {

struct TerrainVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
  glm::vec2 uv;  // the base colour texture's (TEXCOORD_0; 0 without one)
};
static_assert(sizeof(TerrainVertex) == 44);

}  // namespace

namespace {

// For every vertex, the vertex that represents its cell of a `cell`-metre grid (the first one
// met), or itself when `cell` is 0.
std::vector<std::uint32_t> clusterRepresentatives(const assets::MeshData& mesh, float cell) {
  std::vector<std::uint32_t> representative(mesh.positions.size());
  if (cell <= 0.0f) {
    for (std::uint32_t i = 0; i < representative.size(); ++i) representative[i] = i;
    return representative;
  }
  std::unordered_map<std::uint64_t, std::uint32_t> cells;
  cells.reserve(mesh.positions.size());
  for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 q = glm::floor(mesh.positions[i] / cell);
    const auto key = (std::uint64_t(std::uint32_t(std::int32_t(q.x)) & 0x1fffff) << 42) |
                     (std::uint64_t(std::uint32_t(std::int32_t(q.y)) & 0x1fffff) << 21) |
                     std::uint64_t(std::uint32_t(std::int32_t(q.z)) & 0x1fffff);
    representative[i] = cells.emplace(key, i).first->second;
  }
  return representative;
}

}  // namespace

std::vector<TerrainChunk> buildChunks(const assets::MeshData& mesh,
                                      std::vector<std::uint32_t>& indices, std::uint32_t grid,
                                      const std::array<float, kTerrainLods>& lodCellMetres) {
  const glm::vec2 lo(mesh.boundsMin.x, mesh.boundsMin.z);
  const glm::vec2 size =
      glm::max(glm::vec2(mesh.boundsMax.x, mesh.boundsMax.z) - lo, glm::vec2(1e-3f));
  std::vector<std::vector<std::uint32_t>> buckets(std::size_t{grid} * grid);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 centroid =
        (mesh.positions[mesh.indices[t]] + mesh.positions[mesh.indices[t + 1]] +
         mesh.positions[mesh.indices[t + 2]]) /
        3.0f;
    const glm::vec2 uv = (glm::vec2(centroid.x, centroid.z) - lo) / size;
    const auto cx =
        std::min(static_cast<std::uint32_t>(std::max(uv.x, 0.0f) * float(grid)), grid - 1);
    const auto cz =
        std::min(static_cast<std::uint32_t>(std::max(uv.y, 0.0f) * float(grid)), grid - 1);
    auto& bucket = buckets[std::size_t{cz} * grid + cx];
    bucket.insert(bucket.end(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(t),
                  mesh.indices.begin() + static_cast<std::ptrdiff_t>(t + 3));
  }
  std::array<std::vector<std::uint32_t>, kTerrainLods> representatives;
  for (std::size_t l = 0; l < kTerrainLods; ++l) {
    representatives[l] = clusterRepresentatives(mesh, lodCellMetres[l]);
  }
  std::vector<TerrainChunk> chunks;
  indices.clear();
  for (const auto& bucket : buckets) {
    if (bucket.empty()) continue;
    TerrainChunk chunk;
    chunk.boundsMin = glm::vec3(std::numeric_limits<float>::max());
    chunk.boundsMax = glm::vec3(std::numeric_limits<float>::lowest());
    for (std::uint32_t i : bucket) {
      chunk.boundsMin = glm::min(chunk.boundsMin, mesh.positions[i]);
      chunk.boundsMax = glm::max(chunk.boundsMax, mesh.positions[i]);
    }
    for (std::size_t l = 0; l < kTerrainLods; ++l) {
      chunk.lods[l].firstIndex = static_cast<std::uint32_t>(indices.size());
      const auto& rep = representatives[l];
      for (std::size_t t = 0; t + 2 < bucket.size(); t += 3) {
        const std::uint32_t a = rep[bucket[t]];
        const std::uint32_t b = rep[bucket[t + 1]];
        const std::uint32_t c = rep[bucket[t + 2]];
        if (a == b || b == c || a == c) continue;  // collapsed by the clustering
        indices.insert(indices.end(), {a, b, c});
      }
      chunk.lods[l].indexCount =
          static_cast<std::uint32_t>(indices.size()) - chunk.lods[l].firstIndex;
    }
    chunks.push_back(chunk);
  }
  return chunks;
}

std::size_t lodForDistance(float distanceMetres) {
  // Chosen for the generated 40 km terrain at 640x360: beyond ~4 km a full-detail triangle is
  // smaller than a couple of pixels.
  if (distanceMetres < 4000.0f) return 0;
  return distanceMetres < 11000.0f ? 1 : 2;
}

bool boxInFrustum(const glm::mat4& m, const glm::vec3& lo, const glm::vec3& hi) {
  // Planes from the rows of the matrix (Gribb & Hartmann): left, right, bottom, top, near.
  // Reversed-Z with an infinite far plane has no far plane to test.
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]);
  const glm::vec4 row1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::vec4 row2(m[0][2], m[1][2], m[2][2], m[3][2]);
  const glm::vec4 row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  const glm::vec4 planes[5] = {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row3 - row2};
  for (const glm::vec4& p : planes) {
    // The box corner furthest along the plane normal.
    const glm::vec3 corner(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
    if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return false;
  }
  return true;
}

TerrainRenderer::TerrainRenderer(gfx::Device& device, const assets::MeshData& mesh,
                                 VkFormat hdrFormat, VkFormat depthFormat, bool aerialPerspective,
                                 bool cloudShadows, bool lightning, bool closeDetail)
    : aerialPerspective_(aerialPerspective),
      cloudShadows_(cloudShadows),
      baseColour_(device, mesh.baseColorTexture) {
  std::vector<TerrainVertex> vertices(mesh.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::vec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
    vertices[i] = {mesh.positions[i], mesh.normals[i], glm::vec3(mesh.colors[i]), uv};
  }
  // Levels of detail from the mesh's own density: clusters of about 2.5 and 6 average edges.
  float edgeSum = 0.0f;
  std::size_t edgeCount = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3 * 97) {  // a sample is plenty
    edgeSum += glm::distance(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]]);
    ++edgeCount;
  }
  const float edge = edgeCount > 0 ? edgeSum / float(edgeCount) : 1.0f;
  std::vector<std::uint32_t> indices;
  chunks_ = buildChunks(mesh, indices, 8, {0.0f, 2.5f * edge, 6.0f * edge});
  visible_.resize(chunks_.size());

  vertices_ = gfx::Buffer(
      device, gfx::BufferDesc{vertices.size() * sizeof(TerrainVertex),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gfx::MemoryUsage::GpuOnly, "terrain vertices"});
  indices_ = gfx::Buffer(
      device, gfx::BufferDesc{indices.size() * sizeof(std::uint32_t),
                              VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gfx::MemoryUsage::GpuOnly, "terrain indices"});
  gfx::uploadToBuffer(device, vertices_, std::as_bytes(std::span(vertices)));
  gfx::uploadToBuffer(device, indices_, std::as_bytes(std::span(indices)));

  using Spirv = std::span<const std::uint32_t>;
  gfx::GraphicsPipelineDesc desc;
  // The shader variants (terrain_vertex.glsl, terrain_fragment.glsl): hazed or fogged, with or
  // without cloud shadows.
  if (aerialPerspective) {
    desc.vertexSpirv =
        cloudShadows ? Spirv(terrain_hazed_shadowed_vert_spv) : Spirv(terrain_hazed_vert_spv);
    desc.fragmentSpirv =
        cloudShadows ? Spirv(terrain_hazed_shadowed_frag_spv) : Spirv(terrain_hazed_frag_spv);
  } else {
    desc.vertexSpirv = cloudShadows ? Spirv(terrain_shadowed_vert_spv) : Spirv(terrain_vert_spv);
    desc.fragmentSpirv = cloudShadows ? Spirv(terrain_shadowed_frag_spv) : Spirv(terrain_frag_spv);
  }
  desc.bindings = {
      {kFrameBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
      {kBaseColourBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, TerrainTexture::kFormat,
       VK_IMAGE_VIEW_TYPE_2D, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT}};
  if (aerialPerspective || cloudShadows) {
    gfx::SamplerDesc clamped;
    clamped.debugName = "terrain linear clamped";
    sampler_ = gfx::Sampler(device, clamped);
  }
  // (Both faces: user meshes come with either winding.)
  describeSceneSurface(desc, hdrFormat, depthFormat, aerialPerspective, kHazeBinding, cloudShadows,
                       kSunlightBinding);
  desc.vertexBindings = {{0, sizeof(TerrainVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(TerrainVertex, position)},
                           {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(TerrainVertex, normal)},
                           {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(TerrainVertex, color)},
                           {5, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(TerrainVertex, uv)}};
  const std::uint32_t textured = baseColour_.present() ? 1u : 0u;
  const std::uint32_t detailed = closeDetail ? 1u : 0u;
  desc.specialization = {{kTexturedConstant, textured}, {kCloseDetailConstant, detailed}};
  desc.debugName = cloudShadows ? "terrain (cloud shadows)" : "terrain";
  pipelines_ = FlashVariants(device, desc, kLightningConstant, lightning);
}

void TerrainRenderer::cull(const glm::mat4& viewProjection, const glm::dvec3& cameraPosition) {
  visibleCount_ = 0;
  for (const TerrainChunk& chunk : chunks_) {
    const glm::vec3 lo = glm::vec3(glm::dvec3(chunk.boundsMin) - cameraPosition);
    const glm::vec3 hi = glm::vec3(glm::dvec3(chunk.boundsMax) - cameraPosition);
    if (!boxInFrustum(viewProjection, lo, hi)) continue;
    // Distance from the camera (the origin here) to the nearest point of the box.
    const float distance = glm::length(glm::max(glm::max(lo, -hi), glm::vec3(0.0f)));
    visible_[visibleCount_++] = {distance, chunk.lods[lodForDistance(distance)]};
  }
  // Nearest first: the depth test then rejects what is hidden before it is shaded (a CPU
  // rasteriser pays for every fragment it shades).
  std::sort(visible_.begin(), visible_.begin() + std::ptrdiff_t(visibleCount_),
            [](const VisibleChunk& a, const VisibleChunk& b) { return a.distance < b.distance; });
}

std::uint64_t TerrainRenderer::visibleTriangles() const {
  std::uint64_t triangles = 0;
  for (std::size_t v = 0; v < visibleCount_; ++v) triangles += visible_[v].range.indexCount / 3;
  return triangles;
}

void TerrainRenderer::draw(VkCommandBuffer cmd) const {
  const VkBuffer vertexBuffer = vertices_.vk();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
  vkCmdBindIndexBuffer(cmd, indices_.vk(), 0, VK_INDEX_TYPE_UINT32);
  for (std::size_t v = 0; v < visibleCount_; ++v) {
    const IndexRange& range = visible_[v].range;
    vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
  }
}

}  // namespace sample
