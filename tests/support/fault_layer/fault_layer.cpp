// VK_LAYER_CLOUDSCAPE_faults: a Vulkan layer that makes one chosen call fail the way a driver
// may, so a test can run the real sample and check that it ends in a clear error, leaks nothing
// the validation layer can see and does not hang. An implicit layer, on where
// CLOUDSCAPE_FAULT_LAYER=1 (see tests/support/CMakeLists.txt for how the loader finds it). It sits
// above the layers the application enables, so the validation layer sees only what the fault
// layer passes on, as it would see a real driver's failure.
//
// CLOUDSCAPE_FAULT=<kind>:<n> picks the fault; n counts from 1:
//   create:n          the n-th object creation of any kind (vkCreate*, vkAllocate*) returns
//                     VK_ERROR_OUT_OF_DEVICE_MEMORY
//   <vkCreateX>:n     the n-th call of that creation function returns
//                     VK_ERROR_OUT_OF_DEVICE_MEMORY
//   vkQueueSubmit:n   the n-th submission (vkQueueSubmit or vkQueueSubmit2) is not carried out
//                     and returns VK_ERROR_OUT_OF_DEVICE_MEMORY
//   device-lost:n     the n-th submission is not carried out and returns VK_ERROR_DEVICE_LOST;
//                     from then on every submit, wait, query read, acquire and present does too
//                     (creations still succeed, as the specification allows)
//   vkAcquireNextImageKHR:n:<result>, vkQueuePresentKHR:n:<result>
//                     the n-th acquire or present returns <result>: out-of-date, suboptimal,
//                     surface-lost or out-of-memory. As a driver would: an acquire that fails
//                     acquires nothing, a suboptimal one does acquire; a present reporting
//                     out-of-date, suboptimal or surface-lost has still been queued (its
//                     semaphore waits happen), one out of memory has not
// CLOUDSCAPE_FAULT_REPORT=<file>: when the device is destroyed, the layer writes there how many
// calls of each hooked kind it saw and which one it failed, for the test to sweep n over.
//
// One instance and one device at a time (what the sample makes); not for general use.
#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <string>

namespace {

// The results an acquire or present can be made to return: the name CLOUDSCAPE_FAULT gives, the
// result, and its name in the report. The first, out of memory, is the default.
struct PresentationResult {
  const char* option;
  VkResult result;
  const char* name;
};
constexpr PresentationResult kPresentationResults[] = {
    {"out-of-memory", VK_ERROR_OUT_OF_DEVICE_MEMORY, "VK_ERROR_OUT_OF_DEVICE_MEMORY"},
    {"out-of-date", VK_ERROR_OUT_OF_DATE_KHR, "VK_ERROR_OUT_OF_DATE_KHR"},
    {"suboptimal", VK_SUBOPTIMAL_KHR, "VK_SUBOPTIMAL_KHR"},
    {"surface-lost", VK_ERROR_SURFACE_LOST_KHR, "VK_ERROR_SURFACE_LOST_KHR"}};

const PresentationResult& presentationResult(const std::string& option) {
  for (const PresentationResult& r : kPresentationResults) {
    if (option == r.option) return r;
  }
  return kPresentationResults[0];
}

struct Fault {
  std::string kind;  // "create", a function name, "device-lost" or empty (none)
  long at = 0;
  PresentationResult result = kPresentationResults[0];  // what an acquire or present returns
};

// "<kind>:<n>" or "<kind>:<n>:<result>".
Fault parseFault() {
  const char* text = std::getenv("CLOUDSCAPE_FAULT");
  if (text == nullptr) return {};
  const std::string value = text;
  const std::size_t colon = value.find(':');
  if (colon == std::string::npos) return {};
  const std::size_t second = value.find(':', colon + 1);
  Fault fault{value.substr(0, colon), std::strtol(value.c_str() + colon + 1, nullptr, 10)};
  if (second != std::string::npos) fault.result = presentationResult(value.substr(second + 1));
  return fault;
}

struct State {
  std::mutex mutex;
  Fault fault = parseFault();
  std::map<std::string, long> calls;  // per hooked function, plus "create" and "submit"
  std::string injected;               // what was failed, e.g. "vkCreateImage (creation 12)"
  bool deviceLost = false;
  PFN_vkGetInstanceProcAddr nextInstanceProcAddr = nullptr;
  PFN_vkGetDeviceProcAddr nextDeviceProcAddr = nullptr;
  PFN_vkQueueWaitIdle nextQueueWaitIdle = nullptr;
};

State& state() {
  static State s;
  return s;
}

// Counts a creation call and says whether it must fail.
bool creationFails(const char* name) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  const long creation = ++s.calls["create"];
  const long ofThisKind = ++s.calls[name];
  const bool fails = (s.fault.kind == "create" && creation == s.fault.at) ||
                     (s.fault.kind == name && ofThisKind == s.fault.at);
  if (fails) s.injected = std::string(name) + " (creation " + std::to_string(creation) + ")";
  return fails;
}

