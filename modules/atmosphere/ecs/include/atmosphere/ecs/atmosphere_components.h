#pragma once
// The atmosphere as ECS data. A scene with an Atmosphere entity gets the atmosphere module (its
// passes, pipelines and memory, the sky it draws, the sun and sky light it publishes); a scene
// without one gets none of it.
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"

namespace atmosphere::ecs {

// The planet's air. One per scene.
struct Atmosphere {
  atmosphere::Parameters parameters;  // Earth unless the scene says otherwise
};

// On a camera entity: the quality preset the atmosphere renders with for it (Medium without
// one).
struct AtmosphereQuality {
  atmosphere::Quality preset = atmosphere::Quality::Medium;
};

// Context singleton the atmosphere module keeps up to date, for HUDs and logs: the sky the
// latest completed frame measured, its pass times and GPU memory, and the last error, if any.
// Read-only for everyone else.
struct AtmosphereStatus {
  atmosphere::SkyLighting sky;
  std::vector<atmosphere::PassTiming> passTimings;
  atmosphere::MemoryUsage memory;
  std::string lastError;  // empty when the last frame rendered
};

}  // namespace atmosphere::ecs
