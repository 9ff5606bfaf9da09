#pragma once
// The module's own tests and tools reach a Context's internals (noise textures, weather map,
// last uniforms, test flags) through this; hosts never see it.
#include "clouds/clouds.h"
#include "context_impl.h"

namespace clouds::detail {

struct ContextAccess {
  static Context::Impl& impl(Context& context) { return *context.impl_; }
  static const Context::Impl& impl(const Context& context) { return *context.impl_; }
};

}  // namespace clouds::detail
