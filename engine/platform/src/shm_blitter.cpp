#include "engine/platform/shm_blitter.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstring>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/platform/window.h"

namespace engine::platform {
namespace {

// XShmAttach fails asynchronously (BadAccess from a remote server): an error handler installed
// around the attach and its round trip turns that into a return value.
bool gAttachFailed = false;
int onAttachError(Display*, XErrorEvent*) {
  gAttachFailed = true;
  return 0;
}

}  // namespace

struct ShmBlitter::X11 {
  Display* display = nullptr;
  ::Window window = 0;
  Visual* visual = nullptr;
  GC gc = nullptr;
  XImage* image = nullptr;  // the frame's XImage over `segment`
  XShmSegmentInfo segment{};
};

std::unique_ptr<ShmBlitter> ShmBlitter::create(Window& window, std::string* whyNot) {
  const auto fail = [&](const char* reason) {
    if (whyNot) *whyNot = reason;
    return std::unique_ptr<ShmBlitter>();
  };
  const Window::X11Handles handles = window.x11();
  if (handles.display == nullptr) return fail("the window is not on X11");
  auto x11 = std::make_unique<X11>();
  x11->display = static_cast<Display*>(handles.display);
  x11->window = handles.window;
  if (!XShmQueryExtension(x11->display)) return fail("the X server has no MIT-SHM");
  XWindowAttributes attributes{};
  if (!XGetWindowAttributes(x11->display, x11->window, &attributes)) {
    return fail("the window's attributes cannot be read");
  }
  const Visual* visual = attributes.visual;
  if (attributes.depth != 24 || visual->red_mask != 0xff0000 || visual->green_mask != 0xff00 ||
      visual->blue_mask != 0xff || ImageByteOrder(x11->display) != LSBFirst) {
    return fail("the window's visual is not 24-bit little-endian BGRX");
  }
  x11->visual = attributes.visual;
  // A probe segment: a remote server cannot attach it, and the error says so.
  XShmSegmentInfo probe{};
  probe.shmid = shmget(IPC_PRIVATE, 4096, IPC_CREAT | 0600);
  if (probe.shmid < 0) return fail("shmget failed");
  probe.shmaddr = static_cast<char*>(shmat(probe.shmid, nullptr, 0));
  if (probe.shmaddr == reinterpret_cast<char*>(-1)) {
    shmctl(probe.shmid, IPC_RMID, nullptr);
    return fail("shmat failed");
  }
  probe.readOnly = True;
  XSync(x11->display, False);
  gAttachFailed = false;
  XErrorHandler previous = XSetErrorHandler(onAttachError);
  const bool requested = XShmAttach(x11->display, &probe);
  XSync(x11->display, False);  // the attach's error, if any, arrives here
  XSetErrorHandler(previous);
  const bool usable = requested && !gAttachFailed;
  if (usable) XShmDetach(x11->display, &probe);
  XSync(x11->display, False);
  shmdt(probe.shmaddr);
  shmctl(probe.shmid, IPC_RMID, nullptr);
  if (!usable) return fail("the X server cannot attach this process's memory (remote?)");
  x11->gc = XCreateGC(x11->display, x11->window, 0, nullptr);
  return std::unique_ptr<ShmBlitter>(new ShmBlitter(std::move(x11)));
}

ShmBlitter::ShmBlitter(std::unique_ptr<X11> x11) : x11_(std::move(x11)) {}

ShmBlitter::~ShmBlitter() {
  release();
  XFreeGC(x11_->display, x11_->gc);
  XSync(x11_->display, False);
}

void ShmBlitter::release() {
  if (x11_->image == nullptr) return;
  XShmDetach(x11_->display, &x11_->segment);
  XSync(x11_->display, False);  // the server lets go before the memory does
  x11_->image->data = nullptr;  // the segment is ours: XDestroyImage would free() it
  XDestroyImage(x11_->image);
  shmdt(x11_->segment.shmaddr);
  x11_->image = nullptr;
  x11_->segment = {};
  extent_ = {0, 0};
}

std::span<std::byte> ShmBlitter::pixels(VkExtent2D extent) {
  require(extent.width > 0 && extent.height > 0, "ShmBlitter", "an empty frame has no pixels");
  if (extent.width != extent_.width || extent.height != extent_.height) {
    release();
    X11& x = *x11_;
    const std::size_t bytes = std::size_t{extent.width} * extent.height * 4;
    // The image keeps a pointer to its segment's info (XShmPutImage reads it): x.segment, which
    // lives as long as the blitter.
    XShmSegmentInfo& segment = x.segment;
    segment = {};
    segment.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
    if (segment.shmid < 0)
      throw Error("ShmBlitter: shmget of " + std::to_string(bytes) + " failed");
    segment.shmaddr = static_cast<char*>(shmat(segment.shmid, nullptr, 0));
    XImage* image = segment.shmaddr == reinterpret_cast<char*>(-1)
                        ? nullptr
                        : XShmCreateImage(x.display, x.visual, 24, ZPixmap, segment.shmaddr,
                                          &segment, extent.width, extent.height);
    if (image == nullptr || image->bits_per_pixel != 32 ||
        image->bytes_per_line != static_cast<int>(extent.width * 4)) {
      if (image != nullptr) {
        image->data = nullptr;
        XDestroyImage(image);
      }
      if (segment.shmaddr != reinterpret_cast<char*>(-1)) shmdt(segment.shmaddr);
      shmctl(segment.shmid, IPC_RMID, nullptr);
      segment = {};
      throw Error("ShmBlitter: no 32-bit, tightly packed shared image of " +
                  std::to_string(extent.width) + "x" + std::to_string(extent.height));
    }
    segment.readOnly = True;
    XShmAttach(x.display, &segment);
    XSync(x.display, False);
    // Marked for removal once both sides have it attached: it goes when both detach, also if
    // this process dies.
    shmctl(segment.shmid, IPC_RMID, nullptr);
    x.image = image;
    extent_ = extent;
  }
  return {reinterpret_cast<std::byte*>(x11_->segment.shmaddr),
          std::size_t{extent_.width} * extent_.height * 4};
}

void ShmBlitter::put() {
  require(x11_->image != nullptr, "ShmBlitter", "put() before pixels()");
  X11& x = *x11_;
  XShmPutImage(x.display, x.window, x.gc, x.image, 0, 0, 0, 0, extent_.width, extent_.height,
               False);
  XSync(x.display, False);  // the server has copied the segment: the next frame may write it
  ++puts_;
}

std::vector<std::uint32_t> ShmBlitter::readWindow() const {
  std::vector<std::uint32_t> pixels;
  if (extent_.width == 0) return pixels;
  XImage* image = XGetImage(x11_->display, x11_->window, 0, 0, extent_.width, extent_.height,
                            AllPlanes, ZPixmap);
  if (image == nullptr) return pixels;
  pixels.reserve(std::size_t{extent_.width} * extent_.height);
  for (std::uint32_t y = 0; y < extent_.height; ++y) {
    for (std::uint32_t x = 0; x < extent_.width; ++x) {
      pixels.push_back(static_cast<std::uint32_t>(XGetPixel(image, int(x), int(y))) & 0xffffffu);
    }
  }
  XDestroyImage(image);
  return pixels;
}

}  // namespace engine::platform
