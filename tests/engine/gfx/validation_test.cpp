// The validation plumbing itself: a clean operation produces no message, and a deliberate
// violation is caught by the handler that turns messages into test failures (negative control).
#include <gtest/gtest.h>

#include "gpu_test.h"

namespace {

class Validation : public test::GpuTest {};

TEST_F(Validation, LayerIsActive) {
  EXPECT_TRUE(instance().validationEnabled());
}

TEST_F(Validation, InjectedViolationIsCaught) {
  // VUID-VkBufferCreateInfo-usage-requiredbitmask: usage must not be 0. Drivers tolerate it,
  // so only the validation layer can notice.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 64;
  info.usage = 0;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(device().vk(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(device().vk(), buffer, nullptr);

  const auto messages = takeMessages();  // taken, so this test's TearDown stays clean
  ASSERT_FALSE(messages.empty()) << "the validation layer did not report the violation";
  bool found = false;
  for (const auto& m : messages) {
    found = found || m.idName.find("VkBufferCreateInfo-usage") != std::string::npos;
  }
  EXPECT_TRUE(found) << "first message: " << messages.front().idName << " "
                     << messages.front().text;
}

TEST_F(Validation, CleanWorkProducesNoMessages) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 64;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateBuffer(device().vk(), &info, nullptr, &buffer), VK_SUCCESS);
  vkDestroyBuffer(device().vk(), buffer, nullptr);
  EXPECT_TRUE(takeMessages().empty());
}

}  // namespace
