// Intersection lines with CGAL (compiled with -frounding-math, as its interval filters need,
// and without GMP: exact fallbacks use Boost.Multiprecision).
#include "lines/intersections.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

namespace lw {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
// Boxes of floats (the positions are floats, so their bounds are exact) named by a pointer to
// their face: 32 bytes, which the search sorts and swaps a great deal.
using Box = CGAL::Box_intersection_d::Box_with_handle_d<float, 3, const glm::uvec3*>;

// A barycentric coordinate this close to 0 puts a point on the opposite edge. Crossing
// points of two triangles are constructed in doubles from float input, so they are off
// their edge by ~1e-7 relative; a crossing far from every edge has coordinates of order 1.
constexpr double kOnEdge = 1e-5;
// Endpoints closer than this share a key (× the model's bounding-box diagonal).
constexpr double kSamePoint = 1e-7;
// Below this many boxes the search compares all pairs instead of splitting further (CGAL's
// default is 10). Measured on two crossing copies of LeePerrySmith subdivided once (141k
// faces): 10 → 409 ms, 100 → 338, 1000 → 240, 5000 → 180, 20000 → 263; on two of
// FlightHelmet (189k): 10 → 964 ms, 5000 → 606, 20000 → 779 (docs/BENCHMARKS.md).
constexpr std::ptrdiff_t kCutoff = 5000;

glm::dvec3 to_glm(const Point& p) { return {p.x(), p.y(), p.z()}; }

glm::dvec3 corner(const WeldedMesh& m, uint32_t face, int c) { return glm::dvec3(m.positions[m.faces[face][c]]); }

// Barycentric coordinates of p (on or near the plane of `face`) in `face`.
glm::dvec3 barycentric(const WeldedMesh& m, uint32_t face, const glm::dvec3& p) {
    const glm::dvec3 a = corner(m, face, 0), b = corner(m, face, 1), c = corner(m, face, 2);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area = glm::dot(n, n);
    const double u = glm::dot(glm::cross(c - b, p - b), n) / area;
    const double v = glm::dot(glm::cross(a - c, p - c), n) / area;
    return {u, v, 1.0 - u - v};
}

bool share_vertex(const glm::uvec3& f, const glm::uvec3& g) {
    for (int i = 0; i < 3; ++i)
        if (f[i] == g.x || f[i] == g.y || f[i] == g.z) return true;
    return false;
}

// One crossing: the segment two faces have in common, kept by the lower-numbered one.
struct Crossing {
    uint32_t face;   // the lower-numbered face of the pair
    uint32_t other;  // the other face: with `face`, the crossings' order
    glm::dvec3 p[2];
    glm::dvec3 bary[2];  // in `face`
};

// The segment faces `a` < `b` have in common, if they cross (not merely touch).
bool cross(const WeldedMesh& m, uint32_t a, uint32_t b, Crossing& out) {
    const auto tri = [&](uint32_t f) {
        const auto p = [&](int c) { const glm::vec3 x = m.positions[m.faces[f][c]]; return Point(x.x, x.y, x.z); };
        return Triangle(p(0), p(1), p(2));
    };
    const Triangle ta = tri(a), tb = tri(b);  // neither degenerate: those have no box
    if (!CGAL::do_intersect(ta, tb)) return false;
    const auto result = CGAL::intersection(ta, tb);
    if (!result) return false;
    const Kernel::Segment_3* segment = boost::get<Kernel::Segment_3>(&*result);  // CGAL 5.5: a boost::variant
    if (!segment) return false;  // a point (touching), or a coplanar overlap
    out.face = a;
    out.other = b;
    for (int e = 0; e < 2; ++e) {
        out.p[e] = to_glm(segment->vertex(e));
        out.bary[e] = barycentric(m, a, out.p[e]);
    }
    if (out.p[1] == out.p[0]) return false;
    // Both ends on the same edge of one face: the faces meet along that edge without
    // crossing (a seam of parts that are not welded, a wall standing on a floor).
    const glm::dvec3 in_b[2] = {barycentric(m, b, out.p[0]), barycentric(m, b, out.p[1])};
    for (const glm::dvec3* ends : {static_cast<const glm::dvec3*>(out.bary), in_b})
        for (int c = 0; c < 3; ++c)
            if (std::abs(ends[0][c]) <= kOnEdge && std::abs(ends[1][c]) <= kOnEdge) return false;
    return true;
}

// Chaining keys for the endpoints: one number per point where segments meet. A crossing
// curve leaves one face pair where it crosses an edge of one of the two faces and enters
// the next pair there, so consecutive segments share an endpoint; it is computed by two
// face pairs, so the two copies may differ by rounding, and in symmetric cases (mirror-image
// parts) it lies on an edge of both faces at once, which rules out naming it by an edge.
// Endpoints within `tolerance` of each other get the same key (a hash grid of that cell
// size; the first endpoint of a cluster is its representative), numbered densely from 0 as
// chaining indexes keys.
std::vector<uint32_t> endpoint_keys(const std::vector<Crossing>& crossings, double tolerance) {
    struct CellHash {
        size_t operator()(const glm::i64vec3& c) const {
            return size_t(uint64_t(c.x) * 73856093u ^ uint64_t(c.y) * 19349663u ^ uint64_t(c.z) * 83492791u);
        }
    };
    std::unordered_map<glm::i64vec3, std::vector<uint32_t>, CellHash> grid;
    std::vector<glm::dvec3> representative;
    std::vector<uint32_t> keys;
    keys.reserve(crossings.size() * 2);
    for (const Crossing& c : crossings)
        for (const glm::dvec3& p : c.p) {
            const glm::i64vec3 cell(glm::floor(p / tolerance));
            uint32_t key = kNoKey;
            for (int dz = -1; dz <= 1 && key == kNoKey; ++dz)
                for (int dy = -1; dy <= 1 && key == kNoKey; ++dy)
                    for (int dx = -1; dx <= 1 && key == kNoKey; ++dx) {
                        const auto found = grid.find(cell + glm::i64vec3(dx, dy, dz));
                        if (found == grid.end()) continue;
                        for (const uint32_t k : found->second)
                            if (glm::length(representative[k] - p) <= tolerance) { key = k; break; }
                    }
            if (key == kNoKey) {
                key = uint32_t(representative.size());
                representative.push_back(p);
                grid[cell].push_back(key);
            }
            keys.push_back(key);
        }
    return keys;
}

}  // namespace

