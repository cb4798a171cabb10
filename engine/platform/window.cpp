#include "platform/window.h"

#include <algorithm>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

namespace {

std::string glfw_error() {
    const char* text = nullptr;
    const int code = glfwGetError(&text);
    return code == GLFW_NO_ERROR ? std::string("no GLFW error") : std::string(text ? text : "unknown GLFW error");
}

}  // namespace

Window::Window(const WindowDesc& desc) {
    if (desc.width <= 0 || desc.height <= 0) throw usage_error("window size must be positive");
    if (!glfwInit())
        throw Error("cannot open a window: " + glfw_error() +
                    " (is DISPLAY set? without a screen run under xvfb-run -a -s \"-screen 0 1280x1024x24\")");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("cannot open a window: GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(desc.width, desc.height, desc.title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = glfw_error();
        glfwTerminate();
        throw Error("glfwCreateWindow failed: " + why);
    }
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::required_instance_extensions() const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("glfwGetRequiredInstanceExtensions failed: " + glfw_error());
    return std::vector<std::string>(names, names + count);
}

VkExtent2D Window::framebuffer_size() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) != 0; }

bool Window::iconified() const { return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0; }

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    LW_VK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

}  // namespace lw
