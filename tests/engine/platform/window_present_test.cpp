// A real window (under Xvfb in CI), presented both ways a window target can.
// The swapchain: frames present, a resize rebuilds the swapchain at the new size, a 0x0
// framebuffer (minimized) leaves no swapchain and renders nothing, and restoring the size brings
// it back; a storm of 300 resizes stays valid and settles.
// MIT-SHM (ShmWindowTarget): what the frame graph draws is what the window's pixels hold, in
// the right channel order; a resize and a minimize are followed.
// Validation-clean throughout.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "engine/gfx/barriers.h"
#include "engine/gfx/device.h"
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/instance.h"
#include "engine/platform/shm_blitter.h"
#include "engine/platform/window.h"
#include "engine/render/frame_graph.h"
#include "engine/render/present_target.h"
#include "engine/render/shm_window_target.h"

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

// What a test gets inside a real window: a validated device, a frame ring and a window target
// sized to the window, and the validation messages so far.
template <typename Target>
struct Windowed {
  platform::Window& window;
  gfx::Device& device;
  gfx::FrameRing& ring;
  Target& target;
  const std::vector<std::string>& messages;
};

// Runs `body` with a `width` x `height` window and the target `makeTarget(device, surface,
// window)` returns, then drains the ring, destroys everything and expects no validation message
// (destroying the device with an object alive would be one).
template <typename Target, typename MakeTarget, typename Body>
void withWindow(const char* title, std::uint32_t width, std::uint32_t height,
                MakeTarget&& makeTarget, Body&& body) {
  platform::Window window(platform::WindowDesc{title, width, height});
  gfx::InstanceDesc desc;
  desc.validation = true;
  desc.extensions = window.requiredInstanceExtensions();
  std::vector<std::string> messages;  // before the instance: its teardown may still report
  gfx::Instance instance(desc);
  instance.setValidationHandler(
      [&](const gfx::ValidationMessage& m) { messages.push_back(m.text); });
  {
    const platform::Surface surface = window.createSurface(instance.vk());
    gfx::Device device(instance, gfx::DeviceDesc{surface.vk(), ""});
    gfx::FrameRing ring(device);
    std::unique_ptr<Target> target = makeTarget(device, surface.vk(), window);
    if (!target) return;  // makeTarget reported why
    target->resize(window.framebufferExtent());
    Windowed<Target> windowed{window, device, ring, *target, messages};
    body(windowed);
    ring.drain();
  }
  EXPECT_TRUE(messages.empty()) << messages.front();
}

// A swapchain window: the sample's path on a device with its own memory.
template <typename Body>
void withSwapchainWindow(const char* title, std::uint32_t width, std::uint32_t height,
                         Body&& body) {
  withWindow<render::SwapchainTarget>(
      title, width, height,
      [](gfx::Device& device, VkSurfaceKHR surface, platform::Window&) {
        return std::make_unique<render::SwapchainTarget>(device, surface, /*vsync=*/false);
      },
      std::forward<Body>(body));
}

// Asks the window system for a size and polls (up to a second) until the framebuffer has it;
// returns the framebuffer's extent then.
VkExtent2D resizeAndWait(platform::Window& window, std::uint32_t width, std::uint32_t height) {
  window.setSize(width, height);
  VkExtent2D extent{};
  for (int i = 0; i < 100 && (extent.width != width || extent.height != height); ++i) {
    window.pollEvents();
    extent = window.framebufferExtent();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return extent;
}

TEST(WindowSwapchain, ResizeAndMinimizeAreHandled) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  withSwapchainWindow("window test", 320, 180, [](Windowed<render::SwapchainTarget>& w) {
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(renderClearFrame(w.ring, w.target));
    EXPECT_EQ(w.target.extent().width, 320u);
    EXPECT_EQ(w.target.extent().height, 180u);
    const auto rebuildsBefore = w.target.swapchain().rebuildCount();

    const VkExtent2D extent = resizeAndWait(w.window, 200, 100);
    ASSERT_EQ(extent.width, 200u) << "the window system did not resize the window";
    w.target.resize(extent);
    EXPECT_TRUE(renderClearFrame(w.ring, w.target));
    EXPECT_EQ(w.target.extent().width, 200u);
    EXPECT_EQ(w.target.extent().height, 100u);
    EXPECT_GT(w.target.swapchain().rebuildCount(), rebuildsBefore);

    // Minimized: a 0x0 framebuffer. No swapchain, nothing acquired, frames are skipped.
    w.target.resize({0, 0});
    EXPECT_FALSE(renderClearFrame(w.ring, w.target));
    EXPECT_FALSE(w.target.swapchain().hasImages());
    EXPECT_FALSE(renderClearFrame(w.ring, w.target));

    w.target.resize(w.window.framebufferExtent());
    EXPECT_TRUE(renderClearFrame(w.ring, w.target));
    EXPECT_TRUE(w.target.swapchain().hasImages());
  });
}

