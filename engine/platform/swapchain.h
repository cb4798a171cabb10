// engine/platform/swapchain.h — a window's swapchain, and how a rendered frame reaches it.
//
// Input:  a `Context` made with the window's instance extensions and `swapchain = true`,
//         the `Window`, and per frame a `PresentDesc`: the finished frame (an Image in
//         TRANSFER_SRC_OPTIMAL, e.g. FrameRenderer::target().color), an overlay recorded in
//         `render_pass()` (the UI), and optionally where to put a screenshot.
// Output: the frame copied to the acquired image when it has the swapchain's size and format
//         (a viewer renders in format()), else blitted (scaled when the sizes differ, converted
//         to the swapchain's format), the overlay drawn over it, presented.
//
// One frame in flight: present() waits for the previous frame's fence before recording, so
// nothing the GPU may still read is rewritten (the renderer itself waits for its own
// submissions). The render pass (LOAD, COLOR_ATTACHMENT_OPTIMAL → PRESENT_SRC_KHR) exists
// because Dear ImGui 1.86's Vulkan backend needs one; it survives recreation (the format is
// chosen once: B8G8R8A8_UNORM or R8G8B8A8_UNORM — UNORM so that presented pixels equal
// the PNG that `linework render` writes).
//
// Recreation: present() returns false when the swapchain is out of date or suboptimal;
// the caller then calls recreate() with the window's framebuffer size. A zero size (a
// minimized window) is refused: recreate() returns false and the caller skips the frame.
#pragma once

#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/image.h"
#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/resources.h"
#include "platform/window.h"

namespace lw {

struct SwapchainDesc {
    bool vsync = true;  // FIFO; false: MAILBOX, else IMMEDIATE, else FIFO
};

struct PresentDesc {
    const Image* frame = nullptr;                        // TRANSFER_SRC_OPTIMAL, fully written
    std::function<void(VkCommandBuffer)> overlay;        // recorded inside render_pass()
    ImageRGBA8* screenshot = nullptr;                    // receives the presented pixels (waits)
};

class Swapchain {
public:
    Swapchain(const Context& ctx, const Window& window, const SwapchainDesc& desc = {});
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Makes the swapchain (again) for a framebuffer of `size` pixels. Returns false, and
    // keeps what it had, when the size or the surface's current extent is zero.
    [[nodiscard]] bool recreate(VkExtent2D size);

    // Acquires, records (copy or blit, overlay, screenshot copy), submits and presents. Returns
    // false when the swapchain is out of date or suboptimal: recreate before the next frame
    // (an out-of-date acquire presents nothing).
    [[nodiscard]] bool present(const PresentDesc& desc);

    VkExtent2D extent() const { return extent_; }
    VkFormat format() const { return format_; }
    VkRenderPass render_pass() const { return render_pass_; }
    uint32_t image_count() const { return uint32_t(images_.size()); }
    uint32_t min_image_count() const { return min_image_count_; }
    VkPresentModeKHR present_mode() const { return present_mode_; }
    // Whether screenshots read the swapchain image (with the overlay) — else the frame.
    bool screenshots_include_overlay() const { return readable_; }

private:
    void record(VkCommandBuffer cmd, uint32_t index, const PresentDesc& desc, const Buffer* readback) const;

    const Context* ctx_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;  // instance-level: destroyed by hand
    SwapchainDesc desc_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR color_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkExtent2D extent_{};
    uint32_t min_image_count_ = 2;
    bool readable_ = false;  // images have TRANSFER_SRC usage
    Handle<VkRenderPass> render_pass_;
    Handle<VkSwapchainKHR> swapchain_;
    std::vector<VkImage> images_;
    std::vector<Handle<VkImageView>> views_;
    std::vector<Handle<VkFramebuffer>> framebuffers_;
    std::vector<Handle<VkSemaphore>> render_done_;  // per image: present waits on it
    Handle<VkSemaphore> acquired_;
    Handle<VkFence> in_flight_;
    Handle<VkCommandPool> pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
};

}  // namespace lw
