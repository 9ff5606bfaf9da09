#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/gfx/device_selection.h"

namespace {

using engine::gfx::chooseDevice;
using engine::gfx::DeviceCandidate;

std::vector<DeviceCandidate> typicalMachine() {
  return {
      {"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, true, ""},
      {"Intel(R) UHD Graphics 630", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, true, ""},
      {"NVIDIA GeForce RTX 4070", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, true, ""},
      {"Old GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, false, "Vulkan 1.3 not supported"},
  };
}

TEST(DeviceSelection, PrefersDiscreteThenIntegratedThenCpu) {
  EXPECT_EQ(chooseDevice(typicalMachine(), ""), 2u);
  auto noDiscrete = typicalMachine();
  noDiscrete[2].suitable = false;
  EXPECT_EQ(chooseDevice(noDiscrete, ""), 1u);
  EXPECT_EQ(chooseDevice({typicalMachine()[0]}, ""), 0u);
}

TEST(DeviceSelection, PreferenceForcesCpuGpuOrName) {
  EXPECT_EQ(chooseDevice(typicalMachine(), "cpu"), 0u);
  EXPECT_EQ(chooseDevice(typicalMachine(), "gpu"), 2u);
  EXPECT_EQ(chooseDevice(typicalMachine(), "intel"), 1u);
  EXPECT_EQ(chooseDevice(typicalMachine(), "LLVMPIPE"), 0u);
}

TEST(DeviceSelection, ExplainsWhyNothingMatches) {
  try {
    chooseDevice({typicalMachine()[0], typicalMachine()[3]}, "gpu");
    FAIL() << "expected an error";
  } catch (const engine::Error& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("llvmpipe"), std::string::npos);
    EXPECT_NE(text.find("Vulkan 1.3 not supported"), std::string::npos);
  }
  EXPECT_THROW(chooseDevice({}, ""), engine::Error);
}

}  // namespace
