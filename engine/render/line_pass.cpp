#include "render/line_pass.h"

#include <algorithm>
#include <cstring>

#include "lines_draw_frag.h"
#include "lines_draw_vert.h"
#include "stroke/modifiers.h"
#include "stroke/stroke_geometry.h"
#include "stroke/stroke_pass.h"

namespace lw {

namespace {

// Indices of the samples to draw through (greedy: extend the current straight piece while
// every skipped sample lies within `tolerance` px of it and alpha stays within 0.05).
std::vector<size_t> simplify(const ScreenPath& path, float tolerance = 0.25f) {
    const auto& s = path.samples;
    std::vector<size_t> kept{0};
    size_t anchor = 0;
    for (size_t next = 2; next < s.size(); ++next) {
        const glm::vec2 a = s[anchor].pixel, b = s[next].pixel;
        const glm::vec2 ab = b - a;
        const float len = glm::length(ab);
        bool straight = len > 0.0f;
        for (size_t k = anchor + 1; k < next && straight; ++k) {
            const glm::vec2 ak = s[k].pixel - a;
            const float off_line = std::abs(ab.x * ak.y - ab.y * ak.x) / len;
            straight = off_line <= tolerance && std::abs(s[k].alpha - s[anchor].alpha) <= 0.05f &&
                       glm::dot(ak, ab) >= 0.0f;
        }
        if (!straight || next - anchor > 64) {  // the cap bounds the quadratic check
            kept.push_back(next - 1);
            anchor = next - 1;
        }
    }
    if (s.size() > 1) kept.push_back(s.size() - 1);
    return kept;
}

}  // namespace

// The stroke builder's triangles for each run, of the type's width (thinner and fainter for
// hidden runs drawn faint or dashed), with mitre joins and square caps: antialiased like every
// stroke (stroke_geometry.h). Mitres, not round joins: the fans of round joins at every sharp
// turn of dense feature lines cost lavapipe 1.4× the drawing (FlightHelmet, 1920×1080: 13 → 18
// ms), and at 1.5–2.5 px the two look alike. u is the arc length in pixels (ρ = 1, φ = 0) for the dashes, and
// the level coordinate w, which a flat line does not need, says whether the run is dashed.
std::vector<StrokeVertex> line_triangles(const std::vector<ScreenPath>& paths, const LineDrawStyle& style,
                                         float margin_px, bool geometric_dashes) {
    std::vector<StrokeVertex> vertices;
    for (const ScreenPath& path : paths) {
        const float faint = path.visible || style.hidden != HiddenLines::Faint ? 1.0f : 0.25f;
        const bool dashed = !path.visible && style.hidden == HiddenLines::Dashed;
        const float width = path.visible || style.hidden == HiddenLines::None ? style.width
                                                                              : std::max(1.0f, 0.6f * style.width);
        // Draw through the samples that matter: a sample is skipped while the polyline from
        // the last kept one stays within 0.25 px of a straight line and the alpha barely
        // changes. Visibility samples every δ px are far denser than straight runs need,
        // and lavapipe pays per triangle.
        ScreenPath kept = path;
        kept.samples.clear();
        for (const size_t i : simplify(path)) kept.samples.push_back(path.samples[i]);
        // The type's width and colour, the style's alpha times each sample's fade.
        auto attributes_of = [&](const ScreenPath& piece) {
            const size_t n = piece.samples.size();
            StrokeAttributes a{.width = std::vector<float>(n, width), .alpha = {},
                               .color = std::vector<glm::vec3>(n, style.color)};
            for (const ScreenSample& q : piece.samples) a.alpha.push_back(style.alpha * (style.fade ? q.alpha : 1.0f) * faint);
            return a;
        };
        const StrokeParams params{.rho = 1.0f, .phi = 0.0f, .fold = {.level = 1.0f, .scale = 1.0f, .w = dashed ? 1.0f : 0.0f},
                                  .coverage_margin_px = margin_px};
        if (!(dashed && geometric_dashes)) {
            append_stroke(kept, params, attributes_of(kept), Cap::Square, Join::Mitre, vertices);
            continue;
        }
        // The shader's dashes: on where fract(s / period) ≤ ½, butt-ended.
        for (const ScreenPath& dash : dash_path(kept, StrokeParams{}, 1.0f, {0.5f * kDashPeriodPx, 0.5f * kDashPeriodPx}))
            append_stroke(dash, params, attributes_of(dash), Cap::Butt, Join::Mitre, vertices);
    }
    return vertices;
}

LinePass::LinePass(const Context& ctx, VkFormat color_format)
    : draw_(ctx,
            {.vertex_spirv = LW_SPIRV(lines_draw_vert_spv), .fragment_spirv = LW_SPIRV(lines_draw_frag_spv),
             .name = "lines draw"},
            color_format) {}

bool LinePass::record(const Context& ctx, VkCommandBuffer cmd, RenderTarget& target, const std::vector<ScreenPath>& paths,
                      const LineDrawStyle& style, UploadArena& arena, CoverageLayer* layer) const {
    return draw_.record(ctx, cmd, target, line_triangles(paths, style, kCoverageMarginPx, false), kDashPeriodPx, arena,
                        layer);
}

}  // namespace lw
