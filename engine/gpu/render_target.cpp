#include "gpu/render_target.h"

#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"

namespace lw {

namespace {
// 0 for counts other than 1, 4 and 8 (the choices offered).
VkSampleCountFlagBits sample_count_bit_of(uint32_t n) {
    return n == 1 ? VK_SAMPLE_COUNT_1_BIT : n == 4 ? VK_SAMPLE_COUNT_4_BIT : n == 8 ? VK_SAMPLE_COUNT_8_BIT
                                                                                    : VkSampleCountFlagBits(0);
}
}  // namespace

VkSampleCountFlagBits sample_count_bit(const Context& ctx, uint32_t samples) {
    const VkSampleCountFlags supported = ctx.properties().limits.framebufferColorSampleCounts &
                                         ctx.properties().limits.framebufferDepthSampleCounts;
    const VkSampleCountFlagBits bit = sample_count_bit_of(samples);
    if (bit != 0 && (supported & bit)) return bit;
    std::string list;
    for (const uint32_t n : {1u, 4u, 8u})
        if (supported & sample_count_bit_of(n)) list += (list.empty() ? "" : " or ") + std::to_string(n);
    // Named by the caller that knows where the count came from (a scene key, a flag).
    throw ParameterError("samples", " " + std::to_string(samples) + ": " +
                                        (bit == 0 ? std::string("expected 1, 4 or 8")
                                                  : "the device " + std::string(ctx.properties().deviceName) +
                                                        " renders " + list + " samples per pixel"));
}

RenderTarget::RenderTarget(const Context& ctx, uint32_t w, uint32_t h, VkFormat color_format, uint32_t sample_count)
    : width(w),
      height(h),
      samples(sample_count),
      color(ctx, {.width = w, .height = h, .format = color_format,
                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT,  // cleared by transfer when lines-only
                  .name = "color target"}),
      depth(ctx, {.width = w, .height = h, .format = VK_FORMAT_D32_SFLOAT,
                  .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                           VK_IMAGE_USAGE_SAMPLED_BIT,
                  .name = "depth target"}) {
    const VkSampleCountFlagBits bit = sample_count_bit(ctx, samples);
    if (samples == 1) return;
    // Transient: only the resolved images are ever read.
    msaa_color = Image(ctx, {.width = w, .height = h, .format = color_format,
                             .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                             .name = "multisampled color", .samples = bit});
    msaa_depth = Image(ctx, {.width = w, .height = h, .format = VK_FORMAT_D32_SFLOAT,
                             .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                             .name = "multisampled depth", .samples = bit});
}

void RenderTarget::color_to_attachment(VkCommandBuffer cmd, VkImageLayout from) const {
    record_image_barrier(cmd, color,
                         {.old_layout = from,
                          .new_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          .src_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .dst_access = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
}

void RenderTarget::color_to_transfer_src(VkCommandBuffer cmd) const {
    record_image_barrier(cmd, color,
                         {.old_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                          .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT});
}

void RenderTarget::set_viewport(VkCommandBuffer cmd) const {
    VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void begin_color_rendering(VkCommandBuffer cmd, const Image& image, VkAttachmentLoadOp load, VkRect2D area,
                           uint32_t width, uint32_t height, VkClearColorValue clear) {
    VkRenderingAttachmentInfo attachment{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                         .imageView = image.view(),
                                         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         .loadOp = load,
                                         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                         .clearValue = {.color = clear}};
    VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = area,
                              .layerCount = 1,
                              .colorAttachmentCount = 1,
                              .pColorAttachments = &attachment};
    vkCmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
}

void RenderTarget::begin_overlay(VkCommandBuffer cmd) const {
    color_to_attachment(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    begin_color_rendering(cmd, color, VK_ATTACHMENT_LOAD_OP_LOAD, {{0, 0}, {width, height}}, width, height);
}

void RenderTarget::end_overlay(VkCommandBuffer cmd) const {
    vkCmdEndRendering(cmd);
    color_to_transfer_src(cmd);
}

void RenderTarget::write_color(const Context& ctx, std::span<const uint8_t> rgba) const {
    if (rgba.size() != size_t(width) * height * 4) throw Error("RenderTarget::write_color: the image is not the target's size");
    Buffer staging(ctx, {.size = rgba.size(), .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         .purpose = MemoryPurpose::Upload, .name = "color upload"});
    auto* bytes = static_cast<uint8_t*>(staging.mapped());
    std::memcpy(bytes, rgba.data(), rgba.size());
    if (color.format() == VK_FORMAT_B8G8R8A8_UNORM || color.format() == VK_FORMAT_B8G8R8A8_SRGB)
        for (size_t i = 0; i < rgba.size(); i += 4) std::swap(bytes[i], bytes[i + 2]);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        record_image_barrier(cmd, color,
                             {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                              .src_access = VK_ACCESS_2_MEMORY_READ_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
        record_buffer_to_image(cmd, staging, color);
        record_image_barrier(cmd, color,
                             {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                              .dst_access = VK_ACCESS_2_MEMORY_READ_BIT});
    });
}

}  // namespace lw
