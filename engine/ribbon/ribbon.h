// engine/ribbon/ribbon.h — a ribbon around a curve, sliced into pieces (Zhou et al. 2013, §1.1–1.2).
//
// Input:  an `ArclengthCurve` and `RibbonParams` (b, δ, s).
// Output: `Ribbon`: pieces i = 0..N-1, quadrilaterals (T(x_i), B(x_i), B(x_i+1), T(x_i+1)) in
//         output pixels, with T(x) = C(x) + b/2·n(x), B(x) = C(x) − b/2·n(x), x_i = iδ.
//
// Conventions (pixels, y down, in the canvas and in the exemplar E):
// - n(x) is the tangent turned so that a curve running left to right has n pointing up:
//   n = (t.y, −t.x). The top offset T lies on that side.
// - Each piece is copied into E by a similarity (§1.2): rotation R_i taking the piece's
//   chord, from the middle of its left edge C(x_i) to the middle of its right edge C(x_i+1),
//   to +x, and scaling s/b (an edge spans s exemplar pixels: the paper's M·l_i = y with
//   |y| = 1, times s). The paper takes the tangent at x_i to +x, keeping the left edge
//   vertical; but the straight pattern of a piece then ends off the curve by the arc's
//   offset from that tangent, κδ²/2 towards the outside, and the next piece starts from the
//   curve again, so
//   that along a bend the pattern must step back at every seam or drift out of the ribbon:
//   πδ over a closed loop, which cut a chain in four places around a circle of radius 4.5δ.
//   Along the chord the pattern enters and leaves every piece on the curve. Where the curve
//   does not turn over a piece the chord is the tangent, and the left edge is vertical.
//   A piece placed at integer position u = (x, y) has its top-left corner at (x + 0.5, y) in
//   E, so that a vertical left edge runs through the centres of texel column x; edge sample
//   k of C = ⌈s⌉ lies at (k + 0.5)/C along an edge — on texel centres when s is an integer.
// - Drawing reads the texel under e + (½, 0): a straight piece of w = δs/b texels shows
//   columns x+1 … x+w, the span (left edge, right edge], so at a perfect seam (next piece at
//   x+w) every column appears once; and where a ribbon is aligned with the pixel grid, pixel
//   centres land on texel centres rather than on texel borders, where rounding could flicker.
// - L/δ is rarely an integer: the remainder r = L − ⌊L/δ⌋δ becomes a final, shorter piece
//   when r > δ/4 and lengthens the last piece otherwise (the paper: "a final smaller piece
//   can be added"). A closed curve's last piece ends exactly on the first one's left edge.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "vector/curve.h"

namespace lw {

struct RibbonParams {
    float width = 0.0f;  // b: ribbon width, output pixels
    float piece = 0.0f;  // δ: piece length along the curve, output pixels
    float scale = 0.0f;  // s: exemplar pixels across the ribbon (the left edge of every piece in E)
};

struct RibbonPiece {
    glm::vec2 top_left{0.0f};      // T(x_i)
    glm::vec2 bottom_left{0.0f};   // B(x_i)
    glm::vec2 bottom_right{0.0f};  // B(x_i+1)
    glm::vec2 top_right{0.0f};     // T(x_i+1)
    glm::vec2 tangent{1.0f, 0.0f};  // unit tangent at x_i (the left edge is its normal)
    glm::vec2 chord{1.0f, 0.0f};    // unit direction the piece is copied along (+x in E; see above)
};

// The left edge of a piece in E, top to bottom: s·(sin φ, cos φ) for the turn φ from the
// tangent to the chord; exactly (0, s) where they are the same.
[[nodiscard]] glm::dvec2 left_edge_in_exemplar(const RibbonPiece& piece, double scale);

struct Ribbon {
    std::vector<RibbonPiece> pieces;
    bool closed = false;
    float width = 0.0f;  // b
    float scale = 0.0f;  // s
    int samples = 0;     // C = ⌈s⌉ samples per piece edge

    // Exemplar coordinates of canvas point p when piece i is placed at u (continuous; the
    // texel is floor()). Affine in p, so it can be interpolated across the piece's triangles.
    glm::vec2 to_exemplar(size_t piece, glm::ivec2 u, glm::vec2 p) const;
    // Bounding box of all piece corners, output pixels.
    glm::vec2 min_corner() const;
    glm::vec2 max_corner() const;
};

// C = ⌈s⌉, the samples along each piece edge for scale s (an s a hair over an integer, from
// rounding, does not take one more).
[[nodiscard]] inline int ribbon_edge_samples(float scale) { return static_cast<int>(std::ceil(scale - 1e-4f)); }

// Throws lw::Error (exit code 2 for parameter values) for b, δ, s not positive, C > 4096 or
// more than 100000 pieces.
[[nodiscard]] Ribbon build_ribbon(const ArclengthCurve& curve, const RibbonParams& params);

// The output size when none is asked for: from the origin to past the ribbon's far corner, and
// at least the page an SVG curve was drawn on (`page`, 0 for none), so that the image lines up
// with that drawing. Throws lw::Error naming `curve_file` past kLargestImageSide pixels.
[[nodiscard]] glm::ivec2 default_ribbon_size(const Ribbon& ribbon, glm::vec2 page, const std::string& curve_file);

// An output of width × height pixels that no piece reaches into would be blank: a
// ParameterError "ribbon size" saying where the ribbon lies. (Piece by piece: the ribbon's box
// can overlap an image that the ribbon misses.)
void check_ribbon_in_image(const Ribbon& ribbon, int width, int height);

}  // namespace lw
