#pragma once
// The Vulkan instance, with optional validation whose messages go to a replaceable handler.
// Tests install a handler that turns every message into a failure; the default handler logs
// through engine::log and counts.
#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace engine::gfx {

struct ValidationMessage {
  VkDebugUtilsMessageSeverityFlagBitsEXT severity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  std::string idName;  // e.g. "VUID-VkBufferCreateInfo-size-00912"
  std::string text;
};

using ValidationHandler = std::function<void(const ValidationMessage&)>;

struct InstanceDesc {
  std::string appName = "cloudscape";
  // Enables VK_LAYER_KHRONOS_validation and a debug messenger. Creation fails with a clear
  // error when the layer is not installed (package vulkan-validationlayers).
  bool validation = false;
  // Extra instance extensions, e.g. those GLFW needs for a window surface.
  std::vector<std::string> extensions;
};

// True when the environment asks for validation (CLOUDSCAPE_VALIDATION=1). Tests set it.
bool validationRequestedByEnvironment();

class Instance {
 public:
  explicit Instance(const InstanceDesc& desc);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance vk() const { return instance_; }
  bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
  // True when VK_EXT_debug_utils is enabled (object names and command labels work).
  bool debugUtilsEnabled() const { return debugUtils_; }

  // Replaces the handler; an empty handler restores the default (log + count).
  void setValidationHandler(ValidationHandler handler);
  // Number of warning- and error-severity messages received since creation.
  std::uint32_t validationMessageCount() const { return messageCount_.load(); }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  void dispatch(const ValidationMessage& message);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool debugUtils_ = false;
  std::mutex handlerMutex_;
  ValidationHandler handler_;
  std::atomic<std::uint32_t> messageCount_{0};
};

}  // namespace engine::gfx
