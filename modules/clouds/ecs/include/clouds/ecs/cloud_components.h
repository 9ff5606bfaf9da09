#pragma once
// The clouds as ECS data. A scene with a CloudLayer entity gets the clouds module (its systems,
// pipelines and passes); a scene without one gets none of it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "clouds/hero_cloud_life.h"
#include "clouds/nvdf.h"

namespace clouds::ecs {

struct CloudLayer {
  clouds::Settings settings;
  std::uint32_t noiseSeed = 1;
  std::optional<std::filesystem::path> weatherMap;  // painted weather (PNG), else procedural
  // The hero clouds' assets, read and validated when the scene loaded. Entities with a
  // clouds::HeroCloud component place them (its `asset` indexes this list), and a
  // clouds::HeroCloudLifecycle beside it makes one come and go; each frame draws the
  // kMaxHeroClouds nearest the camera. None: the module loads no atlas and runs no hero march.
  std::vector<std::shared_ptr<const clouds::NvdfVolume>> heroCloudAssets;
};

// On a camera entity: the quality preset its clouds render with, settingsFor(preset) over the
// layer's look. A camera without one renders the layer's settings as they are.
struct CloudQuality {
  clouds::Quality preset = clouds::Quality::Medium;
};

// Context singleton the clouds module keeps up to date, for HUDs and logs: how the clouds
// rendered (the module's report of its last frame, the pass times of the latest completed
// frame, its GPU memory) and the last error, if any. Read-only for everyone else.
struct CloudStatus {
  clouds::FrameReport report;
  std::vector<clouds::PassTiming> passTimings;
  clouds::MemoryUsage memory;
  std::string lastError;  // empty when the last frame rendered
};

}  // namespace clouds::ecs
