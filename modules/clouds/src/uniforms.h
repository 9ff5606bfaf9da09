#pragma once
// Building the march's uniforms from the host's inputs and the settings. Offsets into the
// tiling textures are computed here in double precision (camera position modulo each tile),
// so the GPU only ever sees small camera-relative numbers.
#include "cloud_types.h"
#include "clouds/clouds.h"
#include "temporal_state.h"

namespace clouds::detail {

struct UniformContext {
  bool reversedZ = true;
  bool hasDepth = false;
  VkExtent2D traceExtent{0, 0};
  VkExtent2D fullExtent{0, 0};
  // The frame's temporal plan (defaults: a single self-contained frame, every pixel marched).
  TemporalFrame temporal;
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
  std::uint32_t lightReuse;
  std::uint32_t edgeRays;   // 0/1: the settings have edge rays (and temporal upsampling)
  std::uint32_t heroLight;  // shader::kHeroLight* (Settings::heroLight)
};
MarchVariant marchVariant(const Settings& settings);

// Whether a frame marches edge rays (Settings::edgeRays): only while the output history keeps
// their samples, and with a second pixel in each tile to hold them (edgeRaySlot()).
bool marchesEdgeRays(const Settings& settings, const TemporalFrame& temporal);

// The bytes of the edge rays' list for a trace extent: its header (the indirect dispatch and
// the count) and a tile per 2 x 2 trace pixels (the smallest tile that has edge rays).
VkDeviceSize edgeRayListBytes(VkExtent2D traceExtent);

// The trace resolution for an output extent: ceil(extent x scale), at least 1.
VkExtent2D traceExtentFor(VkExtent2D full, float traceScale);
// The near field's resolution (Settings::nearFieldMetres): half the trace's per axis, rounded
// up (Nubis³ marches the near part at half the far part's resolution: close by, a cloud's
// features cover many pixels).
VkExtent2D nearFieldExtentFor(VkExtent2D trace);

// x modulo tile into [0, tile).
double wrapToTile(double x, double tile);

}  // namespace clouds::detail
