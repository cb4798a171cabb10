#include "gpu/coverage_layer.h"

#include <algorithm>
#include <cmath>

#include "layer_composite_frag.h"
#include "layer_composite_vert.h"

namespace lw {

CoverageLayer::CoverageLayer(const Context& ctx, uint32_t w, uint32_t h)
    : width(w),
      height(h),
      image(ctx, {.width = w, .height = h, .format = kFormat,
                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                  .name = "coverage layer"}) {}

VkRect2D pixel_bounds(float lo_x, float lo_y, float hi_x, float hi_y, uint32_t width, uint32_t height) {
    const auto x0 = uint32_t(std::clamp(std::floor(lo_x), 0.0f, float(width)));
    const auto y0 = uint32_t(std::clamp(std::floor(lo_y), 0.0f, float(height)));
    const auto x1 = uint32_t(std::clamp(std::ceil(hi_x), 0.0f, float(width)));
    const auto y1 = uint32_t(std::clamp(std::ceil(hi_y), 0.0f, float(height)));
    if (x1 <= x0 || y1 <= y0) return {{0, 0}, {0, 0}};
    return {{int32_t(x0), int32_t(y0)}, {x1 - x0, y1 - y0}};
}

void CoverageLayer::begin(VkCommandBuffer cmd, VkRect2D area) {
    area_ = area;
    // UNDEFINED: the last composite's contents are not needed (the clear replaces them); the
    // source scope waits for that composite's reads and any earlier drawing into the layer.
    record_image_barrier(cmd, image,
                         {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                          .new_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .src_access = VK_ACCESS_2_NONE,
                          .dst_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .dst_access = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    begin_color_rendering(cmd, image, VK_ATTACHMENT_LOAD_OP_CLEAR, area_, width, height);  // cleared to transparent
}

void CoverageLayer::end(VkCommandBuffer cmd) const {
    vkCmdEndRendering(cmd);
    record_image_barrier(cmd, image,
                         {.old_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                          .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
}

LayerComposite::LayerComposite(const Context& ctx, VkFormat target_format)
    : pipeline_(ctx, {.vertex_spirv = LW_SPIRV(layer_composite_vert_spv),
                      .fragment_spirv = LW_SPIRV(layer_composite_frag_spv),
                      .color_format = target_format,
                      .depth_format = VK_FORMAT_UNDEFINED,
                      .depth_test = false,
                      .depth_write = false,
                      .blend = BlendMode::Premultiplied,
                      .sampled_images = 1,
                      .name = "layer composite"}),
      sampler_(create_sampler(ctx, {.filter = VK_FILTER_NEAREST,
                                    .address_u = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .mipmap_mode = VK_SAMPLER_MIPMAP_MODE_NEAREST})) {}

void LayerComposite::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                            const CoverageLayer& layer) const {
    target.begin_overlay(cmd);
    const VkRect2D area = layer.area();
    vkCmdSetScissor(cmd, 0, 1, &area);  // the layer holds nothing outside it
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    pipeline_.push_image(ctx, cmd, 0, layer.image.view(), sampler_.get());
    pipeline_.draw_generated(cmd, 3, nullptr, 0);
    target.end_overlay(cmd);
}

}  // namespace lw
