#pragma once
// Lightning bolts onto the screen: FrameInputs::lightningBolts projected into the pieces the
// upsample draws (cloud_types.h's LightningBoltsHeader layout), clipped to what the camera
// sees. A pure function of the inputs, tested without a GPU.
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"

namespace clouds::detail {

struct ProjectedBolts {
  shader::LightningBoltsHeader header{};
  std::vector<glm::vec4> segments;  // kBoltVec4sPerSegment per piece on screen
};

// The pieces of `inputs.lightningBolts` in front of the camera and on screen (with a margin of
// their width), in output pixels of `inputs.renderExtent`.
ProjectedBolts projectBolts(const FrameInputs& inputs);

}  // namespace clouds::detail
