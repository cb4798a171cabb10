// engine/pattern/distribution.h — how elements are arranged (Barla et al. 2006, §2.3, §3.2).
//
// Input:  element positions in the pattern's frame — 2D: drawing coordinates; 1D: (s, t), the
//         arc length along the path and the signed offset from it.
// Output: `Distribution`: the neighbour graph, per element the shift vector
//         S = position − barycentre of its neighbours (§2.3, used by the variation post-process,
//         §3.3) and the mean distance to its neighbours.
//
// 1D: neighbours along a chain (sorted by s; a closed path links the ends).
// 2D: a Delaunay triangulation (CGAL, engine/pattern/delaunay.cpp) keeping only the edges of
//     at least one unskewed triangle, i.e. one with no angle above 2π/3 (§2.3: this drops the
//     long, thin triangles along the convex hull).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

constexpr float kUnskewedMaxAngle = 2.0943951f;  // 2π/3

struct Distribution {
    std::vector<glm::vec2> positions;
    std::vector<std::vector<int>> neighbours;  // sorted, symmetric
    std::vector<std::array<int, 3>> triangles; // 2D: the unskewed Delaunay triangles kept
    std::vector<glm::vec2> shift;              // position − barycentre of the neighbours (0 without any)
    std::vector<float> spacing;                // mean distance to the neighbours (0 without any)
    float period = 0.0f;                       // closed 1D chains: the path length (s wraps), else 0

    // positions[b] − positions[a], with s wrapped into [−period/2, period/2] on a closed chain.
    glm::vec2 delta(int a, int b) const { return wrapped(positions[size_t(b)] - positions[size_t(a)]); }
    glm::vec2 wrapped(glm::vec2 d) const {
        if (period > 0.0f) d.x -= period * std::round(d.x / period);
        return d;
    }
};

// The Delaunay triangles of `points` (indices; counter-clockwise). Duplicate points are
// triangulated once (the duplicates get no triangles). Fewer than 3 points: none.
[[nodiscard]] std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<glm::vec2>& points);

// The largest and smallest interior angles of triangle abc, radians.
[[nodiscard]] float max_angle(glm::vec2 a, glm::vec2 b, glm::vec2 c);
[[nodiscard]] float min_angle(glm::vec2 a, glm::vec2 b, glm::vec2 c);

// positions[i].x is the arc length; a closed chain (period = the path length > 0) links the
// first and the last.
[[nodiscard]] Distribution chain_distribution(const std::vector<glm::vec2>& positions, float period = 0.0f);
[[nodiscard]] Distribution delaunay_distribution(const std::vector<glm::vec2>& positions);

// The elements within k graph steps of `center`, itself excluded, nearest rings first.
[[nodiscard]] std::vector<int> k_ring(const Distribution& d, int center, int k);

}  // namespace lw
