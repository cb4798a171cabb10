#include "stroke/stroke_geometry.h"

#include <algorithm>

namespace lw {

namespace {

glm::vec2 unit_normal(glm::vec2 a, glm::vec2 b) {
    const glm::vec2 d = b - a;
    const float len = glm::length(d);
    return len > 0.0f ? glm::vec2(-d.y, d.x) / len : glm::vec2(0.0f);
}

}  // namespace

void append_stroke(const ScreenPath& path, const StrokeParams& params, std::vector<StrokeVertex>& out) {
    const auto& s = path.samples;
    const size_t n = s.size();
    if (n < 2) return;
    const bool closed = path.closed;
    const float length = s.back().s - s.front().s;

    // Offset of each sample: the mitre of its two segments (one at open ends).
    std::vector<glm::vec2> left(n), right(n);
    for (size_t i = 0; i < n; ++i) {
        const bool has_prev = i > 0 || closed, has_next = i + 1 < n || closed;
        const glm::vec2 n_prev = has_prev ? unit_normal(s[(i + n - 1) % n].pixel, s[i].pixel) : glm::vec2(0.0f);
        const glm::vec2 n_next = has_next ? unit_normal(s[i].pixel, s[(i + 1) % n].pixel) : glm::vec2(0.0f);
        glm::vec2 miter = n_prev + n_next;
        const float miter_len = glm::length(miter);
        glm::vec2 offset(0.0f);
        float half = 0.5f * params.width * s[i].width;
        if (params.taper_px > 0.0f && !closed) {
            const float from_end = std::min(s[i].s - s.front().s, s.back().s - s[i].s);
            half *= std::clamp(from_end / std::min(params.taper_px, 0.5f * std::max(length, 1e-3f)), 0.15f, 1.0f);
        }
        if (miter_len > 1e-6f) {
            miter /= miter_len;
            const glm::vec2 reference = glm::length(n_next) > 0.0f ? n_next : n_prev;
            const float cos_half = std::max(glm::dot(miter, reference), 1e-3f);
            offset = miter * std::min(half / cos_half, params.mitre_limit * half);
        }
        left[i] = s[i].pixel + offset;
        right[i] = s[i].pixel - offset;
    }

    auto vertex = [&](size_t i, bool is_left, float u) {
        return StrokeVertex{is_left ? left[i] : right[i], glm::vec3(u, is_left ? 0.0f : 1.0f, params.fold.w),
                            glm::vec4(params.color, s[i].alpha)};
    };
    const size_t segments = closed ? n : n - 1;
    for (size_t i = 0; i < segments; ++i) {
        const size_t j = (i + 1) % n;
        const float ui = params.fold.scale * (params.rho * s[i].s + params.phi);
        // The closing segment continues the arclength past the last sample.
        const float sj = j == 0 ? s[i].s + glm::length(s[0].pixel - s[i].pixel) : s[j].s;
        const float uj = params.fold.scale * (params.rho * sj + params.phi);
        const StrokeVertex a = vertex(i, true, ui), b = vertex(i, false, ui);
        const StrokeVertex c = vertex(j, true, uj), d = vertex(j, false, uj);
        out.insert(out.end(), {a, b, c, c, b, d});
    }
}

}  // namespace lw
