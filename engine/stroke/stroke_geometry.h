// engine/stroke/stroke_geometry.h — stroke triangles along screen paths.
//
// Input: a `ScreenPath`, its parameterization T(s) = ρs + φ with its SLAM fold (`StrokeParams`:
// ρ, φ, the fold, `mitre_limit` and the coverage margin), per-sample width, colour and alpha
// (`StrokeAttributes`, made by stroke/modifiers.h), a cap and a join. Output: a triangle list of `StrokeVertex`.
// Caps on open ends are Freestyle's butt / square / round, joins are mitred (clamped to
// `mitre_limit` half widths) or round. A path of one sample, or whose samples span at most
// one pixel of arc length, is a dot: a full disc (round caps) or a square (square caps) of
// the widest sample's width at its midpoint; nothing with butt caps unless it has some
// length. Consecutive samples closer than 1e-4 px are merged (the first one's attributes win)
// so that zero-length segments never define a direction.
//
// Antialiasing (analytic coverage over one pixel of falloff): the triangles are the stroke's
// outline pushed out by `kCoverageMarginPx`, and each vertex carries `edge`, its position
// relative to the centre line, from which the fragment shader computes the share of the pixel
// inside the outline (`stroke_coverage` below, mirrored in shaders/stroke_coverage.glsl). On
// the body it is exact: the ink integrated across a stroke is its width, thinner than a pixel
// too (and ½ on the outline of strokes at least 1.4 px wide). Butt ends get a fringe past the
// end, and the end segments of open paths carry the distance to their end, so that ends ramp
// as well (an open path of one segment is drawn as two, for one end each).
//
// Texture coordinates: u = fold.scale · T(s) along (periods of the sampled level), v across
// (0 on the side of the normal (−dy, dx) of the direction d, 1 on the other, 0.5 on the
// centre line; outside [0, 1] in the coverage margin, where the shader clamps it), w = the
// level coordinate 2l − 1. On caps u continues T past the end with s extended along the end
// tangent, and v follows the offset across; round-join fans keep the sample's u and go from
// 0.5 at the centre to the outer side's v, so a SLAM texture stays continuous across every
// seam between body, join and cap.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "types/line_set.h"
#include "types/screen_path.h"
#include "types/slam_level.h"

namespace lw {

// The line-set builder draws a path of at most this much arc length (pixels) as a dot.
constexpr float kDotLengthPx = 1.0f;

constexpr float kNoEndZ = -1e6f;  // StrokeVertex::edge.z far from any end: no share lost to one

struct StrokeVertex {
    glm::vec2 pixel;
    glm::vec3 tex;    // u, v, w
    glm::vec4 color;  // rgb, alpha (the path's fade alpha)
    // Coverage coordinates, pixels: xy the offset from the centre line (signed across it on
    // the body; from the node on round ends and joins, whose coverage is radial); z near a
    // square end the signed distance past the end sample (the cap's edge lies at z = w), near
    // a butt end the half width plus the signed distance past the end (its edge at z = w),
    // kNoEndZ elsewhere; w the half width of the stroke there.
    glm::vec4 edge{0.0f, 0.0f, kNoEndZ, 0.0f};
};

// How far the triangles reach past the outline: half the diagonal of a pixel, the farthest a
// pixel's square reaches from its centre in any direction (so every pixel that a box filter
// gives some ink is drawn).
constexpr float kCoverageMarginPx = 0.7072f;

// Coverage coordinates of a point deep inside a shape (coverage 1): the fills of vector layers,
// whose triangles are drawn by the stroke pass without an outline to ramp across (their edges
// are not antialiased; an outline stroke over them is).
constexpr glm::vec4 kInteriorEdge{0.0f, 0.0f, kNoEndZ, 1e6f};

// P(u·n ≤ t) for u uniform on a pixel's square [−½, ½]² and n a unit vector: the share of the
// pixel on the inner side of a straight edge at signed distance t from its centre (box
// filter). u·n is the sum of two uniform variables, of widths a ≥ b (|n|'s components): its
// density is a trapezoid, linear in t where it is flat (the whole ramp when n is axis-aligned)
// and quadratic over its slopes. The shaders compute the same (shaders/stroke_coverage.glsl).
inline float square_cdf(float t, glm::vec2 n) {
    const float a = std::max(std::abs(n.x), std::abs(n.y)), b = std::min(std::abs(n.x), std::abs(n.y));
    const float flat = 0.5f * (a - b), reach = 0.5f * (a + b), at = std::abs(t);
    const float upper = at <= flat ? 0.5f + at / a : at < reach ? 1.0f - (reach - at) * (reach - at) / (2.0f * a * b) : 1.0f;
    return t >= 0.0f ? upper : 1.0f - upper;
}

// A pixel's coverage by a stroke, from the coverage coordinates `edge` interpolated at its
// centre and their screen gradients (d/dx and d/dy of edge.xy, and of edge.z): the box-filter
// share of the pixel inside the stroke's outline, taken as straight lines at the distance and
// direction the coordinates give. Across the body it is exact for any width, thinner than a
// pixel too. Round ends and joins take their arc for a straight edge, which is close for
// radii over a pixel (a round dot 1 px wide gets 1.0 px² of ink for π/4). Near square and
// butt ends it multiplies in the share before the end (exact but at the corners).
// Mirrored in stroke_coverage.glsl.
inline float stroke_coverage(const glm::vec4& edge, glm::vec2 dxy_dx, glm::vec2 dxy_dy, glm::vec2 dz) {
    const glm::vec2 e(edge.x, edge.y);
    const float r = glm::length(e), half = std::max(edge.w, 0.0f);
    const float gz = glm::length(dz);
    // The gradient of r = |edge.xy|; on the centre line, that of |edge.x|.
    glm::vec2 grad = r > 1e-4f ? glm::vec2(glm::dot(e, dxy_dx), glm::dot(e, dxy_dy)) / r : glm::vec2(dxy_dx.x, dxy_dy.x);
    float g = glm::length(grad);
    const glm::vec2 n = g > 1e-6f ? grad / g : glm::vec2(1.0f, 0.0f);
    if (!(g > 1e-6f)) g = 1.0f;
    const float across = std::clamp(square_cdf((half - r) / g, n) - square_cdf((-half - r) / g, n), 0.0f, 1.0f);
    const float before_end = gz > 1e-6f ? square_cdf((half - edge.z) / gz, dz / gz) : edge.z <= half ? 1.0f : 0.0f;
    return across * before_end;
}

struct StrokeParams {
    float rho = 0.0f, phi = 0.0f;
    SlamFold fold;
    float mitre_limit = 2.0f;  // in half widths
    // How far the triangles reach past the outline for the coverage ramp; 0: the bare
    // outline, no butt fringes (the SVG export's filled shapes).
    float coverage_margin_px = kCoverageMarginPx;
};

// Per-sample stroke attributes, one entry per sample of the path they were evaluated for
// (all three vectors have the path's sample count; the builder draws nothing otherwise).
struct StrokeAttributes {
    std::vector<float> width;      // full width in pixels, ≥ 0
    std::vector<float> alpha;      // [0, 1]
    std::vector<glm::vec3> color;  // linear rgb
};

void append_stroke(const ScreenPath& path, const StrokeParams& params, const StrokeAttributes& attributes,
                   Cap cap, Join join, std::vector<StrokeVertex>& out);

}  // namespace lw
