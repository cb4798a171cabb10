#include "pattern/lloyd.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

namespace {

// Points bucketed on a uniform grid for nearest-point queries.
class PointGrid {
public:
    PointGrid(const std::vector<glm::vec2>& points, float cell) : points_(points), cell_(std::max(cell, 1e-6f)) {
        lo_ = glm::vec2(INFINITY);
        glm::vec2 hi(-INFINITY);
        for (const glm::vec2& p : points) {
            lo_ = glm::min(lo_, p);
            hi = glm::max(hi, p);
        }
        nx_ = std::max(1, int((hi.x - lo_.x) / cell_) + 1);
        ny_ = std::max(1, int((hi.y - lo_.y) / cell_) + 1);
        start_.assign(size_t(nx_ * ny_) + 1, 0);
        for (const glm::vec2& p : points) ++start_[size_t(index(p)) + 1];
        for (size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
        items_.resize(points.size());
        std::vector<int> fill(start_.begin(), start_.end() - 1);
        for (size_t i = 0; i < points.size(); ++i) items_[size_t(fill[size_t(index(points[i]))]++)] = int(i);
    }

    // The nearest point other than `exclude` (−1 when none), and its squared distance.
    int nearest(glm::vec2 q, int exclude, float* distance2 = nullptr) const {
        const int cx = std::clamp(int((q.x - lo_.x) / cell_), 0, nx_ - 1);
        const int cy = std::clamp(int((q.y - lo_.y) / cell_), 0, ny_ - 1);
        int best = -1;
        float best_d2 = INFINITY;
        const int max_ring = std::max(nx_, ny_);
        for (int r = 0; r <= max_ring; ++r) {
            for (int y = cy - r; y <= cy + r; ++y) {
                if (y < 0 || y >= ny_) continue;
                const bool edge_row = y == cy - r || y == cy + r;
                for (int x = cx - r; x <= cx + r; x += (edge_row || r == 0) ? 1 : 2 * r) {
                    if (x < 0 || x >= nx_) continue;
                    const size_t c = size_t(y * nx_ + x);
                    for (int k = start_[c]; k < start_[c + 1]; ++k) {
                        const int i = items_[size_t(k)];
                        if (i == exclude) continue;
                        const glm::vec2 d = points_[size_t(i)] - q;
                        const float d2 = glm::dot(d, d);
                        if (d2 < best_d2) best_d2 = d2, best = i;
                    }
                }
            }
            // Cells in ring r + 1 are at least r cells away.
            if (best >= 0 && best_d2 <= (float(r) * cell_) * (float(r) * cell_)) break;
        }
        if (distance2) *distance2 = best_d2;
        return best;
    }

private:
    int index(glm::vec2 p) const {
        const int x = std::clamp(int((p.x - lo_.x) / cell_), 0, nx_ - 1);
        const int y = std::clamp(int((p.y - lo_.y) / cell_), 0, ny_ - 1);
        return y * nx_ + x;
    }
    const std::vector<glm::vec2>& points_;
    float cell_;
    glm::vec2 lo_{0.0f};
    int nx_ = 1, ny_ = 1;
    std::vector<int> start_, items_;
};

}  // namespace

float polygon_area(const std::vector<glm::vec2>& polygon) {
    double a = 0.0;
    for (size_t i = 0, n = polygon.size(); i < n; ++i) {
        const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % n];
        a += p.x * q.y - q.x * p.y;
    }
    return float(std::abs(0.5 * a));
}

