// engine/render/line_pass.h — draws screen-space paths as flat strokes over the colour target.
//
// Input:  the `ScreenPath`s of one plain line set (render/line_sets.h) and its draw style:
//         colour, alpha, width, whether the fade alpha applies, and the look of hidden runs
//         (dashed or faint, the scene's "hidden"; plain for sets that select hidden lines).
// Output: the paths composited (alpha blended, fade alpha per sample, antialiased) into the
//         render target's colour image, which is left in TRANSFER_SRC_OPTIMAL as the surface
//         pass leaves it; or, for a translucent set, drawn into a coverage layer
//         (gpu/coverage_layer.h) whose composite then draws them once.
//
// This is the plain line look of the feature-lines stage: flat strokes of the type's width
// along each run, mitre joins and square caps, built by the stroke builder
// (stroke/stroke_geometry.h) so that they are antialiased like every stroke. Textured strokes
// (SLAMs, modifiers) are drawn by engine/stroke's pass.
#pragma once

#include <array>
#include <vector>

#include "gpu/context.h"
#include "gpu/coverage_layer.h"
#include "gpu/pipeline.h"
#include "lines/visibility.h"
#include "render/surface_pass.h"
#include "scene/style.h"
#include "stroke/stroke_geometry.h"
#include "stroke/stroke_pass.h"

namespace lw {

struct LineDrawStyle {
    glm::vec3 color{0.0f};
    float alpha = 1.0f;
    float width = 2.5f;
    bool fade = true;                         // multiply by each sample's fade alpha
    HiddenLines hidden = HiddenLines::None;   // hidden runs: None draws them as visible ones
};

// Dashed hidden runs: on for the first half of every period of arc length.
constexpr float kDashPeriodPx = 8.0f;

// The triangles the pass draws for `paths` in `style` (stroke/stroke_geometry.h), reaching
// `margin_px` past the outline (kCoverageMarginPx; 0: the bare outline, the SVG's shapes).
// The pass cuts dashes per fragment; with `geometric_dashes` dashed runs are cut into their
// dashes here instead (butt-ended), for output without a shader.
[[nodiscard]] std::vector<StrokeVertex> line_triangles(const std::vector<ScreenPath>& paths, const LineDrawStyle& style,
                                                       float margin_px, bool geometric_dashes);

class LinePass {
public:
    explicit LinePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM);

    // Builds the triangles of `paths` into `arena` and records their drawing; the arena must
    // not be reset before the command buffer has completed. With `layer`, they are drawn into
    // it (begun and ended here) for a composite that draws them once, instead of over the
    // target. False: nothing to draw (nothing recorded).
    bool record(const Context& ctx, VkCommandBuffer cmd, RenderTarget& target, const std::vector<ScreenPath>& paths,
                const LineDrawStyle& style, UploadArena& arena, CoverageLayer* layer = nullptr) const;

private:
    StrokeDrawPipelines draw_;
};

}  // namespace lw
