#include "ribbon/problem.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/parallel.h"

namespace lw {

namespace {

// Sorted, unique.
void unique_sorted(std::vector<glm::ivec2>& v) {
    auto less = [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; };
    std::sort(v.begin(), v.end(), less);
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

glm::ivec2 floor_texel(glm::dvec2 e) { return {int(std::floor(e.x)), int(std::floor(e.y))}; }

// Point in triangle within `eps` (distance units of the triangle's space), either winding.
bool inside_triangle(glm::dvec2 p, const std::array<glm::dvec2, 3>& v, double eps) {
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (std::abs(area) < 1e-12) return false;
    const double sign = area > 0.0 ? 1.0 : -1.0;
    for (int e = 0; e < 3; ++e) {
        const glm::dvec2 a = v[size_t(e)], b = v[size_t((e + 1) % 3)];
        const double len = glm::length(b - a);
        if (len == 0.0) return false;
        const double d = sign * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
        if (d < -eps) return false;
    }
    return true;
}

// Texels met along the segment a → b (steps of at most a quarter texel).
void segment_texels(glm::dvec2 a, glm::dvec2 b, std::vector<glm::ivec2>& out) {
    const int steps = std::max(1, int(std::ceil(glm::length(b - a) * 4.0)));
    for (int k = 0; k <= steps; ++k) out.push_back(floor_texel(a + (b - a) * (double(k) / steps)));
}

}  // namespace

PieceProbes piece_probes(const Ribbon& ribbon, size_t i, const ForbiddenMask* forbidden) {
    const RibbonPiece& piece = ribbon.pieces[i];
    const int C = ribbon.samples;
    const double s = ribbon.scale;
    auto e0 = [&](glm::vec2 p) { return glm::dvec2(ribbon.to_exemplar(i, {0, 0}, p)); };
    // The piece in E (u = 0): left edge exact (a column where the curve does not turn over
    // the piece, ribbon.h), right corners through the similarity.
    const glm::dvec2 A(0.5, 0.0), B = A + left_edge_in_exemplar(piece, s), Cq = e0(piece.bottom_right),
                     D = e0(piece.top_right);
    auto on_left = [&](double f) { return A + (B - A) * f; };
    auto on_right = [&](double f) { return D + (Cq - D) * f; };

    PieceProbes probes;
    for (int k = 0; k < C; ++k) {
        probes.left.push_back(floor_texel(on_left((k + 0.5) / C)));
        probes.right.push_back(floor_texel(on_right((k + 0.5) / C)));
    }
    // Top and bottom edges, through the first and last samples of the left and right edges.
    segment_texels(on_left(0.5 / C), on_right(0.5 / C), probes.top);
    segment_texels(on_left((C - 0.5) / C), on_right((C - 0.5) / C), probes.bottom);
    unique_sorted(probes.top);
    unique_sorted(probes.bottom);

    // Texel centres inside the piece's two triangles (as drawn), slightly conservative.
    const std::array<glm::dvec2, 3> t0{A, B, Cq}, t1{A, Cq, D};
    const glm::dvec2 lo = glm::min(glm::min(A, B), glm::min(Cq, D)), hi = glm::max(glm::max(A, B), glm::max(Cq, D));
    for (int y = int(std::floor(lo.y)) - 1; y <= int(std::ceil(hi.y)); ++y)
        for (int x = int(std::floor(lo.x)) - 1; x <= int(std::ceil(hi.x)); ++x) {
            const glm::dvec2 c(x + 0.5, y + 0.5);
            if (inside_triangle(c, t0, 1e-3) || inside_triangle(c, t1, 1e-3)) probes.interior.push_back({x, y});
        }
    probes.interior.insert(probes.interior.end(), probes.left.begin(), probes.left.end());
    unique_sorted(probes.interior);

    // Forbidden canvas pixels the piece draws: the texel each would show must be transparent.
    // The drawing interpolates exemplar coordinates on the GPU, so a coordinate within 2e-3 of
    // a texel border may round either way: both texels are checked. Pixel centres within
    // 0.02 px outside the triangles count too (the rasterizer snaps vertices to 1/256 px).
    if (forbidden && forbidden->count() > 0) {
        const std::array<glm::dvec2, 3> c0{glm::dvec2(piece.top_left), glm::dvec2(piece.bottom_left),
                                           glm::dvec2(piece.bottom_right)};
        const std::array<glm::dvec2, 3> c1{glm::dvec2(piece.top_left), glm::dvec2(piece.bottom_right),
                                           glm::dvec2(piece.top_right)};
        const glm::dvec2 plo = glm::min(glm::min(c0[0], c0[1]), glm::min(c0[2], c1[2]));
        const glm::dvec2 phi = glm::max(glm::max(c0[0], c0[1]), glm::max(c0[2], c1[2]));
        const int x0 = std::max(0, int(std::floor(plo.x)) - 1), x1 = std::min(forbidden->width - 1, int(std::ceil(phi.x)));
        const int y0 = std::max(0, int(std::floor(plo.y)) - 1), y1 = std::min(forbidden->height - 1, int(std::ceil(phi.y)));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px) {
                const glm::dvec2 c(px + 0.5, py + 0.5);
                if (!inside_triangle(c, c0, 0.02) && !inside_triangle(c, c1, 0.02)) continue;
                if (!forbidden->at(px, py)) continue;
                probes.touches_forbidden = true;
                const glm::dvec2 e = e0(glm::vec2(c)) + glm::dvec2(0.5, 0.0);  // as the drawing reads
                const double margin = 2e-3;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        probes.forbidden.push_back(floor_texel(e + glm::dvec2(dx, dy) * margin));
            }
        unique_sorted(probes.forbidden);
    }

