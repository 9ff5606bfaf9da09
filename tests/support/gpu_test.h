#pragma once
// GoogleTest fixture for GPU tests. One Vulkan instance (validation always on) and device per
// test binary; every validation message during a test fails that test, with its text. Tests
// that provoke messages on purpose (the negative control) take them with takeMessages().
#include <gtest/gtest.h>

#include <memory>
#include <mutex>
#include <vector>

#include "engine/gfx/device.h"
#include "engine/gfx/instance.h"

namespace test {

class GpuTest : public ::testing::Test {
 public:
  static engine::gfx::Instance& instance();
  static engine::gfx::Device& device();
  // Messages received since the test started (clears them, so TearDown sees none).
  static std::vector<engine::gfx::ValidationMessage> takeMessages();

 protected:
  void SetUp() override;
  void TearDown() override;
};

}  // namespace test
