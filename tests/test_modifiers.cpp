// Line-set style on the CPU: chaining options, geometry modifiers, dashes, attributes and the
// stroke builder's caps and joins (stroke/modifiers.h, stroke/stroke_geometry.h). Geometry is
// checked by measuring what it covers: a small rasterizer counts 4×4 subsamples per pixel
// whose coverage (stroke_coverage of the interpolated coverage coordinates, what the shaders
// compute; stroke/stroke_reference.h) is at least ½ — the stroke's outline, without the
// antialiasing margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stroke/modifiers.h"
#include "stroke/stroke_geometry.h"
#include "stroke/stroke_reference.h"

namespace lw {
namespace {

constexpr float kPi = 3.14159265358979f;

ScreenSample sample(glm::vec2 pixel, float s) {
    ScreenSample q{};
    q.pixel = pixel;
    q.s = s;
    q.depth = 1.0f;
    q.alpha = 1.0f;
    q.width = 1.0f;
    return q;
}

// A polyline through `points`, s its arclength from s0.
ScreenPath polyline(const std::vector<glm::vec2>& points, float s0 = 0.0f, bool closed = false) {
    ScreenPath path;
    path.closed = closed;
    float s = s0;
    for (size_t i = 0; i < points.size(); ++i) {
        if (i > 0) s += glm::length(points[i] - points[i - 1]);
        path.samples.push_back(sample(points[i], s));
    }
    return path;
}

// Samples every `spacing` px from `from` to `to` (the last one exactly at `to`).
ScreenPath straight(glm::vec2 from, glm::vec2 to, float spacing, float s0 = 0.0f) {
    const float length = glm::length(to - from);
    const int steps = std::max(1, int(std::ceil(length / spacing)));
    std::vector<glm::vec2> points;
    for (int k = 0; k <= steps; ++k) points.push_back(glm::mix(from, to, float(k) / float(steps)));
    return polyline(points, s0);
}

float polyline_length(const ScreenPath& path) {
    float length = 0.0f;
    for (size_t i = 1; i < path.samples.size(); ++i)
        length += glm::length(path.samples[i].pixel - path.samples[i - 1].pixel);
    return length;
}

// Which 4×4 subsamples of a W×H pixel grid lie inside the outline of the triangles' stroke.
struct Coverage {
    static constexpr int kSub = 4;
    int width, height;
    std::vector<char> hit;

