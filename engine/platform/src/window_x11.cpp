// Window::x11() apart from window.cpp: the X11 headers (Xlib, and Xrandr through
// glfw3native.h: libxrandr-dev) define macros (None, Bool, KeyPress) that the rest of the
// window's code must not see.
#include "engine/platform/window.h"

#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>

namespace engine::platform {

Window::X11Handles Window::x11() const {
  if (window_ == nullptr) return {};
  X11Handles handles;
  handles.display = glfwGetX11Display();  // null (and a GLFW error) when not on X11
  if (handles.display != nullptr) handles.window = glfwGetX11Window(window_);
  return handles;
}

}  // namespace engine::platform
