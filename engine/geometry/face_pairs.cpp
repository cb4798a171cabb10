// CGAL's box search and triangle predicate (compiled with -frounding-math, as its interval
// filters need, and without GMP: exact fallbacks use Boost.Multiprecision).
#include "geometry/face_pairs.h"

#include <cmath>
#include <cstddef>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

namespace lw {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
// Boxes of floats (the positions are floats, so their bounds are exact) named by a pointer to
// their face: 32 bytes, which the search sorts and swaps a great deal.
using Box = CGAL::Box_intersection_d::Box_with_handle_d<float, 3, const glm::uvec3*>;

// Below this many boxes the search compares all pairs instead of splitting further (CGAL's
// default is 10). Measured on two crossing copies of LeePerrySmith subdivided once (141k
// faces): 10 → 409 ms, 100 → 338, 1000 → 240, 5000 → 180, 20000 → 263; on two of
// FlightHelmet (189k): 10 → 964 ms, 5000 → 606, 20000 → 779 (docs/BENCHMARKS.md).
constexpr std::ptrdiff_t kCutoff = 5000;

Point point(const glm::vec3& p) { return Point(p.x, p.y, p.z); }

bool share_vertex(const glm::uvec3& f, const glm::uvec3& g) {
    for (int i = 0; i < 3; ++i)
        if (f[i] == g.x || f[i] == g.y || f[i] == g.z) return true;
    return false;
}

Kernel::Triangle_3 triangle(const WeldedMesh& m, uint32_t f) {
    return {point(m.positions[m.faces[f][0]]), point(m.positions[m.faces[f][1]]), point(m.positions[m.faces[f][2]])};
}

}  // namespace

void for_each_box_pair(const WeldedMesh& m, const std::function<void(uint32_t, uint32_t)>& visit, bool neighbours) {
    // A box per face that is a triangle: a degenerate face crosses nothing, and testing it
    // once here spares a test per pair it is in (CGAL's exact collinearity test, a tenth of
    // the intersection lines' time when done per pair).
    std::vector<Box> boxes;
    boxes.reserve(m.faces.size());
    for (uint32_t f = 0; f < m.faces.size(); ++f) {
        const glm::vec3 a = m.positions[m.faces[f].x], b = m.positions[m.faces[f].y], c = m.positions[m.faces[f].z];
        // (A corner at infinity or NaN, from a broken pose, would send CGAL's exact
        // fallback into numbers it cannot represent: such a face crosses nothing.)
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) continue;
        if (CGAL::collinear(point(a), point(b), point(c))) continue;
        glm::vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
        boxes.emplace_back(&lo.x, &hi.x, &m.faces[f]);
    }
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        const auto x_face = uint32_t(x.handle() - m.faces.data()), y_face = uint32_t(y.handle() - m.faces.data());
        const uint32_t a = std::min(x_face, y_face), b = std::max(x_face, y_face);
        if (neighbours || !share_vertex(m.faces[a], m.faces[b])) visit(a, b);
    }, kCutoff);
}

bool triangles_meet(const WeldedMesh& m, uint32_t a, uint32_t b) {
    const glm::uvec3 f = m.faces[a], g = m.faces[b];
    int shared = 0, fi = -1, gi = -1;  // with one shared corner: where it is in each face
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (f[i] == g[j]) ++shared, fi = i, gi = j;
    if (shared == 0) return CGAL::do_intersect(triangle(m, a), triangle(m, b));
    if (shared == 3) return true;  // the same corners: the same triangle, either way round
    const auto p = [&](uint32_t v) { return point(m.positions[v]); };
    if (shared == 2) {
        int fo = 0, go = 0;  // the corner of each face off the shared edge
        while (f[fo] == g[0] || f[fo] == g[1] || f[fo] == g[2]) ++fo;
        while (g[go] == f[0] || g[go] == f[1] || g[go] == f[2]) ++go;
        const Point u = p(f[(fo + 1) % 3]), v = p(f[(fo + 2) % 3]), x = p(f[fo]), y = p(g[go]);
        return CGAL::coplanar(u, v, x, y) && CGAL::coplanar_orientation(u, v, x, y) == CGAL::POSITIVE;
    }
    const Point v = p(f[fi]);
    const Point a1 = p(f[(fi + 1) % 3]), a2 = p(f[(fi + 2) % 3]), b1 = p(g[(gi + 1) % 3]), b2 = p(g[(gi + 2) % 3]);
    if (CGAL::do_intersect(triangle(m, a), Kernel::Segment_3(b1, b2)) ||
        CGAL::do_intersect(triangle(m, b), Kernel::Segment_3(a1, a2)))
        return true;
    for (const Point& x : {a1, a2})
        for (const Point& y : {b1, b2})
            if (CGAL::collinear(v, x, y) && CGAL::angle(x, v, y) == CGAL::ACUTE) return true;
    return false;
}

std::optional<std::array<glm::dvec3, 2>> common_segment(const WeldedMesh& m, uint32_t a, uint32_t b) {
    const Kernel::Triangle_3 ta = triangle(m, a), tb = triangle(m, b);
    if (!CGAL::do_intersect(ta, tb)) return std::nullopt;
    const auto result = CGAL::intersection(ta, tb);
    if (!result) return std::nullopt;
    const Kernel::Segment_3* segment = boost::get<Kernel::Segment_3>(&*result);  // CGAL 5.5: a boost::variant
    if (!segment) return std::nullopt;  // a point (touching), or a coplanar overlap
    const auto to_glm = [](const Point& p) { return glm::dvec3(p.x(), p.y(), p.z()); };
    return std::array<glm::dvec3, 2>{to_glm(segment->vertex(0)), to_glm(segment->vertex(1))};
}

}  // namespace lw
