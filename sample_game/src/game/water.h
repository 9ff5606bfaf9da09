#pragma once
// A scene's water (its "water" key) as the world holds it: a lake or sea at one level, drawn by
// the renderer (WaterRenderer) and flown over, never under (the flight's floor).
#include <glm/glm.hpp>

namespace sample {

struct WaterSurface {
  double levelMetres = 0.0;                 // above sea level
  glm::vec3 colour{0.012f, 0.03f, 0.035f};  // the water body's albedo
  double clarity = 0.35;                    // the share of the bed seen straight down
};

}  // namespace sample
