#pragma once
// A GLFW window with a Vulkan surface. Headless runs never construct one (glfwInit fails
// without a display), which is why nothing else in the engine includes GLFW.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "engine/platform/input.h"

struct GLFWwindow;

namespace engine::platform {

struct WindowDesc {
  std::string title = "cloudscape";
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
};

// A window's Vulkan surface, destroyed with this object. Declare it after the instance it was
// made from (and after the window): it then goes first, also when an exception unwinds.
class Surface {
 public:
  Surface() = default;
  Surface(VkInstance instance, VkSurfaceKHR surface) : instance_(instance), surface_(surface) {}
  ~Surface();
  Surface(Surface&& other) noexcept;
  Surface& operator=(Surface&& other) noexcept;
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  VkSurfaceKHR vk() const { return surface_; }

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

class Window {
 public:
  // True when a display server is reachable (DISPLAY or WAYLAND_DISPLAY set).
  static bool displayAvailable();

  // Throws engine::Error when GLFW cannot start or the window cannot be created.
  explicit Window(const WindowDesc& desc);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Instance extensions the surface needs (call after constructing a window).
  std::vector<std::string> requiredInstanceExtensions() const;
  // A surface for this window; throws engine::Error naming the VkResult when it cannot.
  Surface createSurface(VkInstance instance);

  // Processes window events and updates input(). Call once per frame.
  void pollEvents();
  bool shouldClose() const;
  void requestClose();
  VkExtent2D framebufferExtent() const;
  bool minimized() const;
  void setTitle(const std::string& title);
  // Asks the window system for a new client size (tests, fixed-size captures).
  void setSize(std::uint32_t width, std::uint32_t height);
  // Hides the cursor and reports relative motion (mouse look); toggled by the game.
  void setMouseCaptured(bool captured);

  // The window's X11 connection (a Display*) and window id when GLFW runs on X11; a null
  // display otherwise. For presenters that bypass Vulkan's WSI (shm_blitter.h).
  struct X11Handles {
    void* display = nullptr;
    unsigned long window = 0;
  };
  X11Handles x11() const;

  InputState& input() { return input_; }
  const InputState& input() const { return input_; }

 private:
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onScroll(GLFWwindow* window, double dx, double dy);

  GLFWwindow* window_ = nullptr;
  InputState input_;
  double lastMouseX_ = 0.0;
  double lastMouseY_ = 0.0;
  bool haveMouse_ = false;
};

}  // namespace engine::platform
