#pragma once
// Checking VkResult: a failed call throws gfx::VulkanError naming the call, file and line.
#include <vulkan/vulkan.h>

#include "engine/core/error.h"

namespace engine::gfx {

class VulkanError : public engine::Error {
 public:
  VulkanError(const std::string& message, VkResult result) : Error(message), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

const char* resultName(VkResult result);
void throwVulkanError(VkResult result, const char* expression, const char* file, int line);

}  // namespace engine::gfx

#define GFX_CHECK(expr)                                                            \
  do {                                                                             \
    const VkResult gfxCheckResult_ = (expr);                                       \
    if (gfxCheckResult_ != VK_SUCCESS)                                             \
      ::engine::gfx::throwVulkanError(gfxCheckResult_, #expr, __FILE__, __LINE__); \
  } while (0)