enum class SubmitFate { Run, OutOfMemory, DeviceLost };

SubmitFate submitFate(const char* name) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  if (s.deviceLost) return SubmitFate::DeviceLost;
  const long submission = ++s.calls["submit"];
  ++s.calls[name];
  if (s.fault.kind == "device-lost" && submission == s.fault.at) {
    s.deviceLost = true;
    s.injected =
        std::string("device lost at ") + name + " (submission " + std::to_string(submission) + ")";
    return SubmitFate::DeviceLost;
  }
  if (s.fault.kind == "vkQueueSubmit" && submission == s.fault.at) {
    s.injected = std::string(name) + " (submission " + std::to_string(submission) + ")";
    return SubmitFate::OutOfMemory;
  }
  return SubmitFate::Run;
}

// Counts an acquire or present and returns the result it must report instead of its own, or
// VK_SUCCESS to leave it be.
VkResult presentationFault(const char* name) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  const long call = ++s.calls[name];
  if (s.fault.kind != name || call != s.fault.at) return VK_SUCCESS;
  s.injected = std::string(name) + " (call " + std::to_string(call) + ") " + s.fault.result.name;
  return s.fault.result.result;
}

bool deviceLost() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  return s.deviceLost;
}

void writeReport() {
  const char* path = std::getenv("CLOUDSCAPE_FAULT_REPORT");
  if (path == nullptr) return;
  State& s = state();
  std::lock_guard lock(s.mutex);
  std::ofstream out(path);
  for (const auto& [name, count] : s.calls) out << "calls " << name << ' ' << count << '\n';
  out << "injected " << (s.injected.empty() ? "nothing" : s.injected) << '\n';
}

// --- Hooks, each keeping the next layer's function ----------------------------------------
// Creation functions: (device, info, allocator, out) or (device, info, out).
template <const char* Name, typename Pfn>
struct Creation;
template <const char* Name, typename... Args>
struct Creation<Name, VkResult(VKAPI_PTR*)(Args...)> {
  static inline VkResult(VKAPI_PTR* next)(Args...) = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(Args... args) {
    if (creationFails(Name)) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    return next(args...);
  }
};

// Pipelines: a failed call leaves every output handle null, as the specification requires.
template <const char* Name, typename Info>
struct PipelineCreation {
  static inline VkResult(VKAPI_PTR* next)(VkDevice, VkPipelineCache, std::uint32_t, const Info*,
                                          const VkAllocationCallbacks*, VkPipeline*) = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(VkDevice device, VkPipelineCache cache,
                                             std::uint32_t count, const Info* infos,
                                             const VkAllocationCallbacks* allocator,
                                             VkPipeline* out) {
    if (creationFails(Name)) {
      for (std::uint32_t i = 0; i < count; ++i) out[i] = VK_NULL_HANDLE;
      return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    }
    return next(device, cache, count, infos, allocator, out);
  }
};

// Calls that report a lost device once it is lost, and otherwise pass through.
template <typename Pfn>
struct LostAware;
template <typename... Args>
struct LostAware<VkResult(VKAPI_PTR*)(Args...)> {
  static inline VkResult(VKAPI_PTR* next)(Args...) = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(Args... args) {
    if (deviceLost()) return VK_ERROR_DEVICE_LOST;
    return next(args...);
  }
};

// vkAcquireNextImageKHR: a failure acquires nothing; suboptimal acquires the image.
struct Acquire {
  static inline PFN_vkAcquireNextImageKHR next = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(VkDevice device, VkSwapchainKHR swapchain,
                                             std::uint64_t timeout, VkSemaphore semaphore,
                                             VkFence fence, std::uint32_t* index) {
    if (deviceLost()) return VK_ERROR_DEVICE_LOST;
    const VkResult fault = presentationFault("vkAcquireNextImageKHR");
    if (fault != VK_SUCCESS && fault != VK_SUBOPTIMAL_KHR) return fault;
    const VkResult result = next(device, swapchain, timeout, semaphore, fence, index);
    return result == VK_SUCCESS ? fault : result;
  }
};

// vkQueuePresentKHR: out-of-date, suboptimal and surface-lost are reported after the present
// was queued (the specification has its semaphore waits happen all the same); out of memory
// before, leaving everything as it was.
struct Present {
  static inline PFN_vkQueuePresentKHR next = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(VkQueue queue, const VkPresentInfoKHR* info) {
    if (deviceLost()) return VK_ERROR_DEVICE_LOST;
    const VkResult fault = presentationFault("vkQueuePresentKHR");
    if (fault == VK_ERROR_OUT_OF_DEVICE_MEMORY) return fault;
    const VkResult result = next(queue, info);
    return result == VK_SUCCESS ? fault : result;
  }
};

