#pragma once
// Building the march's uniforms from the host's inputs and the settings. Offsets into the
// tiling textures are computed here in double precision (camera position modulo each tile),
// so the GPU only ever sees small camera-relative numbers.
#include "cloud_types.h"
#include "clouds/clouds.h"

namespace clouds::detail {

struct UniformContext {
  bool reversedZ = true;
  bool hasDepth = false;
  VkExtent2D traceExtent{0, 0};
  VkExtent2D fullExtent{0, 0};
  // Temporal reconstruction (defaults: a single self-contained frame, every pixel marched).
  std::uint32_t temporalIndex = 0;
  std::uint32_t tileSize = 1;
  glm::uvec2 phase{0, 0};
  bool useOutputHistory = false;  // temporal upsampling reads last frame's output history
  glm::dvec3 cameraDelta{0.0};    // camera position now minus the history's (m)
  double deltaSeconds = 0.0;      // time since the history's frame (s), for the wind's drift
  glm::mat4 previousView{1.0f};   // the view and projection the history was made with
  glm::mat4 previousProjection{1.0f};
};

shader::CloudUniforms buildUniforms(const FrameInputs& inputs, const Settings& settings,
                                    const UniformContext& context);

// The specialization constants of the march shader for these settings.
struct MarchVariant {
  std::uint32_t jitter;
  std::uint32_t detail;
  std::uint32_t cheapSampling;
  std::uint32_t multipleScattering;
  std::uint32_t lightSteps;
  std::uint32_t emptySpace;
};
MarchVariant marchVariant(const Settings& settings);

// The trace resolution for an output extent: ceil(extent x scale), at least 1.
VkExtent2D traceExtentFor(VkExtent2D full, float traceScale);

// x modulo tile into [0, tile).
double wrapToTile(double x, double tile);

}  // namespace clouds::detail
