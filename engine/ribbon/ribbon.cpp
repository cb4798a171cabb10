#include "ribbon/ribbon.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/image.h"
#include "core/text.h"

namespace lw {

glm::vec2 Ribbon::to_exemplar(size_t piece, glm::ivec2 u, glm::vec2 p) const {
    const RibbonPiece& q = pieces[piece];
    const glm::vec2 d = p - q.top_left;
    const glm::vec2 t = q.chord;
    // R = [[t.x, t.y], [−t.y, t.x]] takes the chord t to +x and its normal to +y (down).
    const glm::vec2 rotated(t.x * d.x + t.y * d.y, -t.y * d.x + t.x * d.y);
    return glm::vec2(float(u.x) + 0.5f, float(u.y)) + (scale / width) * rotated;
}

glm::dvec2 left_edge_in_exemplar(const RibbonPiece& piece, double scale) {
    if (piece.chord == piece.tangent) return {0.0, scale};
    // The left edge runs along −n = (−t.y, t.x); R (above) takes it to (t × c, t · c).
    const glm::dvec2 t(piece.tangent), c(piece.chord);
    return scale * glm::dvec2(t.x * c.y - t.y * c.x, t.x * c.x + t.y * c.y);
}

glm::vec2 Ribbon::min_corner() const {
    glm::vec2 lo(INFINITY);
    for (const RibbonPiece& p : pieces)
        lo = glm::min(glm::min(lo, glm::min(p.top_left, p.bottom_left)), glm::min(p.top_right, p.bottom_right));
    return lo;
}

glm::vec2 Ribbon::max_corner() const {
    glm::vec2 hi(-INFINITY);
    for (const RibbonPiece& p : pieces)
        hi = glm::max(glm::max(hi, glm::max(p.top_left, p.bottom_left)), glm::max(p.top_right, p.bottom_right));
    return hi;
}

glm::ivec2 default_ribbon_size(const Ribbon& ribbon, glm::vec2 page, const std::string& curve_file) {
    const glm::vec2 lo = ribbon.min_corner(), hi = ribbon.max_corner();
    // The image starts at (0, 0): a ribbon wholly at negative coordinates gave a 1x1 blank one.
    if (!(hi.x > 0.0f && hi.y > 0.0f))
        throw Error(curve_file + ": the ribbon (x " + std::to_string(int(std::floor(lo.x))) + " to " +
                    std::to_string(int(std::ceil(hi.x))) + ", y " + std::to_string(int(std::floor(lo.y))) + " to " +
                    std::to_string(int(std::ceil(hi.y))) +
                    ") lies wholly left of or above the image, whose (0, 0) is the top-left corner: curves are in "
                    "output pixels");
    const glm::ivec2 size = glm::max(glm::ivec2(std::max(1, int(std::ceil(hi.x)) + 2), std::max(1, int(std::ceil(hi.y)) + 2)),
                                     glm::ivec2(int(std::ceil(page.x)), int(std::ceil(page.y))));
    if (size.x > kLargestImageSide || size.y > kLargestImageSide)
        throw Error(curve_file + ": the curve (or its page) reaches past " + std::to_string(kLargestImageSide) +
                    " pixels; give the output's size");
    return size;
}

void check_ribbon_in_image(const Ribbon& ribbon, int width, int height) {
    const bool meets = std::any_of(ribbon.pieces.begin(), ribbon.pieces.end(), [&](const RibbonPiece& p) {
        const glm::vec2 a = glm::min(glm::min(p.top_left, p.top_right), glm::min(p.bottom_left, p.bottom_right));
        const glm::vec2 b = glm::max(glm::max(p.top_left, p.top_right), glm::max(p.bottom_left, p.bottom_right));
        return b.x > 0.0f && b.y > 0.0f && a.x < float(width) && a.y < float(height);
    });
    if (meets || ribbon.pieces.empty()) return;
    const glm::vec2 lo = ribbon.min_corner(), hi = ribbon.max_corner();
    throw ParameterError("ribbon size", " " + std::to_string(width) + "x" + std::to_string(height) +
                                            ": nothing of the ribbon (x " + std::to_string(int(std::floor(lo.x))) +
                                            " to " + std::to_string(int(std::ceil(hi.x))) + ", y " +
                                            std::to_string(int(std::floor(lo.y))) + " to " +
                                            std::to_string(int(std::ceil(hi.y))) +
                                            ", output pixels) falls inside the image");
}

Ribbon build_ribbon(const ArclengthCurve& curve, const RibbonParams& params) {
    if (!(params.width > 0.0f) || !std::isfinite(params.width))
        throw ParameterError("ribbon width", ": the ribbon width b must be a positive number of pixels");
    if (params.width > float(kLargestImageSide))  // (number_text: int() of a width past 2^31 was undefined)
        throw ParameterError("ribbon width", ": " + number_text(params.width) + " px: a ribbon wider than the largest image (" +
                                                 std::to_string(kLargestImageSide) + " px)");
    if (!(params.piece > 0.0f) || !std::isfinite(params.piece))
        throw ParameterError("ribbon piece", ": the piece length δ must be a positive number of pixels");
    if (!(params.scale > 0.0f) || !std::isfinite(params.scale))
        throw ParameterError("ribbon scale", ": s must be a positive number of exemplar pixels");
    // Pieces under an output pixel along the curve are cuts no pixel shows apart, and their
    // count is the DP's rows: --piece 0.01 ran 64,224 rows for minutes.
    if (params.piece < 1.0f)
        throw ParameterError("ribbon piece", ": " + number_text(params.piece) +
                                                 " is under one output pixel along the curve");
    if (params.scale > 4096.0f) throw ParameterError("ribbon scale", ": at most 4096 exemplar pixels across the ribbon");
    // Under one exemplar pixel across the ribbon the DP compares sub-pixel slivers (--scale 0.1
    // ran for half a minute and cut every piece).
    if (params.scale < 1.0f)
        throw ParameterError("ribbon scale", ": " + number_text(params.scale) +
                                                 " is under one exemplar pixel across the ribbon");

    const float length = curve.length();
    const float delta = params.piece;
    // x_0 .. x_N (see the header for the remainder rule).
    std::vector<float> xs;
    const auto full = static_cast<long>(std::floor(length / delta));
    if (full > 100000) throw ParameterError("ribbon piece", ": " + std::to_string(full) + " pieces; at most 100000");
    for (long i = 0; i <= full; ++i) xs.push_back(float(i) * delta);
    const float remainder = length - xs.back();
    if (xs.size() == 1 || remainder > 0.25f * delta)
        xs.push_back(length);
    else
        xs.back() = length;

    // Tangents from a chord of ±δ/2 (at least 1 px): smooth over a piece, exact on circles.
    const float h = std::max(1.0f, 0.5f * delta);
    const float half = 0.5f * params.width;
    std::vector<glm::vec2> centre(xs.size()), top(xs.size()), bottom(xs.size()), tangent(xs.size());
    for (size_t i = 0; i < xs.size(); ++i) {
        const glm::vec2 c = curve.point_at(xs[i]);
        const glm::vec2 t = curve.tangent_at(xs[i], h);
        const glm::vec2 n(t.y, -t.x);
        centre[i] = c;
        top[i] = c + half * n;
        bottom[i] = c - half * n;
        tangent[i] = t;
    }
    if (curve.closed()) {  // the last right edge is exactly the first left edge
        centre.back() = centre.front();
        top.back() = top.front();
        bottom.back() = bottom.front();
    }

    Ribbon ribbon;
    ribbon.closed = curve.closed();
    ribbon.width = params.width;
    ribbon.scale = params.scale;
    ribbon.samples = ribbon_edge_samples(params.scale);
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        // The chord between the middles of the two edges (the header says why); the tangent
        // where the curve does not turn over the piece, so that straight ribbons stay exact.
        glm::vec2 chord = centre[i + 1] - centre[i];
        const float span = glm::length(chord);
        chord = span > 0.0f ? chord / span : tangent[i];
        if (std::abs(tangent[i].x * chord.y - tangent[i].y * chord.x) < 1e-6f && glm::dot(tangent[i], chord) > 0.0f)
            chord = tangent[i];
        ribbon.pieces.push_back({top[i], bottom[i], bottom[i + 1], top[i + 1], tangent[i], chord});
    }
    if (ribbon.closed && ribbon.pieces.size() < 2)
        throw ParameterError("ribbon piece", ": a closed curve of length " + std::to_string(int(std::lround(length))) +
                                                 " px needs at least two pieces; use a shorter piece length");
    return ribbon;
}

}  // namespace lw
