// engine/gpu/coverage_layer.h — an offscreen layer that overlay passes draw into so that
// what they draw is composited over the frame once, however often its pieces overlap.
//
// Input:  premultiplied colour from an overlay pass's fragments (the line and stroke passes
//         have a layer pipeline: their own shaders with premultiplied output and Max
//         blending); the frame's RenderTarget.
// Output: the layer `over` the target's colour: each pixel once, with the largest coverage
//         any fragment gave it.
//
// Why: a translucent line set (alpha < 1) drawn straight into the frame blends twice where
// its own strokes overlap (caps, joins, crossing paths, an edge that is two line types):
// 0.75 where 0.5 was asked. Its SVG fills each run of like colour as one path (the union of
// its shapes at one opacity), and the layer draws the union likewise: per channel the larger
// premultiplied value, so that a pixel covered twice keeps the stronger of its coverages
// (at a join both are the same coverage of the same pixel; `over` would count it twice).
// Per channel: where pieces of one set in different colours (colour modifiers) overlap, the
// pixel takes each channel's larger value (red and blue at one alpha give magenta there),
// where its SVG shows the piece drawn last.
#pragma once

#include <cstdint>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/pipeline.h"
#include "gpu/render_target.h"
#include "gpu/resources.h"

namespace lw {

// The layer image: premultiplied RGBA, the target's size.
struct CoverageLayer {
    static constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;
    CoverageLayer(const Context& ctx, uint32_t width, uint32_t height);
    uint32_t width, height;
    Image image;

    // Clears `area` of the layer to transparent and begins rendering there (viewport: the
    // whole layer; what is drawn must lie in `area`, which the composite alone then reads:
    // on a CPU device a full-screen clear and composite cost as much as the strokes);
    // `end` ends it and leaves the image ready for the composite to sample.
    void begin(VkCommandBuffer cmd, VkRect2D area);
    void end(VkCommandBuffer cmd) const;
    VkRect2D area() const { return area_; }  // of the last `begin`

private:
    VkRect2D area_{};
};

// The whole pixels of the box [lo_x, hi_x] × [lo_y, hi_y] (pixel coordinates) within a
// width × height image; empty (extent 0) where it misses the image.
[[nodiscard]] VkRect2D pixel_bounds(float lo_x, float lo_y, float hi_x, float hi_y, uint32_t width, uint32_t height);

// The composite: the layer `over` a target of one colour format (a full-screen triangle
// reading the layer texel by texel).
class LayerComposite {
public:
    LayerComposite(const Context& ctx, VkFormat target_format);
    void record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target, const CoverageLayer& layer) const;

private:
    GraphicsPipeline pipeline_;
    Handle<VkSampler> sampler_;
};

}  // namespace lw