bool inside_polygon(const std::vector<glm::vec2>& polygon, glm::vec2 p) {
    bool in = false;
    for (size_t i = 0, n = polygon.size(), j = n - 1; i < n; j = i++) {
        const glm::vec2 a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

std::vector<float> lloyd_1d(int count, float length, bool closed, int iterations, Rng& rng) {
    std::vector<float> s(size_t(std::max(count, 0)));
    for (float& x : s) x = float(rng.uniform(0.0, double(length)));
    std::sort(s.begin(), s.end());
    const size_t n = s.size();
    if (n == 0) return s;
    // Lloyd converges slowly in 1D (an error spread over n seeds fades in about n² steps), and
    // uneven seeds break the neighbourhood pairing of the synthesis: after the requested
    // iterations, keep going until no seed moves more than 1e-3 of the spacing (at most
    // 2·10^7 seed updates in all).
    const float tolerance = 1e-3f * length / float(n);
    const long cap = std::max<long>(iterations, long(2e7 / double(n)));
    for (long it = 0; it < cap; ++it) {
        std::vector<float> next(n);
        for (size_t i = 0; i < n; ++i) {
            float lo, hi;
            if (closed) {
                const float prev = i > 0 ? s[i - 1] : s[n - 1] - length;
                const float succ = i + 1 < n ? s[i + 1] : s[0] + length;
                lo = 0.5f * (prev + s[i]);
                hi = 0.5f * (s[i] + succ);
            } else {
                lo = i > 0 ? 0.5f * (s[i - 1] + s[i]) : 0.0f;
                hi = i + 1 < n ? 0.5f * (s[i] + s[i + 1]) : length;
            }
            next[i] = 0.5f * (lo + hi);
            if (closed) next[i] = std::fmod(next[i] + length, length);
        }
        float moved = 0.0f;
        for (size_t i = 0; i < n; ++i) moved = std::max(moved, std::abs(next[i] - s[i]));
        s = std::move(next);
        std::sort(s.begin(), s.end());
        if (it + 1 >= iterations && moved < tolerance) break;
    }
    return s;
}

std::vector<glm::vec2> lloyd_2d(const std::vector<glm::vec2>& polygon, int count, int iterations, Rng& rng) {
    const float area = polygon.size() >= 3 ? polygon_area(polygon) : 0.0f;
    if (!(area > 0.0f)) throw Error("Lloyd: the region has no area");
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec2& p : polygon) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    std::vector<glm::vec2> seeds;
    seeds.reserve(size_t(std::max(count, 0)));
    for (int tries = 0; int(seeds.size()) < count; ++tries) {
        const glm::vec2 p(float(rng.uniform(lo.x, hi.x)), float(rng.uniform(lo.y, hi.y)));
        if (inside_polygon(polygon, p)) seeds.push_back(p);
        if (tries > 1000 * (count + 10)) throw Error("Lloyd: cannot place seeds inside the region");
    }
    if (seeds.empty() || iterations <= 0) return seeds;

    // Grid samples inside the region: about 32 per seed.
    const float step = std::sqrt(area / (32.0f * float(count)));
    std::vector<glm::vec2> samples;
    for (float y = lo.y + 0.5f * step; y < hi.y; y += step)
        for (float x = lo.x + 0.5f * step; x < hi.x; x += step)
            if (inside_polygon(polygon, {x, y})) samples.push_back({x, y});
    if (samples.empty()) return seeds;

    const float cell = std::sqrt(area / float(count));
    std::vector<glm::dvec2> sum(seeds.size());
    std::vector<int> hits(seeds.size());
    for (int it = 0; it < iterations; ++it) {
        const PointGrid grid(seeds, cell);
        std::fill(sum.begin(), sum.end(), glm::dvec2(0.0));
        std::fill(hits.begin(), hits.end(), 0);
        for (const glm::vec2& q : samples) {
            const int i = grid.nearest(q, -1);
            sum[size_t(i)] += glm::dvec2(q);
            ++hits[size_t(i)];
        }
        for (size_t i = 0; i < seeds.size(); ++i)
            if (hits[i] > 0) seeds[i] = glm::vec2(sum[i] / double(hits[i]));
    }
    return seeds;
}

std::vector<float> nearest_neighbour_distances(const std::vector<glm::vec2>& points) {
    std::vector<float> out(points.size(), 0.0f);
    if (points.size() < 2) return out;
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec2& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec2 e = glm::max(hi - lo, glm::vec2(1e-3f));
    const PointGrid grid(points, std::sqrt(e.x * e.y / float(points.size())) + 1e-6f);
    for (size_t i = 0; i < points.size(); ++i) {
        float d2 = 0.0f;
        grid.nearest(points[i], int(i), &d2);
        out[i] = std::sqrt(d2);
    }
    return out;
}

}  // namespace lw