// vkQueueSubmit and vkQueueSubmit2: (queue, count, submits, fence).
template <const char* Name, typename Pfn>
struct Submission;
template <const char* Name, typename Submit>
struct Submission<Name, VkResult(VKAPI_PTR*)(VkQueue, std::uint32_t, const Submit*, VkFence)> {
  static inline VkResult(VKAPI_PTR* next)(VkQueue, std::uint32_t, const Submit*, VkFence) = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(VkQueue queue, std::uint32_t count,
                                             const Submit* submits, VkFence fence) {
    const bool lostBefore = deviceLost();
    switch (submitFate(Name)) {
      case SubmitFate::OutOfMemory:
        return VK_ERROR_OUT_OF_DEVICE_MEMORY;
      case SubmitFate::DeviceLost:
        // A lost device runs nothing more: what was submitted before is let finish now, so
        // that nothing is still running when the application, told the device is lost,
        // destroys it (on a real loss that work is abandoned instead).
        if (!lostBefore) state().nextQueueWaitIdle(queue);
        return VK_ERROR_DEVICE_LOST;
      case SubmitFate::Run:
        break;
    }
    return next(queue, count, submits, fence);
  }
};

struct Hook {
  const char* name;
  PFN_vkVoidFunction function;
  PFN_vkVoidFunction* next;
};

template <typename H>
Hook hook(const char* name) {
  return Hook{name, reinterpret_cast<PFN_vkVoidFunction>(&H::call),
              reinterpret_cast<PFN_vkVoidFunction*>(&H::next)};
}

#define FAULT_NAME(name) constexpr char k_##name[] = #name;
FAULT_NAME(vkAllocateMemory)
FAULT_NAME(vkCreateImage)
FAULT_NAME(vkCreateImageView)
FAULT_NAME(vkCreateBuffer)
FAULT_NAME(vkCreateSampler)
FAULT_NAME(vkCreateShaderModule)
FAULT_NAME(vkCreateDescriptorSetLayout)
FAULT_NAME(vkCreatePipelineLayout)
FAULT_NAME(vkCreateDescriptorPool)
FAULT_NAME(vkAllocateDescriptorSets)
FAULT_NAME(vkCreateQueryPool)
FAULT_NAME(vkCreateSemaphore)
FAULT_NAME(vkCreateFence)
FAULT_NAME(vkCreateCommandPool)
FAULT_NAME(vkAllocateCommandBuffers)
FAULT_NAME(vkCreateSwapchainKHR)
FAULT_NAME(vkCreateComputePipelines)
FAULT_NAME(vkCreateGraphicsPipelines)
FAULT_NAME(vkQueueSubmit)
FAULT_NAME(vkQueueSubmit2)
#undef FAULT_NAME

#define FAULT_CREATION(name) hook<Creation<k_##name, PFN_##name>>(#name)
#define FAULT_LOST_AWARE(name) hook<LostAware<PFN_##name>>(#name)
const Hook kHooks[] = {
    FAULT_CREATION(vkAllocateMemory),
    FAULT_CREATION(vkCreateImage),
    FAULT_CREATION(vkCreateImageView),
    FAULT_CREATION(vkCreateBuffer),
    FAULT_CREATION(vkCreateSampler),
    FAULT_CREATION(vkCreateShaderModule),
    FAULT_CREATION(vkCreateDescriptorSetLayout),
    FAULT_CREATION(vkCreatePipelineLayout),
    FAULT_CREATION(vkCreateDescriptorPool),
    FAULT_CREATION(vkAllocateDescriptorSets),
    FAULT_CREATION(vkCreateQueryPool),
    FAULT_CREATION(vkCreateSemaphore),
    FAULT_CREATION(vkCreateFence),
    FAULT_CREATION(vkCreateCommandPool),
    FAULT_CREATION(vkAllocateCommandBuffers),
    FAULT_CREATION(vkCreateSwapchainKHR),
    hook<PipelineCreation<k_vkCreateComputePipelines, VkComputePipelineCreateInfo>>(
        "vkCreateComputePipelines"),
    hook<PipelineCreation<k_vkCreateGraphicsPipelines, VkGraphicsPipelineCreateInfo>>(
        "vkCreateGraphicsPipelines"),
    hook<Submission<k_vkQueueSubmit, PFN_vkQueueSubmit>>("vkQueueSubmit"),
    hook<Submission<k_vkQueueSubmit2, PFN_vkQueueSubmit2>>("vkQueueSubmit2"),
    FAULT_LOST_AWARE(vkWaitSemaphores),
    FAULT_LOST_AWARE(vkGetSemaphoreCounterValue),
    FAULT_LOST_AWARE(vkDeviceWaitIdle),
    FAULT_LOST_AWARE(vkQueueWaitIdle),
    FAULT_LOST_AWARE(vkWaitForFences),
    FAULT_LOST_AWARE(vkGetFenceStatus),
    FAULT_LOST_AWARE(vkGetQueryPoolResults),
    hook<Acquire>("vkAcquireNextImageKHR"),
    hook<Present>("vkQueuePresentKHR"),
};
#undef FAULT_CREATION
#undef FAULT_LOST_AWARE

