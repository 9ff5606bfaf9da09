#pragma once
// The per-frame uniform block from the host's inputs, the parameters and the settings.
#include "atmosphere/atmosphere.h"
#include "atmosphere_types.h"

namespace atmosphere::detail {

// Half-float targets hold radiance up to 65504; the sun's disc is clamped below that.
inline constexpr float kMaxRadiance = 60000.0f;

shader::AtmosphereUniforms buildUniforms(const FrameInputs& inputs, const Parameters& parameters,
                                         const Settings& settings, bool reversedZ);

}  // namespace atmosphere::detail
