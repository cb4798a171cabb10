// engine/stroke/stroke_reference.h — plain C++ reference for what the stroke and line passes
// draw: their triangles rasterized at pixel centres with the shaders' coverage.
//
// Input:  `StrokeVertex` triangles (stroke_geometry.h) in drawing order and an image size.
// Output: per pixel, the ink of black strokes composited `over` white with a solid texture:
//         1 − Π(1 − αᵢ·coverageᵢ) over the triangles covering the pixel centre (the GPU's
//         alpha blending, up to its 8-bit rounding and its edge tie-breaking rules). The
//         coverage is `stroke_coverage` with the gradients of the triangle's (linear)
//         coverage coordinates, which the shaders take as screen derivatives. Drawn once (a
//         translucent line set through a coverage layer, gpu/coverage_layer.h) the ink is
//         instead the largest αᵢ·coverageᵢ, up to the layer's 8-bit rounding as well.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "stroke/stroke_geometry.h"

namespace lw {

// d/dx and d/dy of a triangle's coverage coordinates (xy and z), which are linear on it.
struct EdgeGradients {
    glm::vec2 dxy_dx{0.0f}, dxy_dy{0.0f}, dz{0.0f};
};
[[nodiscard]] EdgeGradients edge_gradients(const StrokeVertex& a, const StrokeVertex& b, const StrokeVertex& c);

// Calls `visit(ix, iy, edge, alpha)` for every point ((ix + ½)/sub, (iy + ½)/sub) of a
// `sub`×`sub` grid per pixel of a width × height image (sub = 1: the pixel centres) that lies
// inside the triangle, with the coverage coordinates and alpha interpolated there. A point on
// an edge belongs to the triangle when the edge is a top or left one (Vulkan's tie-breaking
// rule), so that triangles sharing an edge never both draw a pixel.
template <class Visit>
void for_each_point_inside(const StrokeVertex& a, const StrokeVertex& b, const StrokeVertex& c, int width, int height,
                           int sub, Visit&& visit) {
    auto side = [](glm::vec2 p, glm::vec2 q, glm::vec2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    const float area = side(a.pixel, b.pixel, c.pixel);
    if (area == 0.0f) return;
    // The edges run with the inside on their positive side; in y-down pixels a top edge then
    // runs in +x and a left edge upwards.
    const float sign = area > 0.0f ? 1.0f : -1.0f;
    const glm::vec2 e0 = (c.pixel - b.pixel) * sign, e1 = (a.pixel - c.pixel) * sign, e2 = (b.pixel - a.pixel) * sign;
    auto owns = [](float w, glm::vec2 e) { return w > 0.0f || (w == 0.0f && (e.y < 0.0f || (e.y == 0.0f && e.x > 0.0f))); };
    const float lo_x = std::min({a.pixel.x, b.pixel.x, c.pixel.x}), hi_x = std::max({a.pixel.x, b.pixel.x, c.pixel.x});
    const float lo_y = std::min({a.pixel.y, b.pixel.y, c.pixel.y}), hi_y = std::max({a.pixel.y, b.pixel.y, c.pixel.y});
    const int x0 = std::max(0, int(std::floor(lo_x * float(sub)))), x1 = std::min(width * sub - 1, int(std::ceil(hi_x * float(sub))));
    const int y0 = std::max(0, int(std::floor(lo_y * float(sub)))), y1 = std::min(height * sub - 1, int(std::ceil(hi_y * float(sub))));
    for (int iy = y0; iy <= y1; ++iy)
        for (int ix = x0; ix <= x1; ++ix) {
            const glm::vec2 p((float(ix) + 0.5f) / float(sub), (float(iy) + 0.5f) / float(sub));
            const float w0 = side(b.pixel, c.pixel, p) / area, w1 = side(c.pixel, a.pixel, p) / area;
            const float w2 = side(a.pixel, b.pixel, p) / area;
            if (!owns(w0, e0) || !owns(w1, e1) || !owns(w2, e2)) continue;
            const float sum = w0 + w1 + w2;
            visit(ix, iy, (w0 * a.edge + w1 * b.edge + w2 * c.edge) / sum,
                  (w0 * a.color.a + w1 * b.color.a + w2 * c.color.a) / sum);
        }
}

// How overlapping triangles combine: Over, blended one after the other as the passes draw
// over the frame; Once, the union a coverage layer draws (the largest ink).
enum class InkBlend { Over, Once };

[[nodiscard]] std::vector<float> stroke_ink_reference(const std::vector<StrokeVertex>& triangles, int width, int height,
                                                      InkBlend blend = InkBlend::Over);

}  // namespace lw