    probes.min_dx = 0;
    probes.max_dx = 0;
    for (const auto* list : {&probes.left, &probes.right, &probes.top, &probes.bottom, &probes.interior})
        for (const glm::ivec2& o : *list) {
            probes.min_dx = std::min(probes.min_dx, o.x);
            probes.max_dx = std::max(probes.max_dx, o.x);
        }
    return probes;
}

glm::ivec2 pattern_band(const Exemplar& e) {
    glm::ivec2 band(e.height, -1);
    for (int y = 0; y < e.height; ++y)
        for (int x = 0; x < e.width; ++x)
            if (texel_opaque(e.at(x, y))) {
                band.x = std::min(band.x, y);
                band.y = std::max(band.y, y);
            }
    return band;
}

namespace {

int band_height(const Exemplar& exemplar) {
    const glm::ivec2 band = pattern_band(exemplar);
    return std::max(1, band.y - band.x + 1);
}

}  // namespace

float default_ribbon_scale(const Exemplar& exemplar) {
    const int height = band_height(exemplar);
    return float(height + 2 + std::max(2, int(std::lround(0.3 * height))));
}

std::optional<ScaleShortfall> scale_shortfall(const Exemplar& exemplar, float scale) {
    const int rows = band_height(exemplar);
    const double s = scale, C = ribbon_edge_samples(scale);
    const bool holds = C >= 1.0 && std::floor((C - 0.5) * s / C) - std::floor(0.5 * s / C) >= double(rows + 1);
    if (holds) return std::nullopt;
    return ScaleShortfall{.band_rows = rows, .least_scale = rows + 2, .default_scale = default_ribbon_scale(exemplar)};
}

DpProblem build_problem(const Exemplar& exemplar, const Ribbon& ribbon, const ForbiddenMask* forbidden) {
    DpProblem problem;
    problem.exemplar = &exemplar;
    problem.band = pattern_band(exemplar);
    problem.samples = ribbon.samples;
    problem.closed = ribbon.closed;
    problem.rows.resize(ribbon.pieces.size());
    parallel_for(ribbon.pieces.size(), 8, [&](size_t begin, size_t end, size_t) {
        for (size_t i = begin; i < end; ++i) problem.rows[i] = piece_probes(ribbon, i, forbidden);
    });
    // §1.5: the terminal piece represents the connection back to the first piece.
    if (ribbon.closed) problem.rows.push_back(problem.rows.front());
    return problem;
}

bool position_valid(const DpProblem& problem, size_t row, glm::ivec2 u, ValidityRule rule) {
    const Exemplar& e = *problem.exemplar;
    const PieceProbes& p = problem.rows[row];
    auto any_opaque = [&](const std::vector<glm::ivec2>& list) {
        for (const glm::ivec2& o : list)
            if (texel_opaque(e.at(u.x + o.x, u.y + o.y))) return true;
        return false;
    };
    // 4. inside E horizontally; 3. no opaque texel on a forbidden pixel
    if (u.x + p.min_dx < 0 || u.x + p.max_dx >= e.width) return false;
    if (any_opaque(p.forbidden)) return false;
    switch (rule) {
        case ValidityRule::Band:  // 1. and 2.
            for (const glm::ivec2& o : p.top)
                if (u.y + o.y >= problem.band.x) return false;
            for (const glm::ivec2& o : p.bottom)
                if (u.y + o.y <= problem.band.y) return false;
            return any_opaque(p.interior);
        case ValidityRule::Empty:
            return p.touches_forbidden && u == glm::ivec2(-p.min_dx, -problem.samples);
        case ValidityRule::Edges:
            return !any_opaque(p.top) && !any_opaque(p.bottom) && any_opaque(p.interior);
        case ValidityRule::Any:
            return true;
    }
    return false;
}

}  // namespace lw
