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

    // Clears the layer to transparent and begins rendering into it (viewport: the whole
    // layer); `end` ends it and leaves the image ready for the composite to sample.
    void begin(VkCommandBuffer cmd) const;
    void end(VkCommandBuffer cmd) const;
};

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
