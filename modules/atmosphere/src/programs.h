#pragma once
// The module's compute programs as one table: shader, descriptor bindings (atmosphere_types.h)
// and the variants, all made at creation (none depends on the settings: sizes and sample
// counts are uniforms).
#include <array>
#include <cstdint>
#include <memory>

#include "kit.h"

namespace atmosphere::detail {

enum class Program : std::uint32_t {
  Transmittance,      // transmittance_lut.comp
  MultiScattering,    // multiscattering_lut.comp
  SkyView,            // sky_view_lut.comp
  AerialPerspective,  // aerial_perspective.comp
  Environment,        // environment.comp
  Apply,              // apply.comp (variants: with and without the host's depth)
  Count
};

// The passes as the timer and passTimings() name them (Apply is "render").
inline constexpr std::array<const char*, static_cast<std::size_t>(Program::Count)> kPassNames = {
    "transmittance",      "multiple scattering", "sky view",
    "aerial perspective", "environment",         "render"};

constexpr std::uint32_t index(Program program) {
  return static_cast<std::uint32_t>(program);
}

SpecializationKey applyKey(bool hasDepth, bool reversedZ);

class Programs {
 public:
  // `reversedZ`: the host's depth convention (CreateInfo), compiled into the render pass.
  Programs(const DeviceContext& device, bool reversedZ);
  ComputeProgram& operator[](Program program) { return *programs_[index(program)]; }
  const ComputeProgram& operator[](Program program) const { return *programs_[index(program)]; }

 private:
  std::array<std::unique_ptr<ComputeProgram>, static_cast<std::size_t>(Program::Count)> programs_;
};

}  // namespace atmosphere::detail
