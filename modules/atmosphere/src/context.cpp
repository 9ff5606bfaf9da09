// atmosphere::Context: the public API. It checks every argument, turns internal failures into
// Error codes (the API never throws) and forwards to Context::Impl.
#include <cmath>
#include <new>

#include "context_impl.h"
#include "vkfx/api_boundary.h"

namespace atmosphere {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::None:
      return "None";
    case ErrorCode::InvalidCreateInfo:
      return "InvalidCreateInfo";
    case ErrorCode::MissingFunction:
      return "MissingFunction";
    case ErrorCode::UnsupportedDevice:
      return "UnsupportedDevice";
    case ErrorCode::OutOfMemory:
      return "OutOfMemory";
    case ErrorCode::VulkanFailure:
      return "VulkanFailure";
    case ErrorCode::InvalidParameters:
      return "InvalidParameters";
    case ErrorCode::InvalidSettings:
      return "InvalidSettings";
    case ErrorCode::InvalidInputs:
      return "InvalidInputs";
    case ErrorCode::NotPrepared:
      return "NotPrepared";
  }
  return "?";
}

namespace {

using vkfx::checkExtent;
using vkfx::extentText;
using vkfx::fail;
using vkfx::finite;
using vkfx::nonNegative;
using vkfx::succeed;

std::string checkCreateInfo(const CreateInfo& info) {
  if (std::string problem = vkfx::checkDeviceAndLimits(info); !problem.empty()) return problem;
  if (info.colorFormat != VK_FORMAT_R16G16B16A16_SFLOAT) {
    return "CreateInfo.colorFormat = " + std::to_string(static_cast<int>(info.colorFormat)) +
           ": only R16G16B16A16_SFLOAT is supported";
  }
  return {};
}

std::string checkInputs(const FrameInputs& in, const CreateInfo& info) {
  if (in.commandBuffer == VK_NULL_HANDLE) return "FrameInputs.commandBuffer: must not be null";
  if (std::string problem = checkExtent("FrameInputs.renderExtent", in.renderExtent, info);
      !problem.empty()) {
    return problem;
  }
  if (!finite(in.view)) return "FrameInputs.view: must be finite";
  if (!finite(in.projection) || std::abs(glm::determinant(in.projection)) < 1e-30f) {
    return "FrameInputs.projection: must be finite and invertible";
  }
  for (double c : {in.cameraPosition.x, in.cameraPosition.y, in.cameraPosition.z}) {
    if (!std::isfinite(c)) return "FrameInputs.cameraPosition: must be finite";
  }
  if (!finite(in.sunDirection) || glm::length(in.sunDirection) < 1e-6f) {
    return "FrameInputs.sunDirection: must be finite and not zero";
  }
  const glm::vec3& e = in.sunIlluminance;
  if (!finite(e) || !nonNegative(e)) {
    return "FrameInputs.sunIlluminance: must be finite and not negative";
  }
  if (in.cloudShadow.view != VK_NULL_HANDLE) {
    for (const glm::vec4& v : in.cloudShadow.parameters) {
      if (!finite(v)) return "FrameInputs.cloudShadow.parameters: must be finite";
    }
    const glm::vec4& shadowInfo = in.cloudShadow.parameters[12];
    if (shadowInfo.x < 0.0f || shadowInfo.x > 4.0f ||
        (shadowInfo.x > 0.0f && shadowInfo.y < 1.0f)) {
      return "FrameInputs.cloudShadow.parameters: info (the last vec4) must hold 0 to 4 "
             "cascades of at least one texel";
    }
  }
  return {};
}

// Runs `work`, turning what it throws into the error out-parameter.
template <typename Work>
bool guarded(Error* error, Work&& work) {
  return vkfx::guarded(error, "atmosphere", std::forward<Work>(work));
}

}  // namespace

