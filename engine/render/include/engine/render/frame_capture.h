#pragma once
// Frame capture: a transfer pass that, when armed, copies the display image (8-bit, what the
// window shows) and the HDR scene image into host-visible buffers; after the frame has retired
// the capture writes them as PNG and EXR. Used by headless runs, screenshots and tests.
#include <filesystem>
#include <optional>
#include <string>

#include "engine/assets/image_io.h"
#include "engine/gfx/resources.h"
#include "engine/render/frame_graph.h"

namespace engine::render {

class FrameCapture {
 public:
  explicit FrameCapture(gfx::Device& device);

  // Adds the "capture" pass reading `display` and `hdr`. Call on every graph build.
  void addToGraph(FrameGraph& graph, TextureHandle hdr, TextureHandle display);

  // The next executed frame is captured to `<stem>.png` and `<stem>.exr`.
  void arm(std::filesystem::path stem);
  bool armed() const { return armed_.has_value(); }
  // Once the captured frame has retired on the GPU: converts and writes the files, returns
  // the PNG path. Returns nullopt when nothing was captured.
  std::optional<std::filesystem::path> writePending();

  // The last captured images (for tests and tools).
  const assets::ImageRgba8& lastDisplay() const { return display_; }
  const assets::ImageRgba32f& lastHdr() const { return hdr_; }

 private:
  void ensureBuffers(VkExtent2D extent, VkFormat displayFormat, VkFormat hdrFormat);

  gfx::Device& device_;
  gfx::Buffer displayBuffer_;
  gfx::Buffer hdrBuffer_;
  VkExtent2D extent_{0, 0};
  VkFormat displayFormat_ = VK_FORMAT_UNDEFINED;
  VkFormat hdrFormat_ = VK_FORMAT_UNDEFINED;
  std::optional<std::filesystem::path> armed_;     // waiting for the next execute
  std::optional<std::filesystem::path> inFlight_;  // copied, waiting to be written
  assets::ImageRgba8 display_;
  assets::ImageRgba32f hdr_;
};

}  // namespace engine::render
