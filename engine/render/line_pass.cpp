#include "render/line_pass.h"

#include <algorithm>
#include <cstring>

#include "lines_draw_frag.h"
#include "lines_draw_vert.h"

namespace lw {

namespace {

struct LineVertex {
    glm::vec2 pixel;
    glm::vec4 color;
    glm::vec2 arc;  // arc length, dashed flag
};

struct LineDrawPush {
    glm::vec2 viewport;
    float dash_period;
    float pad;
};

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

// Two triangles per segment of each run, extended by half the width at both ends (square
// caps) so that neighbouring quads cover the joint.
std::vector<LineVertex> build_quads(const std::vector<ScreenPath>& paths, const LineDrawStyle& style) {
    std::vector<LineVertex> vertices;
    for (const ScreenPath& path : paths) {
        const float faint = path.visible || style.hidden != HiddenLines::Faint ? 1.0f : 0.25f;
        const float dashed = !path.visible && style.hidden == HiddenLines::Dashed ? 1.0f : 0.0f;
        const float width = path.visible || style.hidden == HiddenLines::None ? style.width
                                                                              : std::max(1.0f, 0.6f * style.width);
        // Draw through the samples that matter: a sample is skipped while the polyline from
        // the last kept one stays within 0.25 px of a straight line and the alpha barely
        // changes. Visibility samples every δ px are far denser than straight runs need,
        // and lavapipe pays per triangle.
        const std::vector<size_t> kept = simplify(path);
        const size_t n = kept.size();
        const size_t segments = path.closed ? n : n - 1;
        for (size_t i = 0; i < segments; ++i) {
            const ScreenSample& a = path.samples[kept[i]];
            const ScreenSample& b = path.samples[kept[(i + 1) % n]];
            glm::vec2 dir = b.pixel - a.pixel;
            const float length = glm::length(dir);
            if (length < 1e-6f) continue;
            dir /= length;
            const glm::vec2 side = glm::vec2(-dir.y, dir.x) * (0.5f * width);
            const glm::vec2 cap = dir * (0.5f * width);
            const float alpha_a = style.alpha * (style.fade ? a.alpha : 1.0f) * faint;
            const float alpha_b = style.alpha * (style.fade ? b.alpha : 1.0f) * faint;
            const glm::vec4 ca(style.color, alpha_a), cb(style.color, alpha_b);
            const LineVertex v0{a.pixel - cap + side, ca, {a.s, dashed}};
            const LineVertex v1{a.pixel - cap - side, ca, {a.s, dashed}};
            const LineVertex v2{b.pixel + cap + side, cb, {a.s + length, dashed}};
            const LineVertex v3{b.pixel + cap - side, cb, {a.s + length, dashed}};
            vertices.insert(vertices.end(), {v0, v1, v2, v2, v1, v3});
        }
    }
    return vertices;
}

}  // namespace

LinePass::LinePass(const Context& ctx, VkFormat color_format)
    : pipeline_(ctx, {.vertex_spirv = LW_SPIRV(lines_draw_vert_spv),
                      .fragment_spirv = LW_SPIRV(lines_draw_frag_spv),
                      .vertex_stride = sizeof(LineVertex),
                      .attributes = {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
                                     {.location = 1, .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                      .offset = offsetof(LineVertex, color)},
                                     {.location = 2, .format = VK_FORMAT_R32G32_SFLOAT,
                                      .offset = offsetof(LineVertex, arc)}},
                      .color_format = color_format,
                      .depth_format = VK_FORMAT_UNDEFINED,
                      .depth_test = false,
                      .depth_write = false,
                      .blend = BlendMode::Alpha,
                      .push_constant_size = sizeof(LineDrawPush),
                      .name = "lines draw"}) {}

Buffer LinePass::record(const Context& ctx, VkCommandBuffer cmd, RenderTarget& target,
                        const std::vector<ScreenPath>& paths, const LineDrawStyle& style) const {
    const std::vector<LineVertex> vertices = build_quads(paths, style);
    if (vertices.empty()) return Buffer();
    Buffer buffer = upload_vertices(ctx, std::as_bytes(std::span(vertices)), "line quads");
    target.begin_overlay(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    const LineDrawPush push{{float(target.width), float(target.height)}, 8.0f, 0.0f};
    pipeline_.draw(cmd, buffer, static_cast<uint32_t>(vertices.size()), &push, sizeof(push));
    target.end_overlay(cmd);
    return buffer;
}

}  // namespace lw
