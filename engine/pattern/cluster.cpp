#include "pattern/cluster.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace lw {

namespace {

// E2 against the line through E1's centre along `dir` (one of E1's axes), E1 reaching `reach`
// along it and `across` across it: the gap between the projections, or +∞ when the two are
// not near-collinear. E1 itself must lie within ε/2 of the line (a box wider than ε is not a
// line at this scale: without this, the arms of a cross would continue each other).
float gap_along(const Element& e1, glm::vec2 dir, float reach, float across, const Element& e2, float epsilon) {
    if (across >= 0.5f * epsilon) return INFINITY;
    const glm::vec2 normal(-dir.y, dir.x);
    float lo = INFINITY, hi = -INFINITY;
    for (const glm::vec2& q : e2.corners()) {
        const glm::vec2 d = q - e1.center;
        if (std::abs(glm::dot(d, normal)) >= 0.5f * epsilon) return INFINITY;  // ∀p ∈ E2: d(p, A1) < ε/2
        lo = std::min(lo, glm::dot(d, dir));
        hi = std::max(hi, glm::dot(d, dir));
    }
    return std::max({0.0f, lo - reach, -reach - hi});
}

}  // namespace

float proximity(const Element& e1, const Element& e2) {
    return std::min(directed_hausdorff(e1, e2), directed_hausdorff(e2, e1));
}

float continuation(const Element& e1, const Element& e2, float epsilon) {
    return std::min({gap_along(e1, e1.axis, e1.half_length, e1.half_width, e2, epsilon),
                     gap_along(e1, e1.minor_axis(), e1.half_width, e1.half_length, e2, epsilon),
                     gap_along(e2, e2.axis, e2.half_length, e2.half_width, e1, epsilon),
                     gap_along(e2, e2.minor_axis(), e2.half_width, e2.half_length, e1, epsilon)});
}

bool should_cluster(const Element& e1, const Element& e2, float epsilon) {
    // A cheap rejection first: boxes farther apart than ε in every way cannot cluster by
    // proximity, and continuation needs a gap below ε too.
    const float reach1 = e1.half_length + e1.half_width, reach2 = e2.half_length + e2.half_width;
    if (glm::length(e1.center - e2.center) > reach1 + reach2 + epsilon) return false;
    return proximity(e1, e2) < epsilon || continuation(e1, e2, epsilon) < epsilon;
}

std::vector<Element> cluster_strokes(const std::vector<Stroke>& strokes, float epsilon, FitMode mode) {
    std::deque<Element> queue;
    for (size_t i = 0; i < strokes.size(); ++i) queue.push_back(fit_element(strokes, {int(i)}, mode));
    std::vector<Element> out;
    while (!queue.empty()) {
        Element current = std::move(queue.front());
        queue.pop_front();
        bool merged = false;
        std::deque<Element> rest;
        for (Element& other : queue) {
            if (should_cluster(current, other, epsilon)) {
                std::vector<int> ids = current.strokes;
                ids.insert(ids.end(), other.strokes.begin(), other.strokes.end());
                std::sort(ids.begin(), ids.end());
                current = fit_element(strokes, std::move(ids), mode);
                merged = true;
            } else {
                rest.push_back(std::move(other));
            }
        }
        queue = std::move(rest);
        if (merged) queue.push_back(std::move(current));
        else out.push_back(std::move(current));
    }
    std::sort(out.begin(), out.end(), [](const Element& a, const Element& b) { return a.strokes.front() < b.strokes.front(); });
    return out;
}

}  // namespace lw
