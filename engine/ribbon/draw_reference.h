// engine/ribbon/draw_reference.h — the ribbon's pattern drawing in plain C++: the reference
// the GPU pass (ribbon_draw.h, shaders/ribbon_draw.frag) is compared with, and the frame of a
// placed piece both build their inputs from (Zhou et al. 2013, §1.2 and §3.2).
//
// Input:  a `Ribbon`, the `Exemplar`, one position per piece, optionally each seam's stitching
//         remap T (StitchResult::remap) and the forbidden mask, the canvas size.
// Output: the pattern as RGBA8 over a transparent background (straight alpha), as the GPU
//         pass draws it: each piece's two triangles in order, a later piece over an earlier
//         one; at each covered pixel centre the exemplar point, moved by the stitching
//         deformation, read bilinearly with premultiplied alpha (the nearest texel on
//         forbidden pixels, undeformed).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "ribbon/avoidance.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon.h"

namespace lw {

// Piece i placed at u, in exemplar coordinates: its top-left corner A = (u.x + ½, u.y), its
// top-right corner D, and its edges: top (A → D), bottom (bottom left → bottom right), right
// w (D → bottom right) and left l (A → bottom left).
struct PieceFrame {
    glm::vec2 top_left, top_right;
    glm::vec2 top_edge, bottom_edge, right_edge, left_edge;
};
[[nodiscard]] PieceFrame piece_frame(const Ribbon& ribbon, size_t piece, glm::ivec2 u);

// The stitching deformation at exemplar point p of a piece whose right side shows seam T
// (`remap`, C entries; §3.2 "Propagation"): x/(x + r)·Δ·w/C, Δ = T[i] − i interpolated at the
// edge position i where p, moved along the edge direction d (the top and bottom edges mixed by
// p's height on the left edge), meets the right edge; x and r are p's distances along d to the
// left and right edges. Full on the right edge, nothing on the left.
[[nodiscard]] glm::vec2 stitch_deformation(glm::vec2 p, const PieceFrame& frame, std::span<const int32_t> remap);

// `remaps`: per seam r = 1..rows−1 at [r−1], T (null: no stitching); `forbidden`: null for none.
[[nodiscard]] ImageRGBA8 draw_ribbon_reference(const Ribbon& ribbon, const Exemplar& exemplar,
                                               const std::vector<glm::ivec2>& positions,
                                               const std::vector<std::vector<int32_t>>* remaps,
                                               const ForbiddenMask* forbidden, int width, int height);

}  // namespace lw
