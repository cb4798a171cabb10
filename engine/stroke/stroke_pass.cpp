#include "stroke/stroke_pass.h"

#include <cstring>
#include <utility>

#include "stroke_frag.h"
#include "stroke_vert.h"

namespace lw {

std::vector<VertexAttribute> stroke_vertex_attributes() {
    return {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
            {.location = 1, .format = VK_FORMAT_R32G32B32_SFLOAT, .offset = offsetof(StrokeVertex, tex)},
            {.location = 2, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, color)},
            {.location = 3, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, edge)}};
}

VkRect2D stroke_pixel_bounds(const std::vector<StrokeVertex>& vertices, uint32_t width, uint32_t height) {
    glm::vec2 lo{float(width), float(height)}, hi{0.0f};
    for (const StrokeVertex& v : vertices) lo = glm::min(lo, v.pixel), hi = glm::max(hi, v.pixel);
    return pixel_bounds(lo.x, lo.y, hi.x, hi.y, width, height);
}

StrokeDrawPipelines::StrokeDrawPipelines(const Context& ctx, GraphicsPipelineDesc desc, VkFormat color_format)
    : desc_(std::move(desc)) {
    desc_.vertex_stride = sizeof(StrokeVertex);
    desc_.attributes = stroke_vertex_attributes();
    desc_.depth_format = VK_FORMAT_UNDEFINED;
    desc_.depth_test = desc_.depth_write = false;
    desc_.push_constant_size = sizeof(StrokeDrawPush);
    desc_.color_format = color_format;
    desc_.blend = BlendMode::Alpha;
    over_target_ = GraphicsPipeline(ctx, desc_);
    desc_.color_format = CoverageLayer::kFormat;
    desc_.blend = BlendMode::Max;
}

bool StrokeDrawPipelines::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                                 const std::vector<StrokeVertex>& vertices, float param, UploadArena& arena,
                                 CoverageLayer* layer, VkImageView image, VkSampler sampler) const {
    if (vertices.empty()) return false;
    if (layer) {
        const VkRect2D area = stroke_pixel_bounds(vertices, target.width, target.height);
        if (area.extent.width == 0 || area.extent.height == 0) return false;  // nothing inside the target
        if (!into_layer_) into_layer_.emplace(ctx, desc_);
        layer->begin(cmd, area);
    } else {
        target.begin_overlay(cmd);
    }
    const GraphicsPipeline& pipeline = layer ? *into_layer_ : over_target_;
    const UploadArena::Slice buffer = arena.push(ctx, std::as_bytes(std::span(vertices)));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
    if (image != VK_NULL_HANDLE) pipeline.push_image(ctx, cmd, 0, image, sampler);
    const StrokeDrawPush push{{float(target.width), float(target.height)}, param, layer ? 1.0f : 0.0f};
    pipeline.draw(cmd, buffer, static_cast<uint32_t>(vertices.size()), &push, sizeof(push));
    layer ? layer->end(cmd) : target.end_overlay(cmd);
    return true;
}

StrokePass::StrokePass(const Context& ctx, VkFormat color_format)
    : draw_(ctx,
            {.vertex_spirv = LW_SPIRV(stroke_vert_spv),
             .fragment_spirv = LW_SPIRV(stroke_frag_spv),
             .sampled_images = 1,
             .name = "strokes"},
            color_format) {}

bool StrokePass::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                        const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena,
                        CoverageLayer* layer) const {
    return draw_.record(ctx, cmd, target, vertices, float(slam.levels()), arena, layer, slam.view(), slam.sampler());
}

}  // namespace lw
