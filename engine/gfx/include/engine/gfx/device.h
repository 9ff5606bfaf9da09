#pragma once
// The logical device: one graphics+compute queue, a timeline semaphore that numbers every
// submission, the memory allocator, deferred destruction and debug names.
//
// Threading: a Device is used from one thread (the render thread); only validation callbacks
// may arrive on others.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "engine/gfx/deferred_release.h"
#include "engine/gfx/instance.h"
#include "engine/gfx/memory_allocator.h"

namespace engine::gfx {

struct DeviceDesc {
  // When set, the chosen queue family must be able to present to this surface, and
  // VK_KHR_swapchain is enabled. Headless devices leave it null.
  VkSurfaceKHR presentSurface = VK_NULL_HANDLE;
  // Overrides CLOUDSCAPE_DEVICE ("cpu", "gpu" or a name substring); empty: environment.
  std::string preference;
};

class Device {
 public:
  Device(Instance& instance, const DeviceDesc& desc);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice vk() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkInstance vkInstance() const { return instance_.vk(); }
  Instance& instance() const { return instance_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string name() const { return properties_.deviceName; }
  bool isCpu() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  bool canPresent() const { return presentEnabled_; }
  MemoryAllocator& memory() { return *memory_; }

  // --- Submission tracking -------------------------------------------------------------
  // Submits on the queue and signals the device timeline with the returned value. Extra
  // binary semaphores (swapchain acquire/present) are passed through.
  std::uint64_t submit(std::span<const VkCommandBuffer> commandBuffers,
                       std::span<const VkSemaphoreSubmitInfo> waits = {},
                       std::span<const VkSemaphoreSubmitInfo> extraSignals = {});
  std::uint64_t lastSubmittedValue() const { return lastSubmitted_; }
  std::uint64_t completedValue() const;
  void waitFor(std::uint64_t timelineValue) const;
  // Waits for the GPU to finish everything and destroys every released object. Only call it
  // when no command buffer is being recorded (load time, resize, shutdown).
  void waitIdle();
  // Records `record` into a one-time command buffer, submits it and waits. Load time only.
  void immediateSubmit(const std::function<void(VkCommandBuffer)>& record);

  // --- Device loss ---------------------------------------------------------------------
  // The first call that reports VK_ERROR_DEVICE_LOST throws, as any failed call does. From
  // then on the device runs nothing, so everything submitted counts as finished: waits return
  // at once and released objects are destroyed, which lets teardown finish; submit() throws.
  bool lost() const { return lost_; }

  // --- Deferred destruction ------------------------------------------------------------
  // Destroys the object (and frees its memory) once every submission made so far, and the
  // one being recorded now, has completed on the GPU.
  void release(VkObjectType type, std::uint64_t handle, const Allocation& allocation = {});
  // Destroys what the GPU has finished with; called once per frame by the frame ring.
  void collectGarbage();

  // --- Debug names and labels (no-ops without VK_EXT_debug_utils) -----------------------
  void setName(VkObjectType type, std::uint64_t handle, const char* name) const;
  void beginLabel(VkCommandBuffer cmd, const char* name) const;
  void endLabel(VkCommandBuffer cmd) const;

 private:
  void pickPhysicalDevice(const DeviceDesc& desc);
  void createLogicalDevice();
  // Destroys what exists of the device (also after a constructor failed half way).
  void destroy() noexcept;
  // Throws for a failed call; a lost device is remembered (see lost()).
  void check(VkResult result, const char* call, int line) const;

  Instance& instance_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  bool presentEnabled_ = false;
  VkSemaphore timeline_ = VK_NULL_HANDLE;
  std::uint64_t lastSubmitted_ = 0;
  mutable bool lost_ = false;
  VkCommandPool immediatePool_ = VK_NULL_HANDLE;
  std::unique_ptr<MemoryAllocator> memory_;
  DeferredReleaseQueue deferred_;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
  PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel_ = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT endLabel_ = nullptr;
};

// Handle -> VkObjectType for the types the engine names and releases.
template <typename Handle>
constexpr VkObjectType objectType();
#define ENGINE_GFX_OBJECT_TYPE(Handle, Type)    \
  template <>                                   \
  constexpr VkObjectType objectType<Handle>() { \
    return Type;                                \
  }
ENGINE_GFX_OBJECT_TYPE(VkBuffer, VK_OBJECT_TYPE_BUFFER)
ENGINE_GFX_OBJECT_TYPE(VkImage, VK_OBJECT_TYPE_IMAGE)
ENGINE_GFX_OBJECT_TYPE(VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW)
ENGINE_GFX_OBJECT_TYPE(VkSampler, VK_OBJECT_TYPE_SAMPLER)
ENGINE_GFX_OBJECT_TYPE(VkPipeline, VK_OBJECT_TYPE_PIPELINE)
ENGINE_GFX_OBJECT_TYPE(VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT)
ENGINE_GFX_OBJECT_TYPE(VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT)
ENGINE_GFX_OBJECT_TYPE(VkDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL)
ENGINE_GFX_OBJECT_TYPE(VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL)
ENGINE_GFX_OBJECT_TYPE(VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE)
ENGINE_GFX_OBJECT_TYPE(VkCommandPool, VK_OBJECT_TYPE_COMMAND_POOL)
ENGINE_GFX_OBJECT_TYPE(VkCommandBuffer, VK_OBJECT_TYPE_COMMAND_BUFFER)
ENGINE_GFX_OBJECT_TYPE(VkDeviceMemory, VK_OBJECT_TYPE_DEVICE_MEMORY)
ENGINE_GFX_OBJECT_TYPE(VkSwapchainKHR, VK_OBJECT_TYPE_SWAPCHAIN_KHR)
ENGINE_GFX_OBJECT_TYPE(VkQueue, VK_OBJECT_TYPE_QUEUE)
#undef ENGINE_GFX_OBJECT_TYPE

template <typename Handle>
std::uint64_t handleBits(Handle handle) {
  return reinterpret_cast<std::uint64_t>(handle);
}

// Names a Vulkan object; every object the engine creates gets one.
template <typename Handle>
void setName(const Device& device, Handle handle, const char* name) {
  device.setName(objectType<Handle>(), handleBits(handle), name);
}

}  // namespace engine::gfx