std::unique_ptr<Context> Context::create(const CreateInfo& info, Error* error) {
  if (std::string problem = checkCreateInfo(info); !problem.empty()) {
    fail(error, ErrorCode::InvalidCreateInfo, problem);
    return nullptr;
  }
  detail::VulkanFunctions functions;
  std::string missing;
  if (!functions.load(info.instance, info.device, info.getInstanceProcAddr, info.getDeviceProcAddr,
                      info.debugUtils, &missing)) {
    fail(error, ErrorCode::MissingFunction, "atmosphere: cannot load Vulkan function " + missing);
    return nullptr;
  }
  std::unique_ptr<Impl> impl;
  if (!guarded(error, [&] { impl = std::make_unique<Impl>(info, functions); })) return nullptr;
  return std::unique_ptr<Context>(new Context(std::move(impl)));
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

bool Context::prepare(const Parameters& parameters, const Settings& settings,
                      VkExtent2D renderExtent, Error* error) {
  if (std::string problem = validateParameters(parameters); !problem.empty()) {
    return fail(error, ErrorCode::InvalidParameters, problem);
  }
  if (std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidSettings, problem);
  }
  if (std::string problem = checkExtent("renderExtent", renderExtent, impl_->createInfo());
      !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, "prepare: " + problem);
  }
  return guarded(error, [&] { impl_->prepare(parameters, settings); });
}

bool Context::prepared(const Parameters& parameters, const Settings& settings,
                       VkExtent2D renderExtent) const {
  return validateParameters(parameters).empty() && validateSettings(settings).empty() &&
         checkExtent("", renderExtent, impl_->createInfo()).empty() &&
         impl_->unprepared(parameters, settings).empty();
}

bool Context::dispatch(const FrameInputs& inputs, const Parameters& parameters,
                       const Settings& settings, Error* error) {
  if (std::string problem = checkInputs(inputs, impl_->createInfo()); !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (std::string problem = validateParameters(parameters); !problem.empty()) {
    return fail(error, ErrorCode::InvalidParameters, problem);
  }
  if (std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidSettings, problem);
  }
  if (std::string missing = impl_->unprepared(parameters, settings); !missing.empty()) {
    return fail(error, ErrorCode::NotPrepared,
                "dispatch: " + missing +
                    " are not prepared: call Context::prepare() with them "
                    "outside command recording");
  }
  impl_->dispatch(inputs, parameters, settings);
  return succeed(error);
}

bool Context::render(VkCommandBuffer commandBuffer, VkImageView color, VkImageView depth,
                     VkImageLayout depthLayout, VkExtent2D extent, Error* error) {
  if (!impl_->dispatched()) {
    return fail(error, ErrorCode::InvalidInputs, "render: dispatch() first, this frame");
  }
  if (commandBuffer == VK_NULL_HANDLE || color == VK_NULL_HANDLE) {
    return fail(error, ErrorCode::InvalidInputs,
                "render: the command buffer and the colour view are required");
  }
  const VkExtent2D last = impl_->lastExtent();
  if (extent.width != last.width || extent.height != last.height) {
    return fail(error, ErrorCode::InvalidInputs,
                "render: extent " + extentText(extent) +
                    " must equal the last dispatch's renderExtent (" + extentText(last) + ")");
  }
  impl_->render(commandBuffer, color, depth, depthLayout);
  return succeed(error);
}

bool Context::drawSky(VkCommandBuffer commandBuffer, Error* error) {
  if (!impl_->drawsSky()) {
    return fail(error, ErrorCode::InvalidInputs,
                "drawSky: CreateInfo.skyPassColorFormat was VK_FORMAT_UNDEFINED at create()");
  }
  if (!impl_->dispatched()) {
    return fail(error, ErrorCode::InvalidInputs, "drawSky: dispatch() first, this frame");
  }
  if (commandBuffer == VK_NULL_HANDLE) {
    return fail(error, ErrorCode::InvalidInputs, "drawSky: the command buffer is required");
  }
  impl_->drawSky(commandBuffer);
  return succeed(error);
}

Outputs Context::outputs() const {
  return impl_->outputs();
}
SkyLighting Context::skyLighting(std::uint64_t frameIndex) const {
  return impl_->skyLighting(frameIndex);
}
MemoryUsage Context::memoryUsage() const {
  return impl_->memoryUsage();
}
std::vector<PassTiming> Context::passTimings(std::uint64_t frameIndex) const {
  return impl_->passTimings(frameIndex);
}

}  // namespace atmosphere
