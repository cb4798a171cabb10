#include "pattern/distribution.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lw {

namespace {

float corner_angle(glm::vec2 p, glm::vec2 q, glm::vec2 r) {  // the angle at p
    const glm::vec2 u = q - p, v = r - p;
    const float l = glm::length(u) * glm::length(v);
    if (l <= 0.0f) return 0.0f;
    return std::acos(std::clamp(glm::dot(u, v) / l, -1.0f, 1.0f));
}

void add_edge(std::vector<std::vector<int>>& n, int a, int b) {
    n[size_t(a)].push_back(b);
    n[size_t(b)].push_back(a);
}

// Sorts and deduplicates the neighbour lists, then fills shift and spacing.
void finish(Distribution& d) {
    const size_t n = d.positions.size();
    d.shift.assign(n, glm::vec2(0.0f));
    d.spacing.assign(n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        auto& list = d.neighbours[i];
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        if (list.empty()) continue;
        glm::vec2 barycentre(0.0f);  // relative to the element
        float spacing = 0.0f;
        for (int j : list) {
            const glm::vec2 delta = d.delta(int(i), j);
            barycentre += delta;
            spacing += glm::length(delta);
        }
        d.shift[i] = -barycentre / float(list.size());
        d.spacing[i] = spacing / float(list.size());
    }
}

}  // namespace

float max_angle(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return std::max({corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)});
}

float min_angle(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return std::min({corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)});
}

Distribution chain_distribution(const std::vector<glm::vec2>& positions, float period) {
    Distribution d;
    d.positions = positions;
    d.period = period;
    const bool closed = period > 0.0f;
    d.neighbours.resize(positions.size());
    std::vector<int> order(positions.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return positions[size_t(a)].x < positions[size_t(b)].x; });
    for (size_t i = 1; i < order.size(); ++i) add_edge(d.neighbours, order[i - 1], order[i]);
    if (closed && order.size() > 2) add_edge(d.neighbours, order.back(), order.front());
    finish(d);
    return d;
}

Distribution delaunay_distribution(const std::vector<glm::vec2>& positions) {
    Distribution d;
    d.positions = positions;
    d.neighbours.resize(positions.size());
    for (const auto& t : delaunay_triangles(positions)) {
        const glm::vec2 a = positions[size_t(t[0])], b = positions[size_t(t[1])], c = positions[size_t(t[2])];
        if (max_angle(a, b, c) > kUnskewedMaxAngle) continue;
        d.triangles.push_back(t);
        add_edge(d.neighbours, t[0], t[1]);
        add_edge(d.neighbours, t[1], t[2]);
        add_edge(d.neighbours, t[2], t[0]);
    }
    finish(d);
    return d;
}

std::vector<int> k_ring(const Distribution& d, int center, int k) {
    std::vector<int> out;
    std::vector<int> frontier{center};
    std::vector<int> seen{center};
    for (int ring = 0; ring < k && !frontier.empty(); ++ring) {
        std::vector<int> next;
        for (int e : frontier)
            for (int n : d.neighbours[size_t(e)])
                if (std::find(seen.begin(), seen.end(), n) == seen.end()) {
                    seen.push_back(n);
                    next.push_back(n);
                    out.push_back(n);
                }
        frontier = std::move(next);
    }
    return out;
}

}  // namespace lw
