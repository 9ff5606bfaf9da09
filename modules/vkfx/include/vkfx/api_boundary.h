#pragma once
// The public-API boundary of a vkfx module (clouds, atmosphere): its calls never throw, and
// report through an `Error*` out-parameter of the module's own type ({code, message}; its
// ErrorCode has None, OutOfMemory, UnsupportedDevice and VulkanFailure). What is thrown inside
// (vkfx::Error, std::bad_alloc) is caught here and given its code; and the argument checks
// every module's CreateInfo and FrameInputs share (same field names in each module).
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>
#include <new>
#include <string>

#include "vkfx/device_context.h"

namespace vkfx {

template <typename ModuleError, typename Code>
bool fail(ModuleError* error, Code code, std::string message) {
  if (error != nullptr) *error = ModuleError{code, std::move(message)};
  return false;
}

template <typename ModuleError>
bool succeed(ModuleError* error) {
  if (error != nullptr) *error = ModuleError{};
  return true;
}

// The module's code for a failure thrown inside it.
template <typename Code>
Code codeOf(Failure failure) {
  switch (failure) {
    case Failure::OutOfMemory:
      return Code::OutOfMemory;
    case Failure::Unsupported:
      return Code::UnsupportedDevice;
    case Failure::VulkanFailure:
      break;
  }
  return Code::VulkanFailure;
}

// Runs `work`, turning what it throws into `error` ("<module>: <what>"); true when it did not.
template <typename ModuleError, typename Work>
bool guarded(ModuleError* error, const char* module, Work&& work) {
  using Code = decltype(ModuleError::code);
  try {
    work();
  } catch (const Error& e) {
    return fail(error, codeOf<Code>(e.failure()), std::string(module) + ": " + e.what());
  } catch (const std::bad_alloc&) {
    return fail(error, Code::OutOfMemory, std::string(module) + ": out of host memory");
  }
  return succeed(error);
}

bool finite(const glm::mat4& m);
bool finite(const glm::vec3& v);
bool finitePosition(const glm::dvec3& v);
bool nonNegative(const glm::vec3& v);
std::string extentText(VkExtent2D extent);  // "WxH"

// Empty when `extent` is non-zero and within CreateInfo::maxRenderExtent, else the problem,
// naming `field`.
std::string checkExtentWithin(const char* field, VkExtent2D extent, VkExtent2D maxRenderExtent);
template <typename CreateInfo>
std::string checkExtent(const char* field, VkExtent2D extent, const CreateInfo& info) {
  return checkExtentWithin(field, extent, info.maxRenderExtent);
}

// Empty when the device handles, both proc-addr functions, maxFramesInFlight ([1, 8]) and
// maxRenderExtent ([1, 16384] per side) of a module's CreateInfo are valid, else the problem.
std::string checkDeviceAndLimits(VkInstance instance, VkPhysicalDevice physicalDevice,
                                 VkDevice device, PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                 PFN_vkGetDeviceProcAddr getDeviceProcAddr,
                                 std::uint32_t maxFramesInFlight, VkExtent2D maxRenderExtent);
template <typename CreateInfo>
std::string checkDeviceAndLimits(const CreateInfo& info) {
  return checkDeviceAndLimits(info.instance, info.physicalDevice, info.device,
                              info.getInstanceProcAddr, info.getDeviceProcAddr,
                              info.maxFramesInFlight, info.maxRenderExtent);
}

}  // namespace vkfx
