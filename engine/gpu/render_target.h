// engine/gpu/render_target.h — the colour and depth images a frame renders into.
//
// Passes hand the images to each other in TRANSFER_SRC_OPTIMAL (ready to be read back);
// the helpers here move the colour image into and out of attachment use and set the
// viewport to the whole target, so that every pass does it the same way.
#pragma once

#include <cstdint>
#include <span>

#include "gpu/context.h"
#include "gpu/resources.h"

namespace lw {

// The Vulkan sample-count bit of `samples` (1, 4 or 8) if the device renders colour and
// depth at that count; an error listing the counts it does support otherwise.
[[nodiscard]] VkSampleCountFlagBits sample_count_bit(const Context& ctx, uint32_t samples);

// Begins dynamic rendering into one colour image (in COLOR_ATTACHMENT_OPTIMAL) over `area`,
// loading it or clearing it to `clear`, with the viewport over the whole width × height image
// and the scissor on `area`: what every single-attachment pass (overlays, layers, splats)
// starts with.
void begin_color_rendering(VkCommandBuffer cmd, const Image& image, VkAttachmentLoadOp load, VkRect2D area,
                           uint32_t width, uint32_t height, VkClearColorValue clear = {});

struct RenderTarget {
    // `color_format`: R8G8B8A8_UNORM (what PNGs get), or B8G8R8A8_UNORM for a viewer whose
    // swapchain has that format (the frame then reaches it by a copy instead of a blit).
    // `samples` > 1: the surface pass draws into multisampled twins of the colour and depth
    // images and resolves them into `color` and `depth` (MSAA); every other pass draws into
    // the single-sample images (strokes carry their own coverage).
    RenderTarget(const Context& ctx, uint32_t width, uint32_t height, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM,
                 uint32_t samples = 1);
    uint32_t width, height;
    uint32_t samples = 1;
    Image color;  // color_format
    Image depth;  // D32_SFLOAT, cleared to 1
    Image msaa_color, msaa_depth;  // samples > 1 only: the surface pass's attachments

    // Colour from `from` (UNDEFINED discards, TRANSFER_SRC keeps) to COLOR_ATTACHMENT_OPTIMAL.
    void color_to_attachment(VkCommandBuffer cmd, VkImageLayout from) const;
    // Colour from COLOR_ATTACHMENT_OPTIMAL back to TRANSFER_SRC_OPTIMAL.
    void color_to_transfer_src(VkCommandBuffer cmd) const;
    // Viewport and scissor covering the whole target (dynamic state of every pipeline).
    void set_viewport(VkCommandBuffer cmd) const;

    // An overlay pass draws over the finished colour (no depth): begin moves the colour to
    // attachment use, starts rendering with LOAD and sets the viewport; end moves it back.
    void begin_overlay(VkCommandBuffer cmd) const;
    void end_overlay(VkCommandBuffer cmd) const;

    // Replaces the colour (in TRANSFER_SRC_OPTIMAL, left so) by `rgba` (width × height × 4
    // bytes, RGBA; swizzled for a BGRA target): a frame finished on the host (ribbons)
    // goes back to the target a viewer presents. Waits for the copy.
    void write_color(const Context& ctx, std::span<const uint8_t> rgba) const;
};

}  // namespace lw
