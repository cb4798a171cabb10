// engine/stroke/stroke_pass.h — SLAM-textured strokes over the colour target.
//
// Input:  `StrokeVertex` triangles (stroke_geometry.h) and the SLAM texture they sample.
// Output: the strokes alpha-blended into the render target's colour (an overlay pass: the
//         colour comes and goes in TRANSFER_SRC_OPTIMAL, like the line pass), or drawn into
//         a coverage layer for a translucent set (gpu/coverage_layer.h), whose composite
//         then draws them once.
//
// `StrokeDrawPipelines` is what this pass and the line pass (render/line_pass.h) share: both
// draw the builder's triangles, over the target or into a layer.
#pragma once

#include <optional>
#include <vector>

#include "gpu/context.h"
#include "gpu/coverage_layer.h"
#include "gpu/pipeline.h"
#include "gpu/render_target.h"
#include "stroke/slam_texture.h"
#include "stroke/stroke_geometry.h"

namespace lw {

// The vertex layout of `StrokeVertex` (locations 0–3: pixel, tex, color, edge), shared by
// every pass that draws the builder's triangles.
[[nodiscard]] std::vector<VertexAttribute> stroke_vertex_attributes();

// The pixels the triangles touch within a width × height target (a coverage layer's area).
[[nodiscard]] VkRect2D stroke_pixel_bounds(const std::vector<StrokeVertex>& vertices, uint32_t width, uint32_t height);

// What the passes drawing the builder's triangles push (shaders/lines_draw.vert, stroke.vert).
struct StrokeDrawPush {
    glm::vec2 viewport;
    float param;          // the line pass's dash period, the stroke pass's SLAM level count
    float premultiplied;  // 1: into a coverage layer
};

// A pass's two pipelines for the builder's triangles: over the target (Alpha blending) and
// into a coverage layer (premultiplied output, Max blending; made at the first translucent
// set, as most frames have none), and the recording both passes share.
class StrokeDrawPipelines {
public:
    // `desc`: the pass's shaders and bindings; the vertex layout, colour format, blending and
    // push constants are set here.
    StrokeDrawPipelines(const Context& ctx, GraphicsPipelineDesc desc, VkFormat color_format);

    // Puts `vertices` in `arena` (not to be reset before the submission completed) and
    // records their drawing over `target`, or with `layer` into it (begun and ended here,
    // over the triangles' box); `image`, if given, is bound at binding 0. False: nothing was
    // recorded (no vertices, or none inside the target).
    bool record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                const std::vector<StrokeVertex>& vertices, float param, UploadArena& arena, CoverageLayer* layer,
                VkImageView image = VK_NULL_HANDLE, VkSampler sampler = VK_NULL_HANDLE) const;

private:
    GraphicsPipelineDesc desc_;
    GraphicsPipeline over_target_;
    mutable std::optional<GraphicsPipeline> into_layer_;
};

class StrokePass {
public:
    explicit StrokePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM);

    // Records the draw, its vertices put in `arena` (not to be reset before the submission
    // completed). With `layer`, into it (begun and ended here) for a composite that draws
    // the strokes once, instead of over the target. False: no vertices
    // (nothing recorded).
    bool record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena,
                CoverageLayer* layer = nullptr) const;

private:
    StrokeDrawPipelines draw_;
};

}  // namespace lw
