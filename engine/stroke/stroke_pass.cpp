#include "stroke/stroke_pass.h"

#include <cstring>

#include "stroke_frag.h"
#include "stroke_vert.h"

namespace lw {

namespace {
struct StrokePush {  // mirrors shaders/stroke.vert
    glm::vec2 viewport;
    float levels;
    float pad;
};
}  // namespace

std::vector<VertexAttribute> stroke_vertex_attributes() {
    return {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
            {.location = 1, .format = VK_FORMAT_R32G32B32_SFLOAT, .offset = offsetof(StrokeVertex, tex)},
            {.location = 2, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, color)},
            {.location = 3, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .offset = offsetof(StrokeVertex, edge)}};
}

StrokePass::StrokePass(const Context& ctx, VkFormat color_format)
    : pipeline_(ctx, {.vertex_spirv = LW_SPIRV(stroke_vert_spv),
                      .fragment_spirv = LW_SPIRV(stroke_frag_spv),
                      .vertex_stride = sizeof(StrokeVertex),
                      .attributes = stroke_vertex_attributes(),
                      .color_format = color_format,
                      .depth_format = VK_FORMAT_UNDEFINED,
                      .depth_test = false,
                      .depth_write = false,
                      .blend = BlendMode::Alpha,
                      .sampled_images = 1,
                      .push_constant_size = sizeof(StrokePush),
                      .name = "strokes"}) {}

void StrokePass::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                        const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena) const {
    if (vertices.empty()) return;
    const UploadArena::Slice buffer = arena.push(ctx, std::as_bytes(std::span(vertices)));
    target.begin_overlay(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    pipeline_.push_image(ctx, cmd, 0, slam.view(), slam.sampler());
    const StrokePush push{{float(target.width), float(target.height)}, float(slam.levels()), 0.0f};
    pipeline_.draw(cmd, buffer, static_cast<uint32_t>(vertices.size()), &push, sizeof(push));
    target.end_overlay(cmd);
}

}  // namespace lw
