#pragma once
// A vkGetDeviceProcAddr to hand a module (clouds, atmosphere) instead of the loader's: every
// object the module creates and every command it records goes through it. It counts them, keeps the
// set of objects still alive, and can make the Nth creation fail with VK_ERROR_OUT_OF_DEVICE_MEMORY
// (fault injection). One shim per process; not thread-safe.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <string>

namespace test::shim {

struct Counts {
  int creations = 0;  // vkCreate*, vkAllocateMemory and vkAllocateDescriptorSets calls
  int commands = 0;   // vkCmd* calls
  // Objects created and not destroyed yet, with the call that made them (descriptor sets
  // are freed with their pool and not listed).
  std::map<std::uint64_t, std::string> live;
};

// The proc-addr function to put in a module's CreateInfo::getDeviceProcAddr.
PFN_vkGetDeviceProcAddr getDeviceProcAddr();
Counts& counts();
// Zeroes the counts (the live set stays).
void resetCounts();
// Makes the `n`-th creation from now fail (1: the next one); 0 turns failures off.
void failCreation(int n);
// Whether a failure was injected since failCreation() armed it.
bool failed();

}  // namespace test::shim
