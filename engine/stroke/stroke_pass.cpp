#include "stroke/stroke_pass.h"

#include <cstring>

#include "stroke_frag.h"
#include "stroke_vert.h"

namespace lw {

namespace {
struct StrokePush {  // mirrors shaders/stroke.vert
    glm::vec2 viewport;
    float levels;
    float premultiplied;
};

GraphicsPipelineDesc stroke_pipeline_desc(VkFormat color_format, BlendMode blend) {
    return {.vertex_spirv = LW_SPIRV(stroke_vert_spv),
            .fragment_spirv = LW_SPIRV(stroke_frag_spv),
            .vertex_stride = sizeof(StrokeVertex),
            .attributes = stroke_vertex_attributes(),
            .color_format = color_format,
            .depth_format = VK_FORMAT_UNDEFINED,
            .depth_test = false,
            .depth_write = false,
            .blend = blend,
            .sampled_images = 1,
            .push_constant_size = sizeof(StrokePush),
            .name = blend == BlendMode::Max ? "strokes (coverage layer)" : "strokes"};
}
}  // namespace

std::vector<VertexAttribute> stroke_vertex_attributes() {
    return {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
            {.location = 1, .format = VK_FORMAT_R32G32B32_SFLOAT, .offset = offsetof(StrokeVertex, tex)},
            {.location = 2, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, color)},
            {.location = 3, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, edge)}};
}

StrokePass::StrokePass(const Context& ctx, VkFormat color_format)
    : pipeline_(ctx, stroke_pipeline_desc(color_format, BlendMode::Alpha)) {}

bool StrokePass::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                        const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena,
                        const CoverageLayer* layer) const {
    if (vertices.empty()) return false;
    const UploadArena::Slice buffer = arena.push(ctx, std::as_bytes(std::span(vertices)));
    if (layer && !layer_pipeline_) layer_pipeline_.emplace(ctx, stroke_pipeline_desc(CoverageLayer::kFormat, BlendMode::Max));
    const GraphicsPipeline& pipeline = layer ? *layer_pipeline_ : pipeline_;
    layer ? layer->begin(cmd) : target.begin_overlay(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
    pipeline.push_image(ctx, cmd, 0, slam.view(), slam.sampler());
    const StrokePush push{{float(target.width), float(target.height)}, float(slam.levels()), layer ? 1.0f : 0.0f};
    pipeline.draw(cmd, buffer, static_cast<uint32_t>(vertices.size()), &push, sizeof(push));
    layer ? layer->end(cmd) : target.end_overlay(cmd);
    return true;
}

}  // namespace lw
