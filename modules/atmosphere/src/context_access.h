#pragma once
// The module's own tests reach a Context's internals (its LUTs, last uniforms) through this.
#include "atmosphere/atmosphere.h"
#include "context_impl.h"

namespace atmosphere::detail {

struct ContextAccess {
  static Context::Impl& impl(Context& context) { return *context.impl_; }
  static const Context::Impl& impl(const Context& context) { return *context.impl_; }
};

}  // namespace atmosphere::detail
