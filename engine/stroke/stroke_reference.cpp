#include "stroke/stroke_reference.h"

namespace lw {

EdgeGradients edge_gradients(const StrokeVertex& a, const StrokeVertex& b, const StrokeVertex& c) {
    // f(p) = f(a) + ∇f·(p − a): the differences along the two edges give ∇f.
    const glm::mat2 edges_t = glm::transpose(glm::mat2(b.pixel - a.pixel, c.pixel - a.pixel));
    if (glm::determinant(edges_t) == 0.0f) return {};
    const glm::mat2 solve = glm::inverse(edges_t);
    auto gradient = [&](int k) { return solve * glm::vec2(b.edge[k] - a.edge[k], c.edge[k] - a.edge[k]); };
    const glm::vec2 gx = gradient(0), gy = gradient(1), gz = gradient(2);
    // dxy_dx holds d(edge.x)/dx and d(edge.y)/dx, as dFdx(edge.xy) does.
    return {.dxy_dx = {gx.x, gy.x}, .dxy_dy = {gx.y, gy.y}, .dz = gz};
}

std::vector<float> stroke_ink_reference(const std::vector<StrokeVertex>& triangles, int width, int height,
                                        InkBlend blend) {
    // Over: what is left of the white, 1 − ink, multiplied triangle by triangle. Once: the
    // largest ink.
    std::vector<float> value(size_t(width) * height, blend == InkBlend::Over ? 1.0f : 0.0f);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const StrokeVertex &a = triangles[t], &b = triangles[t + 1], &c = triangles[t + 2];
        const EdgeGradients g = edge_gradients(a, b, c);
        for_each_point_inside(a, b, c, width, height, 1, [&](int x, int y, const glm::vec4& edge, float alpha) {
            const float ink = std::clamp(alpha, 0.0f, 1.0f) * stroke_coverage(edge, g.dxy_dx, g.dxy_dy, g.dz);
            float& v = value[size_t(y) * width + x];
            v = blend == InkBlend::Over ? v * (1.0f - ink) : std::max(v, ink);
        });
    }
    if (blend == InkBlend::Over)
        for (float& v : value) v = 1.0f - v;
    return value;
}

}  // namespace lw
