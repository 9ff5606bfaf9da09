#include "cover.h"

namespace terrain {

Cover classifyCover(const CoverRules& rules, double heightMetres, double slopeDegrees) {
  if (heightMetres >= rules.snowMinHeightMetres && slopeDegrees <= rules.snowMaxSlopeDegrees) {
    return Cover::Snow;
  }
  if (slopeDegrees >= rules.rockMinSlopeDegrees || heightMetres >= rules.grassMaxHeightMetres) {
    return Cover::Rock;
  }
  return Cover::Grass;
}

glm::vec3 coverColour(const CoverRules& rules, Cover cover) {
  switch (cover) {
    case Cover::Grass:
      return rules.grassColour;
    case Cover::Rock:
      return rules.rockColour;
    case Cover::Snow:
      return rules.snowColour;
  }
  return rules.rockColour;
}

}  // namespace terrain
