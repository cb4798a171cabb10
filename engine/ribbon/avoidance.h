// engine/ribbon/avoidance.h — the avoidance map: canvas pixels the pattern must not cover
// (Zhou et al. 2013, §3.1).
//
// Fold-overs and self-overlaps: every piece is drawn off-screen as its two triangles
// (T(x_i), B(x_i), B(x_i+1)) and (T(x_i), B(x_i+1), T(x_i+1)), counting how often each pixel
// is covered; a pixel covered more than once is where the ribbon folds over itself (a piece
// whose right edge crosses its left edge, §1.2) or overlaps another part of the curve.
// Consecutive pieces share their edge exactly, so a gentle bend counts once everywhere.
// The GPU version draws it (engine/ribbon/ribbon_draw.h, additive blending); this file has
// the plain C++ rasterization (pixel centres, a consistent tie rule on shared edges) and
// the user's own map, which covers the whole canvas.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "ribbon/ribbon.h"

namespace lw {

struct ForbiddenMask {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;  // 1 = forbidden, rows top to bottom

    bool at(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height && pixels[size_t(y) * size_t(width) + size_t(x)] != 0;
    }
    size_t count() const;
};

// Coverage counts of the ribbon's triangles on a width × height canvas (saturating at 255).
[[nodiscard]] std::vector<uint8_t> coverage_counts_reference(const Ribbon& ribbon, int width, int height);
// Pixels covered more than once.
[[nodiscard]] ForbiddenMask avoidance_map_reference(const Ribbon& ribbon, int width, int height);
// A user's map: pixels with alpha ≥ 128 are forbidden.
[[nodiscard]] ForbiddenMask forbidden_from_image(const ImageRGBA8& image);
// Sets every pixel forbidden in `other` (same size) in `into`.
void merge_forbidden(ForbiddenMask& into, const ForbiddenMask& other);

}  // namespace lw