    Coverage(const std::vector<StrokeVertex>& triangles, int w, int h)
        : width(w * kSub), height(h * kSub), hit(size_t(width * height), 0) {
        for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
            const StrokeVertex &a = triangles[t], &b = triangles[t + 1], &c = triangles[t + 2];
            const EdgeGradients g = edge_gradients(a, b, c);
            for_each_point_inside(a, b, c, w, h, kSub, [&](int ix, int iy, const glm::vec4& edge, float) {
                if (stroke_coverage(edge, g.dxy_dx, g.dxy_dy, g.dz) >= 0.5f) hit[size_t(iy * width + ix)] = 1;
            });
        }
    }
    static glm::vec2 centre(int ix, int iy) {
        return {(float(ix) + 0.5f) / float(kSub), (float(iy) + 0.5f) / float(kSub)};
    }
    float area_px() const { return float(std::count(hit.begin(), hit.end(), 1)) / float(kSub * kSub); }
    // Covered length of the subsample column through pixel x (pixels).
    float column_px(float x) const {
        const int ix = int(x * kSub);
        int count = 0;
        for (int iy = 0; iy < height; ++iy) count += hit[size_t(iy * width + ix)];
        return float(count) / float(kSub);
    }
    float row_px(float y) const {
        const int iy = int(y * kSub);
        return float(std::count(hit.begin() + iy * width, hit.begin() + (iy + 1) * width, 1)) / float(kSub);
    }
    bool covered(glm::vec2 p) const { return hit[size_t(int(p.y * kSub) * width + int(p.x * kSub))] != 0; }
    float farthest_from(glm::vec2 q) const {
        float d = 0.0f;
        for (int iy = 0; iy < height; ++iy)
            for (int ix = 0; ix < width; ++ix)
                if (hit[size_t(iy * width + ix)]) d = std::max(d, glm::length(centre(ix, iy) - q));
        return d;
    }
};

StrokeParams tiling(float period_px, float phi = 0.0f) {
    return StrokeParams{.rho = 1.0f / period_px, .phi = phi, .fold = {}};
}

LineSetStyle plain_style(float width, Cap cap, Join join = Join::Mitre) {
    LineSetStyle style;
    style.width = width;
    style.cap = cap;
    style.join = join;
    return style;
}

// ---- Chaining options ----

TEST(Chaining, SplitsAtSharpTurnsOnly) {
    ScreenPath corner = polyline({{0, 0}, {25, 0}, {50, 0}, {50, 25}, {50, 50}});
    const auto split = apply_chaining_options({corner}, {.split_angle_deg = 45.0f});
    ASSERT_EQ(split.size(), 2u);
    EXPECT_EQ(split[0].samples.back().pixel, glm::vec2(50, 0));  // the corner ends one piece
    EXPECT_EQ(split[1].samples.front().pixel, glm::vec2(50, 0));  // and starts the next
    EXPECT_FLOAT_EQ(split[1].samples.front().s, 50.0f);           // s kept
    EXPECT_FLOAT_EQ(split[1].samples.back().s, 100.0f);
    EXPECT_EQ(apply_chaining_options({corner}, {.split_angle_deg = 120.0f}).size(), 1u);
    EXPECT_EQ(apply_chaining_options({corner}, {}).size(), 1u);
}

TEST(Chaining, ClosedLoopSplitsIntoOpenPieces) {
    ScreenPath square = polyline({{10, 10}, {20, 10}, {30, 10}, {30, 30}, {10, 30}}, 0.0f, true);
    const auto pieces = apply_chaining_options({square}, {.split_angle_deg = 45.0f});
    ASSERT_EQ(pieces.size(), 4u);
    float total = 0.0f;
    for (const ScreenPath& p : pieces) {
        EXPECT_FALSE(p.closed);
        total += polyline_length(p);
        for (size_t i = 1; i < p.samples.size(); ++i) EXPECT_GT(p.samples[i].s, p.samples[i - 1].s);
    }
    EXPECT_NEAR(total, 80.0f, 1e-4f);  // nothing lost, nothing doubled
}

TEST(Chaining, MaxLengthCutsAndMinLengthDrops) {
    ScreenPath line = straight({0, 0}, {100, 0}, 3.0f, 7.0f);
    const auto cut = apply_chaining_options({line}, {.max_length_px = 30.0f});
    ASSERT_EQ(cut.size(), 4u);
    for (size_t k = 0; k < cut.size(); ++k) {
        EXPECT_LE(polyline_length(cut[k]), 30.0f + 1e-3f);
        EXPECT_NEAR(cut[k].samples.front().s, 7.0f + 25.0f * float(k), 1e-3f);  // s continues
        if (k > 0) {
            EXPECT_EQ(cut[k].samples.front().pixel, cut[k - 1].samples.back().pixel);
        }
    }
    ScreenPath short_line = straight({0, 10}, {30, 10}, 3.0f);
    const auto kept = apply_chaining_options({line, short_line}, {.min_length_px = 40.0f});
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_NEAR(polyline_length(kept[0]), 100.0f, 1e-3f);
    // Cutting happens before dropping: 100 px cut to 50-px pieces survive a 40-px minimum.
    EXPECT_EQ(apply_chaining_options({line}, {.min_length_px = 40.0f, .max_length_px = 50.0f}).size(), 2u);
}

// ---- Geometry modifiers ----

TEST(Geometry, SinusDisplacementMatchesFormula) {
    const float period = 40.0f, phi = 0.3f;
    ScreenPath path = straight({10, 50}, {210, 50}, 2.5f, 4.0f);
    GeometryModifier sinus{
        .kind = GeometryModifier::Kind::Sinus, .wavelength_px = 32.0f, .amplitude_px = 3.0f, .phase = 0.25f};
    const ScreenPath before = path;
    apply_geometry_modifiers(path, tiling(period, phi), period, {sinus});
    for (size_t i = 0; i < path.samples.size(); ++i) {
        const double x = double(before.samples[i].s) + double(phi) * period;  // tiling: x = s + φ·period
        const double expected = 3.0 * std::sin(2.0 * 3.141592653589793 * (x / 32.0 + 0.25));
        // Direction +x: the normal (−dy, dx) is +y.
        EXPECT_NEAR(path.samples[i].pixel.y - 50.0f, expected, 1e-3) << i;
        EXPECT_EQ(path.samples[i].pixel.x, before.samples[i].pixel.x);
    }
}

TEST(Geometry, NoiseIsDeterministicCoherentAndBounded) {
    const float period = 40.0f;
    const StrokeParams param = tiling(period, 0.3f);
    GeometryModifier noise{
        .kind = GeometryModifier::Kind::Noise, .wavelength_px = 16.0f, .amplitude_px = 4.0f, .seed = 7};
    const ScreenPath base = straight({10, 50}, {210, 50}, 2.0f);
    ScreenPath a = base, b = base;
    apply_geometry_modifiers(a, param, period, {noise});
    apply_geometry_modifiers(b, param, period, {noise});
    // Another frame: the path moved on screen and starts at another s, ρ and φ giving the same x.
    ScreenPath moved = base;
    for (ScreenSample& q : moved.samples) q.pixel += glm::vec2(37, -12), q.s += 10.0f;
    StrokeParams moved_param = param;
    moved_param.phi -= 10.0f * param.rho;
    apply_geometry_modifiers(moved, moved_param, period, {noise});
    ScreenPath other_seed = base;
    noise.seed = 8;
    apply_geometry_modifiers(other_seed, param, period, {noise});

    float largest = 0.0f, seed_difference = 0.0f;
    for (size_t i = 0; i < base.samples.size(); ++i) {
        const float d = a.samples[i].pixel.y - base.samples[i].pixel.y;
        EXPECT_EQ(a.samples[i].pixel, b.samples[i].pixel);  // bit-identical
        EXPECT_NEAR(moved.samples[i].pixel.y - (base.samples[i].pixel.y - 12.0f), d, 1e-4f);
        EXPECT_LE(std::abs(d), 4.0f);
        largest = std::max(largest, std::abs(d));
        seed_difference = std::max(seed_difference, std::abs(other_seed.samples[i].pixel.y - a.samples[i].pixel.y));
    }
    EXPECT_GT(largest, 0.5f);          // it does displace
    EXPECT_GT(seed_difference, 0.5f);  // and the seed matters
}

TEST(Geometry, GradientNoiseRangeAndContinuity) {
    float lo = 0.0f, hi = 0.0f, previous = gradient_noise(3, -50.0);
    for (int k = 1; k <= 100000; ++k) {
        const double t = -50.0 + double(k) * 1e-3;
        const float n = gradient_noise(3, t);
        ASSERT_LE(std::abs(n), 1.0f);
        EXPECT_LT(std::abs(n - previous), 0.02f) << t;  // continuous: slope ≤ 2·1.875 per unit
        lo = std::min(lo, n), hi = std::max(hi, n), previous = n;
    }
    EXPECT_EQ(gradient_noise(3, 12.0), 0.0f);  // zero at lattice points
    EXPECT_LT(lo, -0.5f);
    EXPECT_GT(hi, 0.5f);
}

TEST(Geometry, BackboneStretchAndTipRemovalChangeLength) {
    using Kind = GeometryModifier::Kind;
    std::vector<glm::vec2> arc;
    for (int k = 0; k <= 40; ++k)
        arc.push_back(glm::vec2(100, 100) + 60.0f * glm::vec2(std::cos(0.05f * float(k)), std::sin(0.05f * float(k))));
    for (const ScreenPath& base : {straight({0, 0}, {100, 0}, 3.0f), polyline(arc)}) {
        const float length = polyline_length(base);
        ScreenPath stretched = base, cut = base;
        apply_geometry_modifiers(stretched, {}, 1.0f, {{.kind = Kind::BackboneStretch, .length_px = 8.0f}});
        apply_geometry_modifiers(cut, {}, 1.0f, {{.kind = Kind::TipRemove, .length_px = 8.0f}});
        EXPECT_NEAR(polyline_length(stretched), length + 16.0f, 0.01f);
        EXPECT_NEAR(polyline_length(cut), length - 16.0f, 0.01f);
        EXPECT_NEAR(stretched.samples.front().s, base.samples.front().s - 8.0f, 1e-4f);  // s continues past the ends
        EXPECT_NEAR(stretched.samples.back().s, base.samples.back().s + 8.0f, 1e-4f);
    }
    ScreenPath too_short = straight({0, 0}, {15, 0}, 3.0f);
    apply_geometry_modifiers(too_short, {}, 1.0f, {{.kind = Kind::TipRemove, .length_px = 8.0f}});
    EXPECT_LT(too_short.samples.size(), 2u);
    std::vector<StrokeVertex> out;  // and a styled stroke skips it
    LineSetStyle style = plain_style(4.0f, Cap::Round);
    style.geometry = {{.kind = Kind::TipRemove, .length_px = 8.0f}};
    append_styled_stroke(straight({0, 0}, {15, 0}, 3.0f), tiling(40.0f), style, 40.0f, out);
    EXPECT_TRUE(out.empty());
}

TEST(Geometry, SimplifyKeepsEndpointsWithinTolerance) {
    std::vector<glm::vec2> wave;
    for (int k = 0; k <= 400; ++k) wave.push_back({float(k) * 0.5f, 50.0f + 10.0f * std::sin(float(k) * 0.02f)});
    const ScreenPath base = polyline(wave);
    ScreenPath simple = base;
    apply_geometry_modifiers(simple, {}, 1.0f, {{.kind = GeometryModifier::Kind::Simplify, .tolerance_px = 0.5f}});
    ASSERT_GE(simple.samples.size(), 2u);
    EXPECT_LT(simple.samples.size(), base.samples.size() / 4);
    EXPECT_EQ(simple.samples.front().pixel, base.samples.front().pixel);
    EXPECT_EQ(simple.samples.back().pixel, base.samples.back().pixel);
    for (const ScreenSample& q : simple.samples) {  // kept samples are original ones, s included
        const auto it = std::find_if(base.samples.begin(), base.samples.end(),
                                     [&](const ScreenSample& o) { return o.pixel == q.pixel; });
        ASSERT_NE(it, base.samples.end());
        EXPECT_EQ(it->s, q.s);
    }
    for (const ScreenSample& q : base.samples) {  // every original sample within tolerance of the result
        float d = 1e9f;
        for (size_t i = 1; i < simple.samples.size(); ++i) {
            const glm::vec2 a = simple.samples[i - 1].pixel, ab = simple.samples[i].pixel - a;
            const float t = std::clamp(glm::dot(q.pixel - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
            d = std::min(d, glm::length(q.pixel - (a + t * ab)));
        }
        EXPECT_LE(d, 0.5f + 1e-4f);
    }
}

// ---- Dashes ----

struct DashRun {
    std::vector<float> starts, lengths, gaps;  // of the interior dashes
};

DashRun interior_dashes(const ScreenPath& path, const std::vector<ScreenPath>& pieces) {
    DashRun run;
    const float s_first = path.samples.front().s, s_last = path.samples.back().s;
    for (size_t k = 0; k < pieces.size(); ++k) {
        const float a = pieces[k].samples.front().s, b = pieces[k].samples.back().s;
        EXPECT_NEAR(polyline_length(pieces[k]), b - a, 1e-3f);  // interpolated exactly at the ends
        if (k > 0) run.gaps.push_back(a - pieces[k - 1].samples.back().s);
        if (a <= s_first + 1e-3f || b >= s_last - 1e-3f) continue;
        run.starts.push_back(a);
        run.lengths.push_back(b - a);
    }
    return run;
}

TEST(Dashes, LengthsAndGapsFollowTheParameter) {
    const float period = 40.0f;
    const ScreenPath path = straight({10, 20}, {310, 20}, 3.0f, 5.0f);
    const auto pieces = dash_path(path, tiling(period, 0.3f), period, {10.0f, 5.0f});
    const DashRun run = interior_dashes(path, pieces);
    ASSERT_GE(run.lengths.size(), 18u);
    for (float l : run.lengths) EXPECT_NEAR(l, 10.0f, 1e-2f);
    for (float g : run.gaps) EXPECT_NEAR(g, 5.0f, 1e-2f);
    for (float a : run.starts) {  // each dash starts where x = s + φ·period is a multiple of 15
        const float x = a + 0.3f * period;
        EXPECT_NEAR(x - 15.0f * std::round(x / 15.0f), 0.0f, 1e-2f);
    }
    // φ advanced by 3 px of parameter: every dash moves 3 px back along s, as the parameter does.
    const DashRun shifted =
        interior_dashes(path, dash_path(path, tiling(period, 0.3f + 3.0f / period), period, {10.0f, 5.0f}));
    for (float a : shifted.starts) {
        const auto near = std::find_if(run.starts.begin(), run.starts.end(),
                                       [&](float b) { return std::abs(b - (a + 3.0f)) < 1e-2f; });
        EXPECT_NE(near, run.starts.end()) << a;
    }
    // The view moves (pixels change, s and the parameter do not): the dashes stay.
    ScreenPath moved = path;
    for (ScreenSample& q : moved.samples) q.pixel += glm::vec2(-4, 9);
    const DashRun same = interior_dashes(moved, dash_path(moved, tiling(period, 0.3f), period, {10.0f, 5.0f}));
    EXPECT_EQ(same.starts, run.starts);
}

TEST(Dashes, OddPatternRepeatsAndEmptyPatternKeepsThePath) {
    const float period = 40.0f;
    const ScreenPath path = straight({0, 20}, {400, 20}, 3.0f);
    const DashRun run = interior_dashes(path, dash_path(path, tiling(period), period, {10.0f, 5.0f, 3.0f}));
    // [10 5 3] draws as [10 5 3 10 5 3]: dashes 10, 3, 5, … and gaps 5, 10, 3, …
    ASSERT_GE(run.lengths.size(), 6u);
    for (size_t k = 0; k < run.lengths.size(); ++k) {
        const float x = run.starts[k];
        const float in_period = x - 36.0f * std::floor(x / 36.0f + 1e-4f);
        const float expected = in_period < 1.0f ? 10.0f : in_period < 16.0f ? 3.0f : 5.0f;  // starts 0, 15, 28
        EXPECT_NEAR(run.lengths[k], expected, 1e-2f) << x;
    }
    const auto unchanged = dash_path(path, tiling(period), period, {});
    ASSERT_EQ(unchanged.size(), 1u);
    EXPECT_EQ(unchanged[0].samples.size(), path.samples.size());
}

TEST(Dashes, ClosedLoopDashesJoinAcrossTheSeam) {
    const ScreenPath loop = polyline({{0, 0}, {40, 0}, {40, 40}, {0, 40}}, 0.0f, true);  // 160 px
    // x = s + 4: dashes [0, 8] − 4 … a dash covers s ∈ [156, 160) ∪ [0, 4): one piece across the seam.
    const auto pieces = dash_path(loop, tiling(40.0f, 0.1f), 40.0f, {8.0f, 8.0f});
    ASSERT_EQ(pieces.size(), 10u);
    for (const ScreenPath& p : pieces) {
        EXPECT_FALSE(p.closed);
        EXPECT_NEAR(polyline_length(p), 8.0f, 1e-3f);
    }
}

TEST(Dashes, StyleRunsOverTheWholeDashedStroke) {
    // As Freestyle's dashed-line shader, dashes hide parts of one stroke: a width ramp along
    // the stroke spans all dashes (2 px at the start to 10 px at the end), not each dash.
    LineSetStyle style = plain_style(1.0f, Cap::Butt);
    style.dashes = {10.0f, 10.0f};
    style.width_modifiers = {{.ramp = {{{0.0f, 2.0f}, {1.0f, 10.0f}}}, .blend = ModifierBlend::Replace}};
    std::vector<StrokeVertex> out;
    append_styled_stroke(straight({20, 30}, {220, 30}, 2.0f), tiling(40.0f), style, 40.0f, out);
    const Coverage cover(out, 240, 60);
    EXPECT_NEAR(cover.column_px(25.0f), 2.0f + 8.0f * 5.0f / 200.0f, 1.0f);   // in the first dash
    EXPECT_NEAR(cover.column_px(205.0f), 2.0f + 8.0f * 185.0f / 200.0f, 1.0f);  // in the last one
    EXPECT_EQ(cover.column_px(35.0f), 0.0f);                                   // a gap
}

// ---- Attributes ----

TEST(Attributes, WidthRampShapesTheBuiltStroke) {
    LineSetStyle style = plain_style(2.5f, Cap::Butt);
    style.width_modifiers = {{.ramp = {{{0.0f, 2.0f}, {0.5f, 10.0f}, {1.0f, 4.0f}}}, .blend = ModifierBlend::Replace}};
    const ScreenPath path = straight({20, 30}, {220, 30}, 2.0f);
    std::vector<StrokeVertex> out;
    append_styled_stroke(path, tiling(40.0f), style, 40.0f, out);
    const Coverage cover(out, 240, 60);
    EXPECT_NEAR(cover.column_px(20.6f), 2.0f, 1.0f);
    EXPECT_NEAR(cover.column_px(120.0f), 10.0f, 1.0f);
    EXPECT_NEAR(cover.column_px(219.4f), 4.0f, 1.0f);
    EXPECT_NEAR(cover.column_px(70.0f), 6.0f, 1.0f);  // linear between
    EXPECT_EQ(cover.column_px(19.5f), 0.0f);          // butt: nothing past the ends
    EXPECT_EQ(cover.column_px(220.5f), 0.0f);
}

TEST(Attributes, TaperFadeAlphaAndColour) {
    LineSetStyle style = plain_style(6.0f, Cap::Butt);
    style.taper_in_px = 20.0f;
    style.taper_out_px = 10.0f;
    style.alpha = 0.8f;
    style.alpha_modifiers = {{.ramp = {{{0.0f, 1.0f}, {1.0f, 2.0f}}}}};  // multiply: 0.8 → 1.6 → clamped
    style.color = {1.0f, 0.0f, 0.0f};
    style.color_modifiers = {{.ramp = {{{0.0f, glm::vec3(0, 0, 1)}}}, .influence = 0.5f}};
    ScreenPath path = straight({0, 0}, {100, 0}, 5.0f);
    for (ScreenSample& q : path.samples) q.alpha = 0.5f;
    const StrokeAttributes a = evaluate_attributes(path, style);
    ASSERT_EQ(a.width.size(), path.samples.size());
    EXPECT_NEAR(a.width.front(), 0.9f, 1e-5f);  // tips keep 15 % of the width
    EXPECT_NEAR(a.width[2], 3.0f, 1e-5f);  // s = 10: half way in
    EXPECT_NEAR(a.width[10], 6.0f, 1e-5f);
    EXPECT_NEAR(a.width[19], 3.0f, 1e-5f);  // s = 95: half way out
    EXPECT_NEAR(a.width.back(), 0.9f, 1e-5f);
    EXPECT_NEAR(a.alpha.front(), 0.4f, 1e-6f);   // 0.8 · fade 0.5 · ramp 1
    EXPECT_NEAR(a.alpha[10], 0.6f, 1e-6f);       // · 1.5 half way
    EXPECT_NEAR(a.alpha.back(), 0.8f, 1e-6f);
    EXPECT_NEAR(a.color[7].r, 0.5f, 1e-6f);
    EXPECT_NEAR(a.color[7].b, 0.5f, 1e-6f);
    style.fade = false;
    style.alpha_modifiers[0].blend = ModifierBlend::Add;
    EXPECT_EQ(evaluate_attributes(path, style).alpha[10], 1.0f);  // 0.8 + 1.5, clamped
    path.closed = true;  // loops have no ends to taper
    EXPECT_NEAR(evaluate_attributes(path, style).width.front(), 6.0f, 1e-6f);
}

TEST(Attributes, CurvatureAndDistanceInputs) {
    std::vector<glm::vec2> circle;
    for (int k = 0; k < 64; ++k)
        circle.push_back(glm::vec2(100, 100) +
                         50.0f * glm::vec2(std::cos(float(k) * kPi / 32.0f), std::sin(float(k) * kPi / 32.0f)));
    ScreenPath path = polyline(circle, 0.0f, true);
    for (size_t i = 0; i < path.samples.size(); ++i) path.samples[i].depth = 2.0f + float(i) / 63.0f * 4.0f;
    LineSetStyle style = plain_style(1.0f, Cap::Butt);
    const Ramp identity{{{0.0f, 0.0f}, {1.0f, 1.0f}}};
    style.width_modifiers = {{.input = ModifierInput::Curvature, .range_min = 0.0f, .range_max = 0.04f,
                              .ramp = {{{0.0f, 0.0f}, {1.0f, 10.0f}}}, .blend = ModifierBlend::Replace}};
    style.alpha_modifiers = {{.input = ModifierInput::Distance, .range_min = 3.0f, .range_max = 5.0f,
                              .ramp = identity, .blend = ModifierBlend::Replace}};
    const StrokeAttributes a = evaluate_attributes(path, style);
    for (float w : a.width) EXPECT_NEAR(w, 5.0f, 0.05f);  // κ = 1/50 = half of 0.04 → 5 px
    EXPECT_EQ(a.alpha.front(), 0.0f);                      // depth 2 < 3
    EXPECT_NEAR(a.alpha[31], (2.0f + 31.0f / 63.0f * 4.0f - 3.0f) / 2.0f, 1e-5f);
    EXPECT_EQ(a.alpha.back(), 1.0f);                       // depth 6 > 5
}

// A dense mesh's screen path wiggles at the sample scale: a straight run of samples 2 px apart,
// each 0.3 px off the line to alternate sides, turned by about 0.58 rad between neighbouring
// segments, read as a curvature of 0.28 / px (a width modifier drew it as barbed wire). The
// turn is measured over ±4 px, where the wiggle averages out; a circle still reads 1/r.
TEST(Attributes, CurvatureIsNotTheSampleScaleWiggle) {
    std::vector<glm::vec2> line;
    for (int k = 0; k <= 40; ++k) line.push_back({float(2 * k), 20.0f + (k % 2 ? 0.3f : -0.3f)});
    LineSetStyle style = plain_style(1.0f, Cap::Butt);
    style.width_modifiers = {{.input = ModifierInput::Curvature, .range_min = 0.0f, .range_max = 0.1f,
                              .ramp = {{{0.0f, 0.0f}, {1.0f, 10.0f}}}, .blend = ModifierBlend::Replace}};
    const StrokeAttributes a = evaluate_attributes(polyline(line), style);
    for (size_t i = 2; i + 2 < a.width.size(); ++i) EXPECT_LT(a.width[i], 1.0f) << i;  // κ < 0.01 / px (was 0.28)
    // A dense circle of radius 40 (samples 2 px apart) reads κ = 1/40 within 2 %.
    std::vector<glm::vec2> circle;
    const int count = int(std::round(2.0 * kPi * 40.0 / 2.0));
    for (int k = 0; k < count; ++k)
        circle.push_back(glm::vec2(100, 100) + 40.0f * glm::vec2(std::cos(2.0f * kPi * float(k) / float(count)),
                                                                 std::sin(2.0f * kPi * float(k) / float(count))));
    for (float w : evaluate_attributes(polyline(circle, 0.0f, true), style).width) EXPECT_NEAR(w, 2.5f, 0.05f);
}

// ---- Caps and joins ----

TEST(Caps, RoundCapsMakeAOnePixelStrokeADisc) {
    const LineSetStyle style = plain_style(8.0f, Cap::Round);
    const glm::vec2 centre(20.5f, 20.0f);
    const std::vector<ScreenPath> dots = {
        polyline({{20, 20}, {21, 20}}),                        // 1 px long
        polyline({centre, centre, centre}),                    // all samples coincide
        polyline({centre}),                                    // one sample
        polyline({{20.1f, 20}, {20.5f, 20.15f}, {20.9f, 20}}),  // bent, 0.85 px of arclength
    };
    for (size_t k = 0; k < dots.size(); ++k) {
        std::vector<StrokeVertex> out;
        append_styled_stroke(dots[k], tiling(40.0f), style, 40.0f, out);
        const Coverage cover(out, 48, 48);
        EXPECT_NEAR(cover.area_px(), kPi * 16.0f, 0.1f * kPi * 16.0f) << k;
        EXPECT_LE(cover.farthest_from(centre), 4.5f) << k;
        EXPECT_TRUE(cover.covered(centre + glm::vec2(0.0f, 3.5f))) << k;
        EXPECT_TRUE(cover.covered(centre + glm::vec2(-3.5f, 0.0f))) << k;
    }
    std::vector<StrokeVertex> butt;
    append_styled_stroke(dots[1], tiling(40.0f), plain_style(8.0f, Cap::Butt), 40.0f, butt);
    EXPECT_TRUE(butt.empty());  // a butt-capped point has no length to draw
}

TEST(Caps, SquareAndRoundExtendByHalfTheWidth) {
    const ScreenPath path = straight({20, 30}, {60, 30}, 4.0f);
    auto covered_row = [&](Cap cap) {
        std::vector<StrokeVertex> out;
        append_styled_stroke(path, tiling(40.0f), plain_style(6.0f, cap), 40.0f, out);
        return Coverage(out, 80, 60);
    };
    EXPECT_NEAR(covered_row(Cap::Butt).row_px(30.1f), 40.0f, 0.5f);
    EXPECT_NEAR(covered_row(Cap::Square).row_px(30.1f), 46.0f, 0.5f);
    EXPECT_NEAR(covered_row(Cap::Round).row_px(30.1f), 46.0f, 0.5f);
    // Square caps fill the corners, round ones do not.
    EXPECT_TRUE(covered_row(Cap::Square).covered({17.4f, 27.4f}));
    EXPECT_FALSE(covered_row(Cap::Round).covered({17.4f, 27.4f}));
    EXPECT_NEAR(covered_row(Cap::Round).area_px(), 40.0f * 6.0f + kPi * 9.0f, 3.0f);
}

TEST(Caps, TextureCoordinatesContinuePastTheEnds) {
    const float period = 40.0f, phi = 0.25f;
    const ScreenPath path = straight({20, 30}, {60, 30}, 4.0f, 10.0f);
    LineSetStyle style = plain_style(6.0f, Cap::Round);
    std::vector<StrokeVertex> out;
    append_styled_stroke(path, tiling(period, phi), style, period, out);
    float u_min = 1e9f, u_max = -1e9f;
    // Vertices lie kCoverageMarginPx outside the outline (the antialiasing margin): v maps
    // the stroke's 6 px to [0, 1], so it reaches 0.5 ± 0.5·(3 + margin)/3 there.
    const float reach = 3.0f + kCoverageMarginPx;
    for (const StrokeVertex& v : out) {
        EXPECT_GE(v.tex.y, 0.5f - 0.5f * reach / 3.0f - 1e-6f);
        EXPECT_LE(v.tex.y, 0.5f + 0.5f * reach / 3.0f + 1e-6f);
        // u = (s + ∆)/period + φ where ∆ is the vertex's offset along the path.
        const float s = v.pixel.x - 20.0f + 10.0f;
        EXPECT_NEAR(v.tex.x, s / period + phi, 1e-5f);
        if (v.pixel == glm::vec2(20, 30) || v.pixel == glm::vec2(60, 30)) {
            EXPECT_FLOAT_EQ(v.tex.y, 0.5f);  // the centre of a cap's fan
        }
        u_min = std::min(u_min, v.tex.x), u_max = std::max(u_max, v.tex.x);
    }
    EXPECT_NEAR(u_min, (10.0f - reach) / period + phi, 1e-5f);
    EXPECT_NEAR(u_max, (50.0f + reach) / period + phi, 1e-5f);
}

TEST(Joins, RoundJoinRoundsTheOuterCorner) {
    // Right, then down: the outer corner is up and to the right of (60, 30).
    const ScreenPath path = polyline({{20, 30}, {40, 30}, {60, 30}, {60, 50}, {60, 70}});
    auto cover = [&](Join join) {
        std::vector<StrokeVertex> out;
        append_styled_stroke(path, tiling(40.0f), plain_style(10.0f, Cap::Butt, join), 40.0f, out);
        return Coverage(out, 90, 90);
    };
    const Coverage mitre = cover(Join::Mitre), round = cover(Join::Round);
    const glm::vec2 corner(60, 30), diagonal = glm::normalize(glm::vec2(1, -1));
    EXPECT_TRUE(mitre.covered(corner + 6.5f * diagonal));   // the mitre's tip is at 5·√2 ≈ 7.07
    EXPECT_FALSE(round.covered(corner + 5.5f * diagonal));  // the fan stops at the half width
    EXPECT_TRUE(round.covered(corner + 4.6f * diagonal));
    for (float a = 0.05f; a < 0.5f * kPi; a += 0.1f)  // the whole quarter disc is covered
        EXPECT_TRUE(round.covered(corner + 4.6f * glm::vec2(std::cos(a), -std::sin(a)))) << a;
    EXPECT_NEAR(round.area_px(), mitre.area_px() - 25.0f * (1.0f - kPi / 4.0f), 2.0f);
}

TEST(Styles, DegenerateInputsAreSafe) {
    using Kind = GeometryModifier::Kind;
    ScreenPath two_point_loop = polyline({{5, 5}, {9, 5}}, 0.0f, true);
    ScreenPath u_turn = polyline({{5, 5}, {25, 5}, {5, 5.0001f}, {5, 5}});
    const std::vector<ScreenPath> paths = {ScreenPath{}, polyline({{3, 3}}), polyline({{3, 3}, {3, 3}}),
                                           two_point_loop, u_turn, straight({0, 0}, {0, 40}, 1.0f)};
    LineSetStyle style = plain_style(4.0f, Cap::Round, Join::Round);
    style.dashes = {0.0f, 6.0f, 3.0f};
    style.taper_in_px = style.taper_out_px = 5.0f;
    style.width_modifiers = {{.input = ModifierInput::Curvature, .ramp = {{{0.0f, 1.0f}}}}};
    style.geometry = {{.kind = Kind::Sinus}, {.kind = Kind::Noise}, {.kind = Kind::BackboneStretch},
                      {.kind = Kind::Simplify}, {.kind = Kind::TipRemove, .length_px = 1.0f}};
    // 1 + 1 + 1 pass through; the 8-px loop is cut in 2; the U-turn splits at both turns into
    // 20 + 20 + 0.0001 px (3 + 3 + 1 pieces); 40 px in 6.
    EXPECT_EQ(apply_chaining_options(paths, {.split_angle_deg = 10.0f, .max_length_px = 7.0f}).size(), 18u);
    for (const Cap cap : {Cap::Butt, Cap::Round, Cap::Square})
        for (const Join join : {Join::Mitre, Join::Round}) {
            style.cap = cap, style.join = join;
            for (const ScreenPath& path : paths) {
                std::vector<StrokeVertex> out;
                append_styled_stroke(path, tiling(40.0f), style, 40.0f, out);
                EXPECT_EQ(out.size() % 3, 0u);
                for (const StrokeVertex& v : out) EXPECT_TRUE(std::isfinite(v.pixel.x) && std::isfinite(v.pixel.y));
                EXPECT_EQ(evaluate_attributes(path, style).width.size(), path.samples.size());
            }
        }
}

}  // namespace
}  // namespace lw

