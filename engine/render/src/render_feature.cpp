#include "engine/render/render_feature.h"

namespace engine::render {

RenderFeature::~RenderFeature() = default;

void RenderFeature::finish(std::uint64_t /*lastFrameIndex*/) {}

}  // namespace engine::render
