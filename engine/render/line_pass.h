// engine/render/line_pass.h — draws screen-space paths as flat quads over the colour target.
//
// Input:  `ScreenPath`s from the visibility stage and the scene's `LinesDesc`: a style per
//         line type, which types are on, what to do with hidden runs (skip, dashed, faint).
// Output: the paths composited (alpha blended, fade alpha per sample) into the render
//         target's colour image, which is left in TRANSFER_SRC_OPTIMAL as the surface pass
//         leaves it.
//
// This is the plain line look of the feature-lines stage: quads of the type's width along
// each run with square caps so that consecutive quads overlap at joints. Textured strokes
// (SLAMs, tapering, mitred joins) replace it in engine/stroke.
#pragma once

#include <array>
#include <vector>

#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "lines/visibility.h"
#include "render/surface_pass.h"
#include "scene/style.h"

namespace lw {

class LinePass {
public:
    explicit LinePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM);

    // Builds the quads of `paths` and records their drawing; the returned buffer must live
    // until the command buffer has completed.
    [[nodiscard]] Buffer record(const Context& ctx, VkCommandBuffer cmd, RenderTarget& target,
                                const std::vector<ScreenPath>& paths, const LinesDesc& style) const;

private:
    GraphicsPipeline pipeline_;
};

}  // namespace lw