// A resize storm: 300 sizes in a row (a user dragging a window's corner, then a minimize every
// tenth step), each followed at once by a frame, as the sample's loop does, without waiting for
// the window system to catch up. Every frame is clean under validation, the swapchain always has
// the extent it was last given, and after the storm it settles at the window's final size.
TEST(WindowSwapchain, AResizeStormStaysValidAndSettles) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  withSwapchainWindow("resize storm", 320, 180, [](Windowed<render::SwapchainTarget>& w) {
    const auto rebuildsBefore = w.target.swapchain().rebuildCount();
    int presented = 0;
    for (std::uint32_t step = 0; step < 300; ++step) {
      // Sizes wander over 64..575 x 48..431 (a fixed sequence, so a failure reproduces).
      w.window.setSize(64 + (step * 97) % 512, 48 + (step * 61) % 384);
      w.window.pollEvents();
      const VkExtent2D extent = step % 10 == 9 ? VkExtent2D{0, 0} : w.window.framebufferExtent();
      w.target.resize(extent);
      if (renderClearFrame(w.ring, w.target)) ++presented;
      if (extent.width > 0 && extent.height > 0) {
        ASSERT_EQ(w.target.extent().width, extent.width) << "step " << step;
        ASSERT_EQ(w.target.extent().height, extent.height) << "step " << step;
      }
      ASSERT_TRUE(w.messages.empty()) << "step " << step << ": " << w.messages.front();
    }
    EXPECT_GT(presented, 200) << "most frames of the storm must present";
    const auto rebuilds = w.target.swapchain().rebuildCount() - rebuildsBefore;
    std::printf("resize storm: %d frames presented, %llu swapchain rebuilds\n", presented,
                static_cast<unsigned long long>(rebuilds));
    EXPECT_GT(rebuilds, 100u) << "the storm must reach the swapchain";
    // Settled: the last size requested reaches the framebuffer, and a frame presents at it.
    const VkExtent2D extent = resizeAndWait(w.window, 300, 200);
    ASSERT_EQ(extent.width, 300u) << "the window system did not settle at the last size";
    w.target.resize(extent);
    EXPECT_TRUE(renderClearFrame(w.ring, w.target));
    EXPECT_EQ(w.target.extent().width, 300u);
    EXPECT_EQ(w.target.extent().height, 200u);
  });
}

// A window presented through MIT-SHM: the sample's path for a software device (lavapipe).
template <typename Body>
void withShmWindow(const char* title, std::uint32_t width, std::uint32_t height, Body&& body) {
  withWindow<render::ShmWindowTarget>(
      title, width, height,
      [](gfx::Device& device, VkSurfaceKHR, platform::Window& window) {
        std::string whyNot;
        auto blitter = platform::ShmBlitter::create(window, &whyNot);
        // Xvfb, the tests' server, is local and has MIT-SHM: no blitter there is a failure.
        if (!blitter) ADD_FAILURE() << "no MIT-SHM blitter: " << whyNot;
        return blitter ? std::make_unique<render::ShmWindowTarget>(device, std::move(blitter))
                       : nullptr;
      },
      std::forward<Body>(body));
}

// Draws one frame the way the sample does (a frame graph ending in the target's own passes):
// the image cleared to `linear`, then presented. False when nothing was acquired (minimized).
bool renderShmFrame(Windowed<render::ShmWindowTarget>& w, VkClearColorValue linear) {
  auto& frame = w.ring.begin();
  if (!w.target.acquire(frame.slot)) {
    w.ring.submit();
    return false;
  }
  render::FrameGraph graph(&w.device);
  const render::TextureHandle image = graph.importTexture("window image", w.target.describe());
  struct Data {
    render::TextureHandle image;
  };
  const Data& cleared = graph.addPass<Data>(
      "clear", render::PassType::Graphics,
      [&](render::PassBuilder& builder, Data& d) {
        d.image = builder.colorAttachment(image, VK_ATTACHMENT_LOAD_OP_CLEAR, linear);
      },
      [](const Data&, render::PassContext&) {});
  w.target.addToGraph(graph, cleared.image);
  graph.compile();
  graph.execute(frame);
  w.ring.submit(w.target.submitWaits(), w.target.submitSignals());
  w.target.present();
  return true;
}

