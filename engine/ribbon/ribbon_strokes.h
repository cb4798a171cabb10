// engine/ribbon/ribbon_strokes.h — ribbons as a stroke style for the 3D renderer's paths.
//
// Input:  a frame's visible screen paths (lines/visibility.h), one line type, the ribbon
//         exemplar and the style's width; the frame's colour image.
// Output: the colour image with a structured pattern (Zhou et al. 2013) synthesized along
//         every visible path of that type and composited over it.
//
// Each path is its own curve: ribbon of width b = the style's width, pieces of δ = b/2, the
// DP on the GPU with the avoidance of fold-overs (synthesize.h). Paths shorter than two
// pieces are skipped (no room for a seam to optimize). The synthesis is per frame and
// seeded per path index: a still frame is deterministic, but the paper gives no temporal
// coherence for ribbons, so an animation re-chooses pieces from frame to frame.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/image.h"
#include "gpu/context.h"
#include "lines/visibility.h"
#include "ribbon/exemplar.h"

namespace lw {

struct RibbonStrokeDesc {
    float width = 0.0f;  // b, output pixels
    float scale = 0.0f;  // s, exemplar pixels across (0: default_ribbon_scale)
    uint64_t seed = 1;
};

struct RibbonStrokeStats {
    size_t paths = 0;    // paths drawn
    size_t skipped = 0;  // visible paths of the type too short for two pieces
    double ms = 0.0;
};

// `type`: only paths of this line type (absent: every visible path, as for a vector layer).
RibbonStrokeStats draw_ribbon_strokes(const Context& ctx, const std::vector<ScreenPath>& paths,
                                      std::optional<LineType> type,
                                      const Exemplar& exemplar, const RibbonStrokeDesc& desc, ImageRGBA8& image);

}  // namespace lw
