// engine/ribbon/triangle_raster.h — which pixel centres a triangle covers, in plain C++: the
// references of the ribbon's two drawing passes (avoidance.h's coverage counts,
// draw_reference.h's pattern) walk the pieces' triangles with it.
//
// Input:  a triangle in canvas pixels, the canvas size.
// Output: a call f(x, y) for every pixel whose centre (x + ½, y + ½) the triangle covers, a
//         pixel centre on an edge shared by two triangles going to exactly one of them (edge
//         functions evaluated with the endpoints in a canonical order, and a tie rule on the
//         edge's direction).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <glm/glm.hpp>

namespace lw {

// Edge function of a → b at p, evaluated with the endpoints in a canonical order so that
// the two triangles sharing an edge get exactly opposite values (no pixel counted twice or
// lost on the shared edge).
inline double edge_function(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    const bool swapped = (b.x < a.x) || (b.x == a.x && b.y < a.y);
    if (swapped) std::swap(a, b);
    const double w = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    return swapped ? -w : w;
}

template <class F>
void for_each_covered_pixel(std::array<glm::dvec2, 3> v, int width, int height, F&& f) {
    const double area = edge_function(v[0], v[1], v[2]);
    if (area == 0.0) return;
    if (area < 0.0) std::swap(v[1], v[2]);  // interior where every edge function is positive
    const double x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
    const double y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
    const int px0 = std::max(0, int(std::floor(x0))), px1 = std::min(width - 1, int(std::ceil(x1)));
    const int py0 = std::max(0, int(std::floor(y0))), py1 = std::min(height - 1, int(std::ceil(y1)));
    for (int py = py0; py <= py1; ++py)
        for (int px = px0; px <= px1; ++px) {
            const glm::dvec2 p(px + 0.5, py + 0.5);
            bool inside = true;
            for (int e = 0; e < 3 && inside; ++e) {
                const glm::dvec2 a = v[size_t(e)], b = v[size_t((e + 1) % 3)];
                const double w = edge_function(a, b, p);
                // On the edge: the pixel belongs to exactly one of the two directions of it.
                const glm::dvec2 d = b - a;
                inside = w > 0.0 || (w == 0.0 && (d.y < 0.0 || (d.y == 0.0 && d.x > 0.0)));
            }
            if (inside) f(px, py);
        }
}

}  // namespace lw