std::vector<LineSegment> find_intersection_lines(const LineMesh& lm, size_t* candidate_pairs) {
    const WeldedMesh& m = lm.mesh;
    // A box per face that is a triangle: a degenerate face (its corners on one line) crosses
    // nothing, and testing it once here spares a test per pair it is in (CGAL's exact
    // collinearity test, a tenth of the time when done per pair).
    std::vector<Box> boxes;
    boxes.reserve(m.faces.size());
    for (uint32_t f = 0; f < m.faces.size(); ++f) {
        const glm::vec3 a = m.positions[m.faces[f].x], b = m.positions[m.faces[f].y], c = m.positions[m.faces[f].z];
        // (A corner at infinity or NaN, from a broken pose, would send CGAL's exact
        // fallback into numbers it cannot represent: such a face crosses nothing.)
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) continue;
        if (CGAL::collinear(Point(a.x, a.y, a.z), Point(b.x, b.y, b.z), Point(c.x, c.y, c.z))) continue;
        glm::vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
        boxes.emplace_back(&lo.x, &hi.x, &m.faces[f]);
    }
    // The spatial search, each pair tested as it is reported (its faces are still in cache);
    // neighbours (a shared vertex) touch by construction and are skipped.
    std::vector<Crossing> crossings;
    size_t candidates = 0;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        ++candidates;
        const auto x_face = uint32_t(x.handle() - m.faces.data()), y_face = uint32_t(y.handle() - m.faces.data());
        const uint32_t a = std::min(x_face, y_face), b = std::max(x_face, y_face);
        Crossing c;
        if (!share_vertex(m.faces[a], m.faces[b]) && cross(m, a, b, c)) crossings.push_back(c);
    }, kCutoff);
    if (candidate_pairs) *candidate_pairs = candidates;
    // The search reports pairs in an order of its own: the crossings (a few percent of the
    // pairs, so cheaper to sort than they) go in face-pair order.
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& x, const Crossing& y) { return std::tie(x.face, x.other) < std::tie(y.face, y.other); });
    // Endpoints are constructed in doubles from float positions by different face pairs;
    // copies of one point can differ by more than 1e-9 of the model's size (they do on the
    // two spheres of tests/test_intersections.cpp); 1e-7 of it joins them all there and is
    // far below a pixel.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& x : m.positions) lo = glm::min(lo, x), hi = glm::max(hi, x);
    std::vector<uint32_t> keys = endpoint_keys(crossings, kSamePoint * std::max(double(glm::length(hi - lo)), 1e-30));
    // A segment shorter than the tolerance (the curve clipping a face's corner) has both
    // ends at one point: left out, its neighbours meet there.
    size_t kept = 0;
    for (size_t i = 0; i < crossings.size(); ++i)
        if (keys[2 * i] != keys[2 * i + 1]) {
            crossings[kept] = crossings[i];
            keys[2 * kept] = keys[2 * i];
            keys[2 * kept + 1] = keys[2 * i + 1];
            ++kept;
        }
    crossings.resize(kept);
    std::vector<LineSegment> out;
    out.reserve(crossings.size());
    for (size_t i = 0; i < crossings.size(); ++i) {
        const Crossing& c = crossings[i];
        out.push_back(LineSegment{.p0 = glm::vec4(glm::vec3(c.p[0]), 1.0f),
                                  .p1 = glm::vec4(glm::vec3(c.p[1]), 1.0f),
                                  .bary0 = glm::vec3(c.bary[0]),
                                  .other_face = c.other,
                                  .bary1 = glm::vec3(c.bary[1]),
                                  .face = c.face,
                                  .type = uint32_t(LineType::Intersection),
                                  .key0 = keys[2 * i],
                                  .key1 = keys[2 * i + 1]});
    }
    return out;
}

const std::vector<LineSegment>& intersection_lines(const LineMesh& mesh, IntersectionCache& cache) {
    if (!holds_pose(cache.generation, mesh)) {
        cache.segments = find_intersection_lines(mesh, &cache.candidate_pairs);
        cache.generation = mesh.generation;
    }
    return cache.segments;
}

}  // namespace lw
