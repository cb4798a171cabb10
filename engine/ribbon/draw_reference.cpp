#include "ribbon/draw_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "ribbon/triangle_raster.h"

namespace lw {

PieceFrame piece_frame(const Ribbon& ribbon, size_t piece, glm::ivec2 u) {
    const RibbonPiece& p = ribbon.pieces[piece];
    const glm::vec2 left(left_edge_in_exemplar(p, ribbon.scale));
    const glm::vec2 A(float(u.x) + 0.5f, float(u.y)), B = A + left;
    const glm::vec2 D = ribbon.to_exemplar(piece, u, p.top_right), Cq = ribbon.to_exemplar(piece, u, p.bottom_right);
    return {.top_left = A, .top_right = D, .top_edge = D - A, .bottom_edge = Cq - B, .right_edge = Cq - D, .left_edge = left};
}

namespace {

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// Unpacked RGBA in [0, 1], transparent black outside E (the shader's fetch).
glm::vec4 fetch(const Exemplar& e, glm::ivec2 t) {
    const uint32_t texel = e.at(t.x, t.y);
    return glm::vec4(float(texel & 0xffu), float((texel >> 8) & 0xffu), float((texel >> 16) & 0xffu),
                     float(texel >> 24)) /
           255.0f;
}

glm::vec4 premultiplied(glm::vec4 c) { return {glm::vec3(c) * c.a, c.a}; }

// The exemplar read at e as the fragment stage reads it: the texel under e + (½, 0) on a
// forbidden pixel, else bilinear with premultiplied alpha, returned straight.
glm::vec4 sample(const Exemplar& exemplar, glm::vec2 e, bool forbidden_pixel) {
    const glm::vec2 q = e + glm::vec2(0.5f, 0.0f);
    if (forbidden_pixel) return fetch(exemplar, glm::ivec2(glm::floor(q)));
    const glm::vec2 g = q - 0.5f;
    const glm::ivec2 i0(glm::floor(g));
    const glm::vec2 f = g - glm::vec2(i0);
    const glm::vec4 c = glm::mix(glm::mix(premultiplied(fetch(exemplar, i0)), premultiplied(fetch(exemplar, i0 + glm::ivec2(1, 0))), f.x),
                                 glm::mix(premultiplied(fetch(exemplar, i0 + glm::ivec2(0, 1))),
                                          premultiplied(fetch(exemplar, i0 + glm::ivec2(1, 1))), f.x),
                                 f.y);
    return c.a > 0.0f ? glm::vec4(glm::vec3(c) / c.a, c.a) : glm::vec4(0.0f);
}

// A float colour channel into an 8-bit UNORM attachment (round to nearest).
uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

glm::vec2 stitch_deformation(glm::vec2 p, const PieceFrame& frame, std::span<const int32_t> remap) {
    const glm::vec2 A = frame.top_left, D = frame.top_right, w = frame.right_edge, l = frame.left_edge;
    const int C = int(remap.size());
    const glm::vec2 d = glm::mix(frame.top_edge, frame.bottom_edge, std::clamp(glm::dot(p - A, l) / glm::dot(l, l), 0.0f, 1.0f));
    const float across = cross2(d, l);  // d's component across the left edge, times |l|
    if (std::abs(across) < 1e-4f * glm::length(l)) return glm::vec2(0.0f);
    // p + a·d = D + m·w
    const float det = w.x * d.y - d.x * w.y;
    if (std::abs(det) < 1e-6f) return glm::vec2(0.0f);
    const glm::vec2 q = D - p;
    const float a = (w.x * q.y - q.x * w.y) / det;
    const float m = (d.x * q.y - q.x * d.y) / det;
    const float x = cross2(p - A, l) / across;  // p − x·d lies on the left edge
    if (x + a <= 1e-6f) return glm::vec2(0.0f);
    const float ratio = std::clamp(x / (x + a), 0.0f, 1.0f);
    const float i = std::clamp(m * float(C) - 0.5f, 0.0f, float(C - 1));
    const int k0 = int(std::floor(i)), k1 = std::min(k0 + 1, C - 1);
    const float delta = glm::mix(float(remap[size_t(k0)] - k0), float(remap[size_t(k1)] - k1), i - float(k0));
    return ratio * delta * (w / float(C));
}

ImageRGBA8 draw_ribbon_reference(const Ribbon& ribbon, const Exemplar& exemplar, const std::vector<glm::ivec2>& positions,
                                 const std::vector<std::vector<int32_t>>* remaps, const ForbiddenMask* forbidden,
                                 int width, int height) {
    if (positions.size() < ribbon.pieces.size()) throw Error("ribbon draw: fewer positions than pieces");
    if (forbidden && (forbidden->width != width || forbidden->height != height))
        throw Error("ribbon draw: the forbidden mask does not match the canvas");
    ImageRGBA8 image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 0)};
    for (size_t i = 0; i < ribbon.pieces.size(); ++i) {
        const RibbonPiece& p = ribbon.pieces[i];
        const glm::ivec2 u = positions[i];
        const PieceFrame frame = piece_frame(ribbon, i, u);
        // Seam i + 1 deforms piece i's right side.
        const std::span<const int32_t> remap =
            remaps && i < remaps->size() ? std::span<const int32_t>((*remaps)[i]) : std::span<const int32_t>();
        if (!remap.empty() && remap.size() != size_t(ribbon.samples))  // the shader reads C = ribbon.samples
            throw Error("ribbon draw: seam " + std::to_string(i + 1) + " has " + std::to_string(remap.size()) +
                        " stitching samples, the ribbon " + std::to_string(ribbon.samples));
        auto shade = [&](int x, int y) {
            const bool forbidden_pixel = forbidden && forbidden->at(x, y);
            glm::vec2 e = ribbon.to_exemplar(i, u, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
            if (!remap.empty() && !forbidden_pixel) e += stitch_deformation(e, frame, remap);
            const glm::vec4 c = sample(exemplar, e, forbidden_pixel);
            uint8_t* out = image.at(x, y);
            for (int k = 0; k < 4; ++k) out[k] = unorm8(c[k]);
        };
        for_each_covered_pixel({glm::dvec2(p.top_left), glm::dvec2(p.bottom_left), glm::dvec2(p.bottom_right)}, width,
                               height, shade);
        for_each_covered_pixel({glm::dvec2(p.top_left), glm::dvec2(p.bottom_right), glm::dvec2(p.top_right)}, width,
                               height, shade);
    }
    return image;
}

}  // namespace lw
