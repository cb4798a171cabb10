// engine/platform/ui_overlay.h — Dear ImGui (1.86, Debian's libimgui-dev) over the swapchain.
//
// Input:  the Context, the Window and the swapchain's render pass (ImGui 1.86's Vulkan
//         backend draws inside a VkRenderPass, not dynamic rendering) and image counts.
// Output: per frame, begin_frame() … ImGui:: calls … end_frame(), then record(cmd) inside
//         Swapchain's render pass (PresentDesc::overlay).
//
// One overlay per process (ImGui's backends keep global state). GLFW callbacks installed
// before construction are chained by ImGui's GLFW backend. No imgui.ini is written.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "platform/window.h"

namespace lw {

class UiOverlay {
public:
    UiOverlay(const Context& ctx, const Window& window, VkRenderPass render_pass, uint32_t min_image_count,
              uint32_t image_count);
    ~UiOverlay();
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;

    void begin_frame();
    void end_frame();
    void record(VkCommandBuffer cmd) const;

    // Whether ImGui uses the mouse or keyboard this frame (the viewer then ignores them).
    [[nodiscard]] bool wants_mouse() const;
    [[nodiscard]] bool wants_keyboard() const;

private:
    Handle<VkDescriptorPool> pool_;
    bool ended_ = false;
};

}  // namespace lw
