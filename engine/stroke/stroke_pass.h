// engine/stroke/stroke_pass.h — SLAM-textured strokes over the colour target.
//
// Input:  `StrokeVertex` triangles (stroke_geometry.h) and the SLAM texture they sample.
// Output: the strokes alpha-blended into the render target's colour (an overlay pass: the
//         colour comes and goes in TRANSFER_SRC_OPTIMAL, like the line pass).
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

class StrokePass {
public:
    explicit StrokePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM);

    // Records the draw, its vertices put in `arena` (not to be reset before the submission
    // completed). With `layer`, into it (begun and ended here) for a composite that draws
    // the strokes once, instead of over the target. False: no vertices
    // (nothing recorded).
    bool record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena,
                const CoverageLayer* layer = nullptr) const;

private:
    GraphicsPipeline pipeline_;
    // Into a coverage layer: made at the first translucent set (most frames have none).
    mutable std::optional<GraphicsPipeline> layer_pipeline_;
};

}  // namespace lw
