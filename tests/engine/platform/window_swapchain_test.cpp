// A real window and swapchain (under Xvfb in CI): frames present, a resize rebuilds the
// swapchain at the new size, a 0x0 framebuffer (minimized) leaves no swapchain and renders
// nothing, and restoring the size brings it back. Validation-clean throughout.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

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

}  // namespace
