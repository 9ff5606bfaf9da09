#include "programs.h"

#include <span>
#include <vector>

#include "atmosphere_shaders/aerial_perspective.comp.spv.h"
#include "atmosphere_shaders/apply.comp.spv.h"
#include "atmosphere_shaders/environment.comp.spv.h"
#include "atmosphere_shaders/multiscattering_lut.comp.spv.h"
#include "atmosphere_shaders/sky_view_lut.comp.spv.h"
#include "atmosphere_shaders/transmittance_lut.comp.spv.h"
#include "atmosphere_types.h"

namespace atmosphere::detail {
namespace {

using namespace shader;
constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kTexture = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kUniforms = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

struct ProgramDesc {
  Program program;
  std::span<const std::uint32_t> spirv;
  std::vector<Binding> bindings;
  const char* name;
};

std::vector<ProgramDesc> programTable() {
  const Binding uniforms{kBindingUniforms, kUniforms};
  const Binding transmittance{kBindingTransmittance, kTexture};
  const Binding multiScattering{kBindingMultiScattering, kTexture};
  const Binding target{kBindingTarget, kImage};
  return {
      {Program::Transmittance, transmittance_lut_comp_spv, {uniforms, target}, "transmittance"},
      {Program::MultiScattering,
       multiscattering_lut_comp_spv,
       {uniforms, transmittance, target},
       "multiple scattering"},
      {Program::SkyView,
       sky_view_lut_comp_spv,
       {uniforms, transmittance, multiScattering, target},
       "sky view"},
      {Program::AerialPerspective,
       aerial_perspective_comp_spv,
       {uniforms,
        transmittance,
        multiScattering,
        target,
        {kBindingCloudShadow, kTexture},
        {kBindingCloudShadowParameters, kUniforms}},
       "aerial perspective"},
      {Program::Environment,
       environment_comp_spv,
       {uniforms,
        transmittance,
        {kBindingSkyView, kTexture},
        target,
        {kBindingSkyLighting, kBuffer}},
       "environment"},
      {Program::Apply,
       apply_comp_spv,
       {uniforms,
        {kBindingSkyView, kTexture},
        {kBindingAerialPerspective, kTexture},
        {kBindingHostDepth, kTexture},
        target},
       "render"},
  };
}

}  // namespace

SpecializationKey applyKey(bool hasDepth, bool reversedZ) {
  SpecializationKey key;
  key.values[kSpecHasDepth] = hasDepth ? 1u : 0u;
  key.values[kSpecReversedZ] = reversedZ ? 1u : 0u;
  key.count = kApplySpecCount;
  return key;
}

Programs::Programs(const DeviceContext& device, bool reversedZ) {
  for (const ProgramDesc& desc : programTable()) {
    auto& program = programs_[index(desc.program)];
    program = std::make_unique<ComputeProgram>(device, desc.spirv, desc.bindings,
                                               sizeof(std::uint32_t), desc.name);
    if (desc.program == Program::Apply) {
      program->prepare(applyKey(false, reversedZ));
      program->prepare(applyKey(true, reversedZ));
    } else {
      program->prepare();
    }
  }
}

}  // namespace atmosphere::detail
