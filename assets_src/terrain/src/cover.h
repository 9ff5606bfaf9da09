#pragma once
// Ground cover (grass, rock, snow) chosen per vertex from height and slope.
#include <glm/vec3.hpp>

namespace terrain {

/// Ground cover classes; a vertex's colour is its class's linear RGB.
enum class Cover { Grass, Rock, Snow };

/// Colours and the thresholds that pick a vertex's cover.
struct CoverRules {
  glm::vec3 grassColour{0.0f};
  glm::vec3 rockColour{0.0f};
  glm::vec3 snowColour{0.0f};
  double rockMinSlopeDegrees = 90.0;
  double grassMaxHeightMetres = 0.0;
  double snowMinHeightMetres = 0.0;
  double snowMaxSlopeDegrees = 0.0;
};

/// Snow wins on gentle slopes above the snow line (it slides off steep ones), rock on steep slopes
/// and above the grass line, grass everywhere else.
Cover classifyCover(const CoverRules& rules, double heightMetres, double slopeDegrees);

glm::vec3 coverColour(const CoverRules& rules, Cover cover);

}  // namespace terrain
