#include "engine/gfx/instance.h"

#include <cstdlib>
#include <cstring>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool instanceExtensionAvailable(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  for (const auto& extension : extensions) {
    if (std::strcmp(extension.extensionName, name) == 0) return true;
  }
  return false;
}

bool layerAvailable(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers) {
    if (std::strcmp(layer.layerName, name) == 0) return true;
  }
  return false;
}

}  // namespace

bool validationRequestedByEnvironment() {
  const char* value = std::getenv("CLOUDSCAPE_VALIDATION");
  return value != nullptr && value[0] != '\0' && value[0] != '0';
}

Instance::Instance(const InstanceDesc& desc) {
  std::uint32_t apiVersion = 0;
  vkEnumerateInstanceVersion(&apiVersion);
  if (apiVersion < VK_API_VERSION_1_3) {
    throw Error("Vulkan instance: the loader supports Vulkan " +
                std::to_string(VK_API_VERSION_MAJOR(apiVersion)) + "." +
                std::to_string(VK_API_VERSION_MINOR(apiVersion)) + ", 1.3 is required");
  }

  std::vector<const char*> extensions;
  for (const auto& ext : desc.extensions) extensions.push_back(ext.c_str());
  std::vector<const char*> layers;
  if (desc.validation) {
    if (!layerAvailable(kValidationLayer)) {
      throw Error(std::string("Vulkan instance: validation requested but ") + kValidationLayer +
                  " is not installed (Debian package vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
  }
  // Debug utils gives every object a name (for validation messages and capture tools); it is
  // enabled whenever the loader offers it, and required for validation.
  debugUtils_ = desc.validation || instanceExtensionAvailable(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = desc.appName.c_str();
  app.pEngineName = "cloudscape";
  app.apiVersion = VK_API_VERSION_1_3;

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Instance::onDebugMessage;
  messengerInfo.pUserData = this;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  // Chaining the messenger info also reports problems in vkCreateInstance/vkDestroyInstance.
  if (desc.validation) info.pNext = &messengerInfo;
  GFX_CHECK(vkCreateInstance(&info, nullptr, &instance_));

  if (desc.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) {
      vkDestroyInstance(instance_, nullptr);
      throw Error("Vulkan instance: vkCreateDebugUtilsMessengerEXT is unavailable");
    }
    GFX_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
}

Instance::~Instance() {
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

void Instance::setValidationHandler(ValidationHandler handler) {
  std::lock_guard lock(handlerMutex_);
  handler_ = std::move(handler);
}

VKAPI_ATTR VkBool32 VKAPI_CALL Instance::onDebugMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  ValidationMessage message;
  message.severity = severity;
  if (data->pMessageIdName != nullptr) message.idName = data->pMessageIdName;
  if (data->pMessage != nullptr) message.text = data->pMessage;
  static_cast<Instance*>(user)->dispatch(message);
  return VK_FALSE;  // never abort the call: the handler decides what a message means
}

void Instance::dispatch(const ValidationMessage& message) {
  ++messageCount_;
  std::lock_guard lock(handlerMutex_);
  if (handler_) {
    handler_(message);
    return;
  }
  log::error("Vulkan validation: " + message.text);
}

}  // namespace engine::gfx
