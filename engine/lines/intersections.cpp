// Intersection lines: the face pairs and their common segments come from CGAL through
// geometry/face_pairs.h; here they become chained line segments.
#include "lines/intersections.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

#include "geometry/face_pairs.h"

namespace lw {

namespace {

// A barycentric coordinate this close to 0 puts a point on the opposite edge. Crossing
// points of two triangles are constructed in doubles from float input, so they are off
// their edge by ~1e-7 relative; a crossing far from every edge has coordinates of order 1.
constexpr double kOnEdge = 1e-5;
// Endpoints closer than this share a key (× the model's bounding-box diagonal).
constexpr double kSamePoint = 1e-7;

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

// One crossing: the segment two faces have in common, kept by the lower-numbered one.
struct Crossing {
    uint32_t face;   // the lower-numbered face of the pair
    uint32_t other;  // the other face: with `face`, the crossings' order
    glm::dvec3 p[2];
    glm::dvec3 bary[2];  // in `face`
};

// The segment faces `a` < `b` have in common, if they cross (not merely touch).
bool cross(const WeldedMesh& m, uint32_t a, uint32_t b, Crossing& out) {
    const std::optional<std::array<glm::dvec3, 2>> segment = common_segment(m, a, b);  // neither degenerate: those have no box
    if (!segment) return false;  // apart, touching at a point, or a coplanar overlap
    out.face = a;
    out.other = b;
    for (int e = 0; e < 2; ++e) {
        out.p[e] = (*segment)[size_t(e)];
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
    // Each pair tested as the search reports it (its faces are still in cache); neighbours
    // (a shared vertex) touch by construction and are not reported.
    std::vector<Crossing> crossings;
    size_t candidates = 0;
    for_each_box_pair(m, [&](uint32_t a, uint32_t b) {
        ++candidates;
        Crossing c;
        if (cross(m, a, b, c)) crossings.push_back(c);
    });
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
