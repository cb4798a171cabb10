#include "ribbon/avoidance.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace lw {

namespace {

// Edge function of a → b at p, evaluated with the endpoints in a canonical order so that
// the two triangles sharing an edge get exactly opposite values (no pixel counted twice or
// lost on the shared edge).
double edge_function(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    const bool swapped = (b.x < a.x) || (b.x == a.x && b.y < a.y);
    if (swapped) std::swap(a, b);
    const double w = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    return swapped ? -w : w;
}

// Adds 1 to the count of every pixel whose centre the triangle covers.
void rasterize(std::array<glm::dvec2, 3> v, int width, int height, std::vector<uint8_t>& counts) {
    double area = edge_function(v[0], v[1], v[2]);
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
            if (inside) {
                uint8_t& c = counts[size_t(py) * size_t(width) + size_t(px)];
                if (c < 255) ++c;
            }
        }
}

}  // namespace

size_t ForbiddenMask::count() const {
    return size_t(std::count_if(pixels.begin(), pixels.end(), [](uint8_t p) { return p != 0; }));
}

std::vector<uint8_t> coverage_counts_reference(const Ribbon& ribbon, int width, int height) {
    std::vector<uint8_t> counts(size_t(width) * size_t(height), 0);
    for (const RibbonPiece& p : ribbon.pieces) {
        rasterize({glm::dvec2(p.top_left), glm::dvec2(p.bottom_left), glm::dvec2(p.bottom_right)}, width, height,
                  counts);
        rasterize({glm::dvec2(p.top_left), glm::dvec2(p.bottom_right), glm::dvec2(p.top_right)}, width, height,
                  counts);
    }
    return counts;
}

ForbiddenMask avoidance_map_reference(const Ribbon& ribbon, int width, int height) {
    const std::vector<uint8_t> counts = coverage_counts_reference(ribbon, width, height);
    ForbiddenMask mask{width, height, std::vector<uint8_t>(counts.size())};
    for (size_t i = 0; i < counts.size(); ++i) mask.pixels[i] = counts[i] > 1 ? 1 : 0;
    return mask;
}

ForbiddenMask forbidden_from_image(const ImageRGBA8& image) {
    ForbiddenMask mask{image.width, image.height, std::vector<uint8_t>(size_t(image.width) * size_t(image.height))};
    for (size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = image.pixels[i * 4 + 3] >= 128 ? 1 : 0;
    return mask;
}

void merge_forbidden(ForbiddenMask& into, const ForbiddenMask& other) {
    if (into.width != other.width || into.height != other.height)
        throw Error("the avoidance map is " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                    " but the canvas is " + std::to_string(into.width) + "x" + std::to_string(into.height));
    for (size_t i = 0; i < into.pixels.size(); ++i) into.pixels[i] = into.pixels[i] | other.pixels[i];
}

}  // namespace lw
