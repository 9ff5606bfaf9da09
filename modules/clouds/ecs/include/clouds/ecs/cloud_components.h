#pragma once
// The clouds as ECS data. A scene with a CloudLayer entity gets the clouds module (its systems,
// pipelines and passes); a scene without one gets none of it.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "clouds/clouds.h"

namespace clouds::ecs {

struct CloudLayer {
  clouds::Settings settings;
  std::uint32_t noiseSeed = 1;
  std::optional<std::filesystem::path> weatherMap;  // painted weather (PNG), else procedural
};

// On a camera entity: the quality preset its clouds render with, settingsFor(preset) over the
// layer's look. A camera without one renders the layer's settings as they are.
struct CloudQuality {
  clouds::Quality preset = clouds::Quality::Medium;
};

class CloudRenderer;

// Context singleton set by whoever owns the CloudRenderer (the game's renderer), so the
// clouds' systems can reach it.
struct CloudRendererRef {
  CloudRenderer* renderer = nullptr;
};

}  // namespace clouds::ecs
