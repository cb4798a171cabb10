// engine/geometry/bounding_sphere.cpp — the smallest sphere enclosing a point set.
//
// rtsc caps its feature size at 5 % of trimesh2's bounding-sphere radius, and trimesh2
// (TriMesh_bounding.cc, need_bsphere) takes that sphere from Gärtner's Miniball: the exact
// smallest enclosing ball, not the box's circumsphere. We compute the same ball with
// Gärtner's pivoting idea (Gärtner 1999, "Fast and robust smallest enclosing balls", §3):
// keep the ball of a support set of at most four points; while a point lies outside it,
// replace the support by that of the smallest ball of support ∪ {farthest point}, found by
// trying the at most 30 candidate boundary subsets of those ≤ 5 points. The radius grows
// strictly at every step, so this ends; in practice after a few dozen O(n) passes.
// Declared in curvature.h (its one user).
#include <algorithm>
#include <bit>
#include <cmath>

#include "geometry/curvature.h"

namespace lw {

namespace {

using glm::dvec3;

struct Ball {
    dvec3 center{0.0};
    double radius2 = -1.0;  // squared radius; negative while there is none
};

// The smallest sphere through k ≤ 4 affinely independent points: its centre lies in their
// affine hull, c = p0 + Σ λi di with di = pi − p0, and |c − pi| = |c − p0| gives
// Σj 2 (di·dj) λj = di·di. False for (nearly) dependent points — some other subset of the
// same points then carries the smallest ball.
bool ball_through(const dvec3* p, int k, Ball& ball) {
    if (k == 1) {
        ball = {p[0], 0.0};
        return true;
    }
    const int n = k - 1;
    dvec3 d[3];
    double m[3][4];  // the system, right-hand side in the last column
    double scale = 0.0;
    for (int i = 0; i < n; ++i) d[i] = p[i + 1] - p[0];
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) m[i][j] = 2.0 * glm::dot(d[i], d[j]);
        m[i][n] = glm::dot(d[i], d[i]);
        scale = std::max(scale, m[i][i]);
    }
    for (int c = 0; c < n; ++c) {  // Gaussian elimination with partial pivoting
        int pivot = c;
        for (int r = c + 1; r < n; ++r)
            if (std::fabs(m[r][c]) > std::fabs(m[pivot][c])) pivot = r;
        if (!(std::fabs(m[pivot][c]) > 1e-12 * scale)) return false;
        if (pivot != c)
            for (int j = 0; j <= n; ++j) std::swap(m[c][j], m[pivot][j]);
        for (int r = c + 1; r < n; ++r) {
            const double factor = m[r][c] / m[c][c];
            for (int j = c; j <= n; ++j) m[r][j] -= factor * m[c][j];
        }
    }
    double lambda[3];
    dvec3 offset(0.0);
    for (int r = n - 1; r >= 0; --r) {
        double sum = m[r][n];
        for (int j = r + 1; j < n; ++j) sum -= m[r][j] * lambda[j];
        lambda[r] = sum / m[r][r];
    }
    for (int i = 0; i < n; ++i) offset += lambda[i] * d[i];
    ball = {p[0] + offset, glm::dot(offset, offset)};
    return true;
}

// The smallest ball enclosing pts[0..n), n ≤ 5: the smallest of the balls through subsets of
// at most four points that encloses all n. Returns that subset as a bit mask (0: none found).
unsigned smallest_ball(const dvec3* pts, int n, Ball& best) {
    best = Ball{};
    unsigned best_mask = 0;
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
        if (std::popcount(mask) > 4) continue;
        dvec3 subset[4];
        int k = 0;
        for (int i = 0; i < n; ++i)
            if (mask & (1u << i)) subset[k++] = pts[i];
        Ball ball;
        if (!ball_through(subset, k, ball)) continue;
        if (best.radius2 >= 0.0 && ball.radius2 >= best.radius2) continue;
        const double limit = ball.radius2 * (1.0 + 1e-10);  // boundary points, up to rounding
        bool encloses = true;
        for (int i = 0; i < n && encloses; ++i) {
            const dvec3 d = pts[i] - ball.center;
            encloses = glm::dot(d, d) <= limit;
        }
        if (encloses) {
            best = ball;
            best_mask = mask;
        }
    }
    return best_mask;
}

}  // namespace

BoundingSphere minimal_bounding_sphere(const std::vector<glm::vec3>& points) {
    if (points.empty()) return {};
    dvec3 support[5] = {dvec3(points[0])};
    int count = 1;
    Ball ball{support[0], 0.0};
    auto farthest = [&](double& dist2) {
        size_t index = 0;
        dist2 = -1.0;
        for (size_t i = 0; i < points.size(); ++i) {
            const dvec3 d = dvec3(points[i]) - ball.center;
            const double d2 = glm::dot(d, d);
            if (d2 > dist2) dist2 = d2, index = i;
        }
        return index;
    };
    for (int pass = 0; pass < 10000; ++pass) {
        double dist2 = 0.0;
        const size_t far = farthest(dist2);
        if (dist2 <= ball.radius2 * (1.0 + 1e-10)) break;
        support[count++] = dvec3(points[far]);
        Ball next;
        const unsigned mask = smallest_ball(support, count, next);
        if (mask == 0 || !(next.radius2 > ball.radius2)) break;  // no progress: rounding
        int kept = 0;
        for (int i = 0; i < count; ++i)
            if (mask & (1u << i)) support[kept++] = support[i];
        count = kept;
        ball = next;
    }
    // The radius that really encloses every point about the centre found (equal to the
    // ball's up to rounding; larger only if the loop above stopped on rounding).
    double dist2 = 0.0;
    farthest(dist2);
    return {glm::vec3(ball.center), static_cast<float>(std::sqrt(std::max(dist2, 0.0)))};
}

}  // namespace lw
