// engine/stroke/stroke_pass.h — SLAM-textured strokes over the colour target.
//
// Input:  `StrokeVertex` triangles (stroke_geometry.h) and the SLAM texture they sample.
// Output: the strokes alpha-blended into the render target's colour (an overlay pass: the
//         colour comes and goes in TRANSFER_SRC_OPTIMAL, like the line pass).
#pragma once

#include <vector>

#include "gpu/context.h"
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
    // completed).
    void record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target,
                const std::vector<StrokeVertex>& vertices, const SlamTexture& slam, UploadArena& arena) const;

private:
    GraphicsPipeline pipeline_;
};

}  // namespace lw
