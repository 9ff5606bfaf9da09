#pragma once
// A hero cloud's life on a timeline: the growth and dissipation (clouds::HeroCloud) it has at a
// time, for a host that wants clouds to come and go without scripting them. Plain CPU code on
// FrameInputs::timeSeconds' clock (or any other the host keeps).
//
//   growth:     0 -> 1 over growSeconds from startSeconds
//   mature:     as authored for matureSeconds
//   dissipate:  dissipation 0 -> 1 over dissipateSeconds
//   rest:       gone for restSeconds, then, when `repeat`, grows again
#include <string>

namespace clouds {

struct HeroCloudLifecycle {
  double startSeconds = 0.0;        // finite: when it starts to grow; before it, not there
  float growSeconds = 300.0f;       // [0.1, 1e6]
  float matureSeconds = 600.0f;     // [0, 1e6]
  float dissipateSeconds = 300.0f;  // [0.1, 1e6]
  float restSeconds = 0.0f;         // [0, 1e6]
  bool repeat = true;               // false: it stays gone after its one life
};

struct HeroCloudLife {
  float growth = 1.0f;       // HeroCloud::growth
  float dissipation = 0.0f;  // HeroCloud::dissipation
};

// The life `lifecycle` gives at `seconds` (finite). Continuous in time, ramps included.
HeroCloudLife heroCloudLife(const HeroCloudLifecycle& lifecycle, double seconds);

// "" when every field is in range, else the first field that is not, named and explained.
std::string validateHeroCloudLifecycle(const HeroCloudLifecycle& lifecycle);

}  // namespace clouds
