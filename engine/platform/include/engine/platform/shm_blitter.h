#pragma once
// Puts a frame's pixels into an X11 window through MIT-SHM: the X server copies them out of a
// segment shared with this process instead of reading them off its socket.
//
// Why: a software Vulkan device (lavapipe) presents through Mesa's X11 WSI, which on a server
// without DRI3 (Xvfb) sends every frame as one PutImage request. Xvfb spent 4.1 ms of CPU a
// frame on that at 640x360 on the 2-core CI machine, where the server's CPU is the renderer's;
// a shared-memory put of the same frame costs it about 0.2 ms (docs/measurements.md).
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace engine::platform {

class Window;

class ShmBlitter {
 public:
  // Null (with the reason in `whyNot`, if given) when the window is not on X11, the server has
  // no MIT-SHM or cannot attach this process's memory (a remote server), or the window's visual
  // is not 24-bit little-endian BGRX, the layout of VK_FORMAT_B8G8R8A8_*.
  static std::unique_ptr<ShmBlitter> create(Window& window, std::string* whyNot = nullptr);
  ~ShmBlitter();
  ShmBlitter(const ShmBlitter&) = delete;
  ShmBlitter& operator=(const ShmBlitter&) = delete;

  // The rows of the next frame, `extent` wide and high, tightly packed (4 bytes a pixel, B G R
  // and an ignored byte); the segment is remade when the extent changes.
  std::span<std::byte> pixels(VkExtent2D extent);
  // Copies the pixels into the window (top-left) and waits until the server has read them, so
  // the next frame may overwrite the segment.
  void put();
  std::uint64_t puts() const { return puts_; }
  // The window's pixels as the server holds them, 0x00RRGGBB, `extent` of the last put (tests).
  std::vector<std::uint32_t> readWindow() const;

 private:
  struct X11;
  explicit ShmBlitter(std::unique_ptr<X11> x11);
  void release();

  std::unique_ptr<X11> x11_;
  VkExtent2D extent_{0, 0};
  std::uint64_t puts_ = 0;
};

}  // namespace engine::platform
