// engine/stroke/stroke_geometry.h — textured quads along screen paths.
//
// Two builders share the vertex format and the texture-coordinate convention:
//
// `append_stroke(path, params, out)` — the original one. The renderer no longer draws with it
// (line sets and layers take the one below); it stays as the reference the line-set builder
// is checked against with butt caps and mitre joins (tests/test_modifiers.cpp).
// Input: a visible `ScreenPath` (≥ 2 samples, else nothing), its
// parameterization T(s) = ρs + φ with its SLAM fold, and a width, colour and taper for the
// whole path. Output: a triangle list of `StrokeVertex`: two vertices per sample (left and
// right of the path), consecutive samples joined without cracks. Joins are mitred along the
// bisector of the two segments, the mitre clamped to `mitre_limit` half widths so that sharp
// turns do not spike; ends taper linearly over `taper_px` (never below 15 % of the width).
//
// `append_stroke(path, params, attributes, cap, join, out)` — the line-set one. Width,
// colour and alpha come per sample from `attributes` (stroke/modifiers.h makes them); of
// `params` it reads ρ, φ, the fold and `mitre_limit` only. It adds caps on open ends
// (Freestyle's butt / square / round) and round joins. A path of one sample, or whose
// samples span at most one pixel of arc length, is a dot: a full disc (round caps) or a
// square (square caps) of the widest sample's width at its midpoint; nothing with butt caps
// unless it has some length. Consecutive samples closer than 1e-4 px are merged (the first
// one's attributes win) so that zero-length segments never define a direction.
//
// Texture coordinates: u = fold.scale · T(s) along (periods of the sampled level), v across
// (0 on the side of the normal (−dy, dx) of the direction d, 1 on the other, 0.5 on the
// centre line), w = the level coordinate 2l − 1. On caps u continues T past the end with s
// extended along the end tangent, and v follows the offset across; round-join fans keep the
// sample's u and go from 0.5 at the centre to the outer side's v, so a SLAM texture stays
// continuous across every seam between body, join and cap.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "types/line_set.h"
#include "types/screen_path.h"
#include "types/slam_level.h"

namespace lw {

// The line-set builder draws a path of at most this much arc length (pixels) as a dot.
constexpr float kDotLengthPx = 1.0f;

struct StrokeVertex {
    glm::vec2 pixel;
    glm::vec3 tex;    // u, v, w
    glm::vec4 color;  // rgb, alpha (the path's fade alpha)
};

struct StrokeParams {
    float rho = 0.0f, phi = 0.0f;
    SlamFold fold;
    float width = 2.0f;
    glm::vec3 color{0.0f};
    float taper_px = 0.0f;     // 0: no taper
    float mitre_limit = 2.0f;  // in half widths
};

// Per-sample stroke attributes, one entry per sample of the path they were evaluated for
// (all three vectors have the path's sample count; the builder draws nothing otherwise).
struct StrokeAttributes {
    std::vector<float> width;      // full width in pixels, ≥ 0
    std::vector<float> alpha;      // [0, 1]
    std::vector<glm::vec3> color;  // linear rgb
};

void append_stroke(const ScreenPath& path, const StrokeParams& params, std::vector<StrokeVertex>& out);

void append_stroke(const ScreenPath& path, const StrokeParams& params, const StrokeAttributes& attributes,
                   Cap cap, Join join, std::vector<StrokeVertex>& out);

}  // namespace lw
