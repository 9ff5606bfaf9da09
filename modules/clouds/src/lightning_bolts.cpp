#include "lightning_bolts.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

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
    lo = glm::min(lo, glm::min(a, b) - margin);
    hi = glm::max(hi, glm::max(a, b) + margin);
  }
  out.header.count.x =
      static_cast<std::uint32_t>(out.segments.size() / shader::kBoltVec4sPerSegment);
  out.header.bounds = out.header.count.x > 0 ? glm::vec4(lo, hi) : glm::vec4(0.0f);
  return out;
}

}  // namespace clouds::detail
