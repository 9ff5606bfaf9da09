// A real window and swapchain (under Xvfb in CI): frames present, a resize rebuilds the
// swapchain at the new size, a 0x0 framebuffer (minimized) leaves no swapchain and renders
// nothing, and restoring the size brings it back; a storm of 300 resizes stays valid and
// settles. Validation-clean throughout.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "engine/gfx/barriers.h"
#include "engine/gfx/device.h"
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/instance.h"
#include "engine/platform/window.h"
#include "engine/render/present_target.h"

namespace {

using namespace engine;

// Clears the acquired image (attachment clear) and presents it; returns false when nothing was
// acquired.
bool renderClearFrame(gfx::FrameRing& ring, render::SwapchainTarget& target) {
  auto& frame = ring.begin();
  if (!target.acquire(frame.slot)) {
    ring.submit();
    return false;
  }
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  const gfx::ImageState attachment{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
  gfx::imageBarrier(frame.cmd, target.image(), range,
                    {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, 0},
                    attachment);
  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  colour.imageView = target.view();
  colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.clearValue.color = {{0.1f, 0.2f, 0.8f, 1.0f}};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, target.extent()};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &colour;
  vkCmdBeginRendering(frame.cmd, &rendering);
  vkCmdEndRendering(frame.cmd);
  gfx::imageBarrier(frame.cmd, target.image(), range, attachment,
                    {VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0});
  ring.submit(target.submitWaits(), target.submitSignals());
  target.present();
  return true;
}

TEST(WindowSwapchain, ResizeAndMinimizeAreHandled) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  platform::Window window(platform::WindowDesc{"window test", 320, 180});
  gfx::InstanceDesc desc;
  desc.validation = true;
  desc.extensions = window.requiredInstanceExtensions();
  gfx::Instance instance(desc);
  std::vector<std::string> messages;
  instance.setValidationHandler(
      [&](const gfx::ValidationMessage& m) { messages.push_back(m.text); });
  VkSurfaceKHR surface = window.createSurface(instance.vk());
  {
    gfx::Device device(instance, gfx::DeviceDesc{surface, ""});
    gfx::FrameRing ring(device);
    render::SwapchainTarget target(device, surface, /*vsync=*/false);

    target.resize(window.framebufferExtent());
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(renderClearFrame(ring, target));
    EXPECT_EQ(target.extent().width, 320u);
    EXPECT_EQ(target.extent().height, 180u);
    const auto rebuildsBefore = target.swapchain().rebuildCount();

    window.setSize(200, 100);
    VkExtent2D extent{};
    for (int i = 0; i < 100 && (extent.width != 200 || extent.height != 100); ++i) {
      window.pollEvents();
      extent = window.framebufferExtent();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(extent.width, 200u) << "the window system did not resize the window";
    target.resize(extent);
    EXPECT_TRUE(renderClearFrame(ring, target));
    EXPECT_EQ(target.extent().width, 200u);
    EXPECT_EQ(target.extent().height, 100u);
    EXPECT_GT(target.swapchain().rebuildCount(), rebuildsBefore);

    // Minimized: a 0x0 framebuffer. No swapchain, nothing acquired, frames are skipped.
    target.resize({0, 0});
    EXPECT_FALSE(renderClearFrame(ring, target));
    EXPECT_FALSE(target.swapchain().hasImages());
    EXPECT_FALSE(renderClearFrame(ring, target));

    target.resize(window.framebufferExtent());
    EXPECT_TRUE(renderClearFrame(ring, target));
    EXPECT_TRUE(target.swapchain().hasImages());
    ring.drain();
  }
  window.destroySurface();
  EXPECT_TRUE(messages.empty()) << messages.front();
}

// A resize storm: 300 sizes in a row (a user dragging a window's corner, then a minimize every
// tenth step), each followed at once by a frame, as the sample's loop does, without waiting for
// the window system to catch up. Every frame is clean under validation, the swapchain always has
// the extent it was last given, and after the storm it settles at the window's final size.
TEST(WindowSwapchain, AResizeStormStaysValidAndSettles) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  platform::Window window(platform::WindowDesc{"resize storm", 320, 180});
  gfx::InstanceDesc desc;
  desc.validation = true;
  desc.extensions = window.requiredInstanceExtensions();
  gfx::Instance instance(desc);
  std::vector<std::string> messages;
  instance.setValidationHandler(
      [&](const gfx::ValidationMessage& m) { messages.push_back(m.text); });
  VkSurfaceKHR surface = window.createSurface(instance.vk());
  {
    gfx::Device device(instance, gfx::DeviceDesc{surface, ""});
    gfx::FrameRing ring(device);
    render::SwapchainTarget target(device, surface, /*vsync=*/false);
    target.resize(window.framebufferExtent());
    const auto rebuildsBefore = target.swapchain().rebuildCount();
    int presented = 0;
    for (std::uint32_t step = 0; step < 300; ++step) {
      // Sizes wander over 64..575 x 48..431 (a fixed sequence, so a failure reproduces).
      const std::uint32_t width = 64 + (step * 97) % 512;
      const std::uint32_t height = 48 + (step * 61) % 384;
      window.setSize(width, height);
      window.pollEvents();
      const VkExtent2D extent = step % 10 == 9 ? VkExtent2D{0, 0} : window.framebufferExtent();
      target.resize(extent);
      if (renderClearFrame(ring, target)) ++presented;
      if (extent.width > 0 && extent.height > 0) {
        ASSERT_EQ(target.extent().width, extent.width) << "step " << step;
        ASSERT_EQ(target.extent().height, extent.height) << "step " << step;
      }
      ASSERT_TRUE(messages.empty()) << "step " << step << ": " << messages.front();
    }
    EXPECT_GT(presented, 200) << "most frames of the storm must present";
    const auto rebuilds = target.swapchain().rebuildCount() - rebuildsBefore;
    std::printf("resize storm: %d frames presented, %llu swapchain rebuilds\n", presented,
                static_cast<unsigned long long>(rebuilds));
    EXPECT_GT(rebuilds, 100u) << "the storm must reach the swapchain";
    // Settled: the last size requested reaches the framebuffer, and a frame presents at it.
    window.setSize(300, 200);
    VkExtent2D extent{};
    for (int i = 0; i < 100 && (extent.width != 300 || extent.height != 200); ++i) {
      window.pollEvents();
      extent = window.framebufferExtent();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(extent.width, 300u) << "the window system did not settle at the last size";
    target.resize(extent);
    EXPECT_TRUE(renderClearFrame(ring, target));
    EXPECT_EQ(target.extent().width, 300u);
    EXPECT_EQ(target.extent().height, 200u);
    ring.drain();
  }
  window.destroySurface();
  // Destroying the device with an object still alive would be a message here too.
  EXPECT_TRUE(messages.empty()) << messages.front();
}

}  // namespace
