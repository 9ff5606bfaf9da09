// CloudWeather's regions at the clock: what the clouds render over each place, and the whole
// state over a column for a storm's strike rate.
#include "clouds/ecs/cloud_components.h"

namespace clouds::ecs {

std::vector<clouds::WeatherRegion> CloudWeather::regionsAt(double seconds) const {
  std::vector<clouds::WeatherRegion> places;
  places.reserve(regions.size());
  for (const RegionalWeather& r : regions) {
    places.push_back(clouds::withWeather(r.place, r.timeline.stateAt(seconds)));
  }
  return places;
}

clouds::WeatherState CloudWeather::stateAt(double seconds, glm::dvec2 xzMetres) const {
  // weatherAt() weighs each region by its place alone: each timeline is read once, here.
  std::vector<clouds::WeatherRegion> places;
  std::vector<clouds::WeatherState> states;
  places.reserve(regions.size());
  states.reserve(regions.size());
  for (const RegionalWeather& r : regions) {
    places.push_back(r.place);
    states.push_back(r.timeline.stateAt(seconds));
  }
  return clouds::weatherAt(timeline.stateAt(seconds), places, states, xzMetres);
}

}  // namespace clouds::ecs
