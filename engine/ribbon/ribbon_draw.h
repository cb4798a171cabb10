// engine/ribbon/ribbon_draw.h — drawing a ribbon on the GPU: the avoidance map (§3.1) and the
// synthesized pattern with the stitching deformation (§3.2) of Zhou et al. 2013.
//
// Input:  a `Ribbon` (pieces in output pixels), the canvas size, and for the pattern the
//         `Exemplar`, one position per piece (the DP's, rows beyond the pieces ignored),
//         optionally the `StitchResult` and the forbidden mask.
// Output: coverage counts / a `ForbiddenMask` of pixels covered more than once; or the
//         pattern as RGBA8 over a transparent background (straight alpha, as E stores it).
//
// Both passes draw every piece as its two triangles (T(x_i), B(x_i), B(x_i+1)) and
// (T(x_i), B(x_i+1), T(x_i+1)) with exemplar coordinates at the corners; the avoidance
// pass counts coverage by additive blending into RGBA8 (red = count / 255), the pattern
// pass resamples the exemplar bilinearly, nearest on forbidden pixels (shaders/ribbon_draw.frag).
// Their plain C++ references: avoidance.h (coverage) and draw_reference.h (the pattern).
#pragma once

#include <vector>

#include "core/image.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "ribbon/avoidance.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon.h"
#include "ribbon/stitch.h"

namespace lw {

class RibbonRenderer {
public:
    explicit RibbonRenderer(const Context& ctx);

    [[nodiscard]] std::vector<uint8_t> coverage_counts(const Ribbon& ribbon, int width, int height) const;
    [[nodiscard]] ForbiddenMask avoidance_map(const Ribbon& ribbon, int width, int height) const;

    [[nodiscard]] ImageRGBA8 draw(const Ribbon& ribbon, const Exemplar& exemplar,
                                  const std::vector<glm::ivec2>& positions, const StitchResult* stitch,
                                  const ForbiddenMask* forbidden, int width, int height) const;

private:
    const Context* ctx_;
    GraphicsPipeline avoid_;
    GraphicsPipeline draw_;
};

}  // namespace lw