// --- The layer's entry points -------------------------------------------------------------
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faultGetDeviceProcAddr(VkDevice device, const char* name);
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faultGetInstanceProcAddr(VkInstance instance,
                                                                  const char* name);

template <typename Info, VkStructureType Type>
Info* findLinkInfo(const void* pNext) {
  auto* info = static_cast<Info*>(const_cast<void*>(pNext));
  while (info != nullptr && !(info->sType == Type && info->function == VK_LAYER_LINK_INFO)) {
    info = static_cast<Info*>(const_cast<void*>(info->pNext));
  }
  return info;
}

VKAPI_ATTR VkResult VKAPI_CALL faultCreateInstance(const VkInstanceCreateInfo* info,
                                                   const VkAllocationCallbacks* allocator,
                                                   VkInstance* instance) {
  auto* link =
      findLinkInfo<VkLayerInstanceCreateInfo, VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO>(
          info->pNext);
  if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;
  state().nextInstanceProcAddr = next;
  auto create = reinterpret_cast<PFN_vkCreateInstance>(next(nullptr, "vkCreateInstance"));
  return create(info, allocator, instance);
}

VKAPI_ATTR VkResult VKAPI_CALL faultCreateDevice(VkPhysicalDevice physical,
                                                 const VkDeviceCreateInfo* info,
                                                 const VkAllocationCallbacks* allocator,
                                                 VkDevice* device) {
  auto* link = findLinkInfo<VkLayerDeviceCreateInfo, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO>(
      info->pNext);
  if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr nextInstance = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  state().nextDeviceProcAddr = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;
  auto create = reinterpret_cast<PFN_vkCreateDevice>(nextInstance(nullptr, "vkCreateDevice"));
  const VkResult result = create(physical, info, allocator, device);
  if (result == VK_SUCCESS) {
    state().nextQueueWaitIdle = reinterpret_cast<PFN_vkQueueWaitIdle>(
        state().nextDeviceProcAddr(*device, "vkQueueWaitIdle"));
  }
  return result;
}

VKAPI_ATTR void VKAPI_CALL faultDestroyDevice(VkDevice device,
                                              const VkAllocationCallbacks* allocator) {
  writeReport();
  auto destroy =
      reinterpret_cast<PFN_vkDestroyDevice>(state().nextDeviceProcAddr(device, "vkDestroyDevice"));
  destroy(device, allocator);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faultGetDeviceProcAddr(VkDevice device, const char* name) {
  if (std::strcmp(name, "vkGetDeviceProcAddr") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultGetDeviceProcAddr);
  }
  if (std::strcmp(name, "vkDestroyDevice") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultDestroyDevice);
  }
  const PFN_vkVoidFunction next = state().nextDeviceProcAddr(device, name);
  if (next == nullptr) return nullptr;
  for (const Hook& h : kHooks) {
    if (std::strcmp(h.name, name) == 0) {
      *h.next = next;
      return h.function;
    }
  }
  return next;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL faultGetInstanceProcAddr(VkInstance instance,
                                                                  const char* name) {
  if (std::strcmp(name, "vkGetInstanceProcAddr") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultGetInstanceProcAddr);
  }
  if (std::strcmp(name, "vkCreateInstance") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultCreateInstance);
  }
  if (std::strcmp(name, "vkCreateDevice") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultCreateDevice);
  }
  if (std::strcmp(name, "vkGetDeviceProcAddr") == 0) {
    return reinterpret_cast<PFN_vkVoidFunction>(&faultGetDeviceProcAddr);
  }
  if (state().nextInstanceProcAddr == nullptr) return nullptr;
  return state().nextInstanceProcAddr(instance, name);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) VKAPI_ATTR VkResult VKAPI_CALL
vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* interface) {
  if (interface == nullptr || interface->loaderLayerInterfaceVersion < 2) {
    return VK_ERROR_INITIALIZATION_FAILED;
  }
  interface->loaderLayerInterfaceVersion = 2;
  interface->pfnGetInstanceProcAddr = &faultGetInstanceProcAddr;
  interface->pfnGetDeviceProcAddr = &faultGetDeviceProcAddr;
  interface->pfnGetPhysicalDeviceProcAddr = nullptr;
  return VK_SUCCESS;
}
