// engine/platform/window.h — a GLFW window for a Vulkan swapchain (the viewer's platform).
//
// Input:  `WindowDesc` — size in screen coordinates and title.
// Output: a `Window` owning GLFW (initialized once per process) and a GLFWwindow made with
//         GLFW_NO_API; the instance extensions its surface needs; the surface itself.
//
// Errors: no display (DISPLAY unset, no X server) or no Vulkan loader support is an
// lw::Error that says so — run under `xvfb-run` to get a display without a screen.
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace lw {

struct WindowDesc {
    int width = 1280;
    int height = 720;
    std::string title = "linework";
};

class Window {
public:
    explicit Window(const WindowDesc& desc);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* get() const { return window_; }

    // VK_KHR_surface and the platform's surface extension (for ContextDesc).
    [[nodiscard]] std::vector<std::string> required_instance_extensions() const;

    // Pixels of the drawable area; (0, 0) while the window is minimized.
    [[nodiscard]] VkExtent2D framebuffer_size() const;
    [[nodiscard]] bool should_close() const;
    [[nodiscard]] bool iconified() const;

    // A VkSurfaceKHR of this window on `instance`; the caller destroys it (Swapchain does).
    [[nodiscard]] VkSurfaceKHR create_surface(VkInstance instance) const;

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace lw
