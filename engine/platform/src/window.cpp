#include "engine/platform/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <optional>
#include <utility>

#include "engine/core/error.h"

namespace engine::platform {
namespace {

std::optional<Key> mapKey(int key) {
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) {
    return static_cast<Key>(static_cast<int>(Key::Num1) + (key - GLFW_KEY_1));
  }
  switch (key) {
    case GLFW_KEY_W:
      return Key::W;
    case GLFW_KEY_A:
      return Key::A;
    case GLFW_KEY_S:
      return Key::S;
    case GLFW_KEY_D:
      return Key::D;
    case GLFW_KEY_Q:
      return Key::Q;
    case GLFW_KEY_E:
      return Key::E;
    case GLFW_KEY_R:
      return Key::R;
    case GLFW_KEY_F:
      return Key::F;
    case GLFW_KEY_T:
      return Key::T;
    case GLFW_KEY_G:
      return Key::G;
    case GLFW_KEY_H:
      return Key::H;
    case GLFW_KEY_P:
      return Key::P;
    case GLFW_KEY_C:
      return Key::C;
    case GLFW_KEY_V:
      return Key::V;
    case GLFW_KEY_B:
      return Key::B;
    case GLFW_KEY_N:
      return Key::N;
    case GLFW_KEY_M:
      return Key::M;
    case GLFW_KEY_UP:
      return Key::Up;
    case GLFW_KEY_DOWN:
      return Key::Down;
    case GLFW_KEY_LEFT:
      return Key::Left;
    case GLFW_KEY_RIGHT:
      return Key::Right;
    case GLFW_KEY_SPACE:
      return Key::Space;
    case GLFW_KEY_LEFT_SHIFT:
      return Key::LeftShift;
    case GLFW_KEY_LEFT_CONTROL:
      return Key::LeftControl;
    case GLFW_KEY_TAB:
      return Key::Tab;
    case GLFW_KEY_ESCAPE:
      return Key::Escape;
    case GLFW_KEY_ENTER:
      return Key::Enter;
    case GLFW_KEY_0:
      return Key::Num0;
    case GLFW_KEY_MINUS:
      return Key::Minus;
    case GLFW_KEY_EQUAL:
      return Key::Equal;
    case GLFW_KEY_LEFT_BRACKET:
      return Key::LeftBracket;
    case GLFW_KEY_RIGHT_BRACKET:
      return Key::RightBracket;
    case GLFW_KEY_F1:
      return Key::F1;
    case GLFW_KEY_F2:
      return Key::F2;
    case GLFW_KEY_F3:
      return Key::F3;
    case GLFW_KEY_F4:
      return Key::F4;
    case GLFW_KEY_F5:
      return Key::F5;
    case GLFW_KEY_F12:
      return Key::F12;
    default:
      return std::nullopt;
  }
}

}  // namespace

bool Window::displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && x11[0] != '\0') || (wayland != nullptr && wayland[0] != '\0');
}

Window::Window(const WindowDesc& desc) {
  if (glfwInit() != GLFW_TRUE) {
    const char* message = nullptr;
    glfwGetError(&message);
    throw Error(std::string("window: GLFW failed to start: ") + (message ? message : "unknown"));
  }
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw Error("window: GLFW found no Vulkan loader");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(static_cast<int>(desc.width), static_cast<int>(desc.height),
                             desc.title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const char* message = nullptr;
    glfwGetError(&message);
    glfwTerminate();
    throw Error(std::string("window: cannot create window: ") + (message ? message : "unknown"));
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &Window::onKey);
  glfwSetScrollCallback(window_, &Window::onScroll);
}

Surface::~Surface() {
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
}

Surface::Surface(Surface&& other) noexcept
    : instance_(std::exchange(other.instance_, VK_NULL_HANDLE)),
      surface_(std::exchange(other.surface_, VK_NULL_HANDLE)) {}

Surface& Surface::operator=(Surface&& other) noexcept {
  if (this != &other) {
    if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
    instance_ = std::exchange(other.instance_, VK_NULL_HANDLE);
    surface_ = std::exchange(other.surface_, VK_NULL_HANDLE);
  }
  return *this;
}

Window::~Window() {
  if (window_ != nullptr) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() const {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  std::vector<std::string> extensions;
  for (std::uint32_t i = 0; i < count; ++i) extensions.emplace_back(names[i]);
  return extensions;
}

Surface Window::createSurface(VkInstance instance) {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  const VkResult result = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (result != VK_SUCCESS) {
    throw Error("window: glfwCreateWindowSurface failed (VkResult " +
                std::to_string(static_cast<int>(result)) + ")");
  }
  return Surface(instance, surface);
}

void Window::pollEvents() {
  input_.beginFrame();
  glfwPollEvents();
  double x = 0.0;
  double y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  if (haveMouse_ && input_.mouseCaptured) {
    input_.mouseDeltaX = x - lastMouseX_;
    input_.mouseDeltaY = y - lastMouseY_;
  }
  lastMouseX_ = x;
  lastMouseY_ = y;
  haveMouse_ = true;
  input_.cursorX = input_.mouseCaptured ? -1.0 : x;
  input_.cursorY = input_.mouseCaptured ? -1.0 : y;
  input_.leftButtonDown = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}
void Window::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

VkExtent2D Window::framebufferExtent() const {
  int width = 0;
  int height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return VkExtent2D{static_cast<std::uint32_t>(std::max(width, 0)),
                    static_cast<std::uint32_t>(std::max(height, 0))};
}

bool Window::minimized() const {
  const VkExtent2D extent = framebufferExtent();
  return extent.width == 0 || extent.height == 0 ||
         glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE;
}

void Window::setTitle(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

void Window::setSize(std::uint32_t width, std::uint32_t height) {
  glfwSetWindowSize(window_, static_cast<int>(width), static_cast<int>(height));
}

void Window::setMouseCaptured(bool captured) {
  glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
  input_.mouseCaptured = captured;
  haveMouse_ = false;  // the first motion after a change is a jump, not a movement
}

void Window::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  const auto mapped = mapKey(key);
  if (self == nullptr || !mapped) return;
  if (action == GLFW_PRESS) self->input_.press(*mapped);
  if (action == GLFW_RELEASE) self->input_.release(*mapped);
}

void Window::onScroll(GLFWwindow* window, double /*dx*/, double dy) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self != nullptr) self->input_.scrollY += dy;
}

}  // namespace engine::platform
