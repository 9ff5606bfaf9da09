#include "lightning_bolts.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clouds::detail {
namespace {

// Pieces nearer than this (clip w: m along the view axis) are cut: a bolt through the camera's
// plane would project to infinity.
constexpr float kNearMetres = 1.0f;

// Cuts [t0, t1] of the 2D piece p + t d to where it lies within [lo, hi] (Liang-Barsky);
// false when none of it does.
bool clipToRect(glm::vec2 p, glm::vec2 d, glm::vec2 lo, glm::vec2 hi, float& t0, float& t1) {
  for (int axis = 0; axis < 2; ++axis) {
    const float edges[2] = {lo[axis] - p[axis], hi[axis] - p[axis]};
    if (std::abs(d[axis]) < 1e-12f) {
      if (edges[0] > 0.0f || edges[1] < 0.0f) return false;
      continue;
    }
    float a = edges[0] / d[axis];
    float b = edges[1] / d[axis];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

// A piece's pixels (with its margin), for binning.
struct PieceBox {
  glm::vec2 lo;
  glm::vec2 hi;
};

// The tiles each box touches on a grid of `side` px from `origin`, `columns` x `rows`.
glm::uvec4 tileSpan(const PieceBox& box, glm::vec2 origin, float side, glm::uvec2 grid) {
  const glm::vec2 lo = glm::floor((box.lo - origin) / side);
  const glm::vec2 hi = glm::floor((box.hi - origin) / side);
  const glm::vec2 last = glm::vec2(grid) - 1.0f;
  return glm::uvec4(glm::clamp(lo, glm::vec2(0.0f), last), glm::clamp(hi, glm::vec2(0.0f), last));
}

// Bins the pieces into square tiles over the bounds (from a multiple of 8 px, so that tiles
// are whole workgroups): 8 px, doubled until the grid and the indices fit their room; then lists
// the blocks of the tiles that hold pieces, on screen (`extent`).
void bin(ProjectedBolts& out, const std::vector<PieceBox>& boxes, glm::uvec2 extent) {
  const glm::vec2 origin = glm::floor(glm::vec2(out.header.bounds) / 8.0f) * 8.0f;
  out.header.bounds.x = origin.x;
  out.header.bounds.y = origin.y;
  const glm::vec2 size = glm::vec2(out.header.bounds.z, out.header.bounds.w) - origin;
  float side = 8.0f;
  glm::uvec2 grid;
  for (;; side *= 2.0f) {
    grid = glm::uvec2(glm::max(glm::ceil(size / side), glm::vec2(1.0f)));
    if (std::uint64_t{grid.x} * grid.y > shader::kBoltMaxTiles) continue;
    std::uint64_t indices = 0;
    for (const PieceBox& box : boxes) {
      const glm::uvec4 span = tileSpan(box, origin, side, grid);
      indices += std::uint64_t{span.z - span.x + 1} * (span.w - span.y + 1);
    }
    if (indices <= shader::kBoltMaxTileIndices) break;
  }
  std::vector<std::vector<std::uint32_t>> lists(std::size_t{grid.x} * grid.y);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const glm::uvec4 span = tileSpan(boxes[i], origin, side, grid);
    for (std::uint32_t y = span.y; y <= span.w; ++y) {
      for (std::uint32_t x = span.x; x <= span.z; ++x)
        lists[std::size_t{y} * grid.x + x].push_back(i);
    }
  }
  const glm::ivec2 lastBlock = (glm::ivec2(extent) - 1) / 8;
  const int blocksPerTile = int(side) / 8;
  for (std::size_t t = 0; t < lists.size(); ++t) {
    const std::vector<std::uint32_t>& list = lists[t];
    out.tiles.emplace_back(std::uint32_t(out.pieces.size()), std::uint32_t(list.size()));
    out.pieces.insert(out.pieces.end(), list.begin(), list.end());
    if (list.empty()) continue;
    const glm::ivec2 first =
        glm::ivec2(origin) / 8 + glm::ivec2(int(t % grid.x), int(t / grid.x)) * blocksPerTile;
    for (int by = std::max(first.y, 0); by < first.y + blocksPerTile && by <= lastBlock.y; ++by) {
      for (int bx = std::max(first.x, 0); bx < first.x + blocksPerTile && bx <= lastBlock.x; ++bx) {
        out.blocks.push_back(std::uint32_t(bx) | std::uint32_t(by) << 16);
      }
    }
  }
  if (out.blocks.size() > shader::kBoltMaxBlocks) out.blocks.clear();
  out.header.count.y = grid.x;
  out.header.count.z = grid.y;
  out.header.count.w = std::uint32_t(side);
  const auto pieceWords = std::uint32_t(out.segments.size() * 4);
  const auto indexWords = pieceWords + 2 * std::uint32_t(out.tiles.size());
  out.header.tiles =
      glm::uvec4(pieceWords, indexWords, indexWords + out.pieces.size(), out.blocks.size());
}

}  // namespace

std::vector<std::uint32_t> ProjectedBolts::words() const {
  // Whole quads of words: the shader reads four at a time.
  const std::size_t count = segments.size() * 4 + tiles.size() * 2 + pieces.size() + blocks.size();
  std::vector<std::uint32_t> w((count + 3) / 4 * 4, 0u);
  std::memcpy(w.data(), segments.data(), segments.size() * sizeof(glm::vec4));
  std::uint32_t* t = w.data() + segments.size() * 4;
  for (const glm::uvec2& tile : tiles) {
    *t++ = tile.x;
    *t++ = tile.y;
  }
  t = std::copy(pieces.begin(), pieces.end(), t);
  std::copy(blocks.begin(), blocks.end(), t);
  return w;
}

std::uint64_t boltBufferBytes(std::uint32_t segments) {
  if (segments == 0) return 0;
  return sizeof(shader::LightningBoltsHeader) +
         sizeof(std::uint32_t) *
             (std::uint64_t{shader::kBoltWordsPerSegment} * segments +
              2 * std::uint64_t{shader::kBoltMaxTiles} + shader::kBoltMaxTileIndices +
              shader::kBoltMaxBlocks + 3);  // + whole quads
}

ProjectedBolts projectBolts(const FrameInputs& inputs) {
  ProjectedBolts out;
  const glm::vec2 extent(float(inputs.renderExtent.width), float(inputs.renderExtent.height));
  const glm::mat3 rotation(inputs.view);
  // Pixels per unit of view-space height at clip w = 1 (a width at clip w is focal / w px).
  const float focal = 0.5f * extent.y * std::abs(inputs.projection[1][1]);
  const glm::mat4& p = inputs.projection;
  out.header.clipWRow = glm::vec4(p[0][3], p[1][3], p[2][3], focal);
  glm::vec2 lo(1e30f);
  glm::vec2 hi(-1e30f);
  std::vector<PieceBox> boxes;
  for (const LightningBoltSegment& bolt : inputs.lightningBolts) {
    glm::vec4 clip[2];
    const glm::dvec3 worldEnds[2] = {bolt.fromMetres, bolt.toMetres};
    for (int e = 0; e < 2; ++e) {
      const glm::vec3 relative(worldEnds[e] - inputs.cameraPosition);
      clip[e] = p * glm::vec4(rotation * relative, 1.0f);
    }
    // In front of the camera only: cut at w = kNearMetres (clip space is linear in the world).
    if (clip[0].w < kNearMetres && clip[1].w < kNearMetres) continue;
    for (int e = 0; e < 2; ++e) {
      if (clip[e].w >= kNearMetres) continue;
      const glm::vec4 other = clip[1 - e];
      clip[e] = glm::mix(clip[e], other, (kNearMetres - clip[e].w) / (other.w - clip[e].w));
    }
    glm::vec2 pixel[2];
    float inverseW[2];
    for (int e = 0; e < 2; ++e) {
      inverseW[e] = 1.0f / clip[e].w;
      pixel[e] = (glm::vec2(clip[e]) * inverseW[e] * 0.5f + 0.5f) * extent;
    }
    // What is on screen, with a margin of the line's half width and its one-pixel filter.
    const float widest = bolt.widthMetres * focal * std::max(inverseW[0], inverseW[1]);
    const float margin = 0.5f * std::max(widest, 1.0f) + 1.0f;
    float t0 = 0.0f;
    float t1 = 1.0f;
    if (!clipToRect(pixel[0], pixel[1] - pixel[0], glm::vec2(-margin), extent + margin, t0, t1)) {
      continue;
    }
    // The quantities the shader interpolates along the piece, cut with it.
    const auto at = [](const float(&v)[2], float t) { return v[0] + (v[1] - v[0]) * t; };
    const glm::vec2 a = glm::mix(pixel[0], pixel[1], t0);
    const glm::vec2 b = glm::mix(pixel[0], pixel[1], t1);
    out.segments.emplace_back(a, b);
    out.segments.emplace_back(at(inverseW, t0), at(inverseW, t1), bolt.widthMetres, 0.0f);
    out.segments.emplace_back(bolt.radiance, 0.0f);
    boxes.push_back({glm::min(a, b) - margin, glm::max(a, b) + margin});
    lo = glm::min(lo, boxes.back().lo);
    hi = glm::max(hi, boxes.back().hi);
  }
  out.header.count.x = static_cast<std::uint32_t>(boxes.size());
  if (boxes.empty()) return out;
  out.header.bounds = glm::vec4(lo, hi);
  bin(out, boxes, glm::uvec2(inputs.renderExtent.width, inputs.renderExtent.height));
  return out;
}

}  // namespace clouds::detail
