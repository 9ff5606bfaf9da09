#pragma once
// The minimal host's own reading of the clouds' shadow map, written from the module's
// documentation alone (clouds.h, ShadowMapParameters and Outputs::shadowMap), as another
// engine would: the atlas read back to the CPU, then per lit point of the host's scene the
// finest cascade that holds it, a bilinear read and Beer's law. (An engine with shaders would
// include fxcontracts/cloud_shadow.h instead, which also blends cascades and reads the terrain
// channel.)
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "clouds/clouds.h"

struct GroundShadow {
  std::uint32_t width = 0;  // the atlas: cascades side by side
  std::uint32_t height = 0;
  std::vector<glm::vec4> texels;  // RGBA16F texels as floats, row-major
  clouds::ShadowMapParameters parameters;

  // The clouds' transmittance towards the sun at a camera-relative position (m); 1 where no
  // cascade reaches.
  float transmittance(const glm::vec3& relative) const {
    const glm::vec4& info = parameters.info;
    const int cascades = static_cast<int>(info.x);
    const float n = info.y;
    for (int c = 0; c < cascades; ++c) {
      const glm::vec4& u = parameters.cascade[3 * c];
      const glm::vec4& v = parameters.cascade[3 * c + 1];
      const glm::vec4& l = parameters.cascade[3 * c + 2];
      const glm::vec2 uv = glm::vec2(glm::dot(glm::vec3(u), relative) - u.w,
                                     glm::dot(glm::vec3(v), relative) - v.w) *
                           l.w;
      if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) continue;
      // Half a texel inside the cascade, so the filter never reads its neighbour.
      const glm::vec2 inside = glm::clamp(uv, glm::vec2(0.5f / n), glm::vec2(1.0f - 0.5f / n));
      const glm::vec4 t = bilinear(glm::vec2((float(c) + inside.x) / float(cascades), inside.y));
      const float altitude = info.z + relative.y;
      const float share = glm::clamp((t.y - altitude) / std::max(t.y - t.z, 1.0f), 0.0f, 1.0f);
      return std::exp(-t.x * share);
    }
    return 1.0f;
  }

 private:
  glm::vec4 bilinear(glm::vec2 uv) const {
    const glm::vec2 p = uv * glm::vec2(width, height) - 0.5f;
    const glm::vec2 base = glm::floor(p);
    const glm::vec2 f = p - base;
    const auto at = [&](int x, int y) {
      const int cx = glm::clamp(x, 0, int(width) - 1);
      const int cy = glm::clamp(y, 0, int(height) - 1);
      return texels[std::size_t(cy) * width + std::size_t(cx)];
    };
    const int x = int(base.x);
    const int y = int(base.y);
    return glm::mix(glm::mix(at(x, y), at(x + 1, y), f.x),
                    glm::mix(at(x, y + 1), at(x + 1, y + 1), f.x), f.y);
  }
};