// The 8-bit sRGB encoding of a linear value, as an _SRGB attachment stores it.
std::uint32_t srgbByte(float linear) {
  const double encoded =
      linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(double(linear), 1.0 / 2.4) - 0.055;
  return static_cast<std::uint32_t>(std::lround(encoded * 255.0));
}

// Counts the window's pixels that differ from 0xRRGGBB by more than one step in a channel.
std::size_t pixelsOff(const std::vector<std::uint32_t>& pixels, std::uint32_t rgb) {
  std::size_t off = 0;
  for (std::uint32_t p : pixels) {
    for (int shift : {0, 8, 16}) {
      const int got = int((p >> shift) & 0xffu);
      const int want = int((rgb >> shift) & 0xffu);
      if (std::abs(got - want) > 1) {
        ++off;
        break;
      }
    }
  }
  return off;
}

TEST(WindowShm, AFrameReachesTheWindowInItsColours) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  withShmWindow("shm window", 320, 180, [](Windowed<render::ShmWindowTarget>& w) {
    // Three channels apart, so a red-blue swap shows.
    const VkClearColorValue linear{{0.2f, 0.4f, 0.8f, 1.0f}};
    const std::uint32_t rgb = srgbByte(0.2f) << 16 | srgbByte(0.4f) << 8 | srgbByte(0.8f);
    ASSERT_TRUE(renderShmFrame(w, linear));
    EXPECT_EQ(w.target.extent().width, 320u);
    EXPECT_EQ(w.target.extent().height, 180u);
    EXPECT_EQ(w.target.blitter().puts(), 1u);
    const std::vector<std::uint32_t> shown = w.target.blitter().readWindow();
    ASSERT_EQ(shown.size(), 320u * 180u);
    EXPECT_EQ(pixelsOff(shown, rgb), 0u)
        << "first pixel 0x" << std::hex << shown[0] << ", want 0x" << rgb;
    // The next frame replaces it: the window follows the frames, not the first one.
    ASSERT_TRUE(renderShmFrame(w, VkClearColorValue{{1.0f, 0.0f, 0.0f, 1.0f}}));
    EXPECT_EQ(pixelsOff(w.target.blitter().readWindow(), 0xff0000u), 0u);
  });
}

TEST(WindowShm, ResizeAndMinimizeAreFollowed) {
  if (!platform::Window::displayAvailable()) GTEST_SKIP() << "no display (run under xvfb-run)";
  withShmWindow("shm window resize", 320, 180, [](Windowed<render::ShmWindowTarget>& w) {
    const VkClearColorValue green{{0.0f, 1.0f, 0.0f, 1.0f}};
    ASSERT_TRUE(renderShmFrame(w, green));
    const VkExtent2D extent = resizeAndWait(w.window, 200, 100);
    ASSERT_EQ(extent.width, 200u) << "the window system did not resize the window";
    w.target.resize(extent);
    ASSERT_TRUE(renderShmFrame(w, green));
    EXPECT_EQ(w.target.extent().width, 200u);
    EXPECT_EQ(w.target.extent().height, 100u);
    const std::vector<std::uint32_t> shown = w.target.blitter().readWindow();
    ASSERT_EQ(shown.size(), 200u * 100u);
    EXPECT_EQ(pixelsOff(shown, 0x00ff00u), 0u);

    // Minimized: nothing acquired, drawn or put.
    const std::uint64_t puts = w.target.blitter().puts();
    w.target.resize({0, 0});
    EXPECT_FALSE(renderShmFrame(w, green));
    EXPECT_EQ(w.target.blitter().puts(), puts);
    w.target.resize(w.window.framebufferExtent());
    EXPECT_TRUE(renderShmFrame(w, green));
    EXPECT_EQ(w.target.blitter().puts(), puts + 1);
  });
}

}  // namespace
