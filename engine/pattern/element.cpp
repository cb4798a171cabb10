#include "pattern/element.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

namespace {
constexpr float kPi = 3.14159265358979f;

glm::vec2 left_normal(glm::vec2 d) {
    const float l = glm::length(d);
    return l > 1e-12f ? glm::vec2(-d.y, d.x) / l : glm::vec2(0.0f);
}
}  // namespace

float Element::angle() const {
    float a = std::atan2(axis.y, axis.x);
    if (a < 0.0f) a += kPi;
    if (a >= kPi) a -= kPi;
    return a;
}

std::array<glm::vec2, 4> Element::corners() const {
    const glm::vec2 a = axis * half_length, b = minor_axis() * half_width;
    return {center - a - b, center + a - b, center + a + b, center - a + b};
}

WeightedPoints element_points(const std::vector<Stroke>& strokes, const std::vector<int>& ids, FitMode mode) {
    WeightedPoints out;
    for (int id : ids) {
        const Stroke& s = strokes.at(size_t(id));
        const size_t n = s.points.size();
        const bool wrap = s.closed && n > 2;
        for (size_t i = 0; i < n; ++i) {
            // Half of each adjacent segment: the polyline length this point stands for.
            const bool has_prev = i > 0 || wrap, has_next = i + 1 < n || wrap;
            const glm::vec2 prev = has_prev ? s.points[(i + n - 1) % n] : s.points[i];
            const glm::vec2 next = has_next ? s.points[(i + 1) % n] : s.points[i];
            const float weight = 0.5f * (glm::length(s.points[i] - prev) + glm::length(next - s.points[i])) + 1e-3f;
            const float w = s.widths.empty() ? 0.0f : s.widths[i];
            if (mode == FitMode::Skeleton || w <= 0.0f) {
                out.points.push_back(s.points[i]);
                out.weights.push_back(weight);
                continue;
            }
            glm::vec2 normal = left_normal(next - prev);
            if (n == 1) {  // a dot: its round extent in both directions
                for (const glm::vec2 d : {glm::vec2(1, 0), glm::vec2(-1, 0), glm::vec2(0, 1), glm::vec2(0, -1)}) {
                    out.points.push_back(s.points[i] + 0.5f * w * d);
                    out.weights.push_back(weight);
                }
                continue;
            }
            for (const float side : {-0.5f, 0.5f}) {
                out.points.push_back(s.points[i] + side * w * normal);
                out.weights.push_back(0.5f * weight);
            }
            // Round caps: the ends reach w/2 beyond the skeleton.
            if (!wrap && (i == 0 || i + 1 == n)) {
                const glm::vec2 d = glm::vec2(normal.y, -normal.x) * (i == 0 ? -1.0f : 1.0f);
                out.points.push_back(s.points[i] + 0.5f * w * d);
                out.weights.push_back(0.25f * weight);
            }
        }
    }
    return out;
}

Element fit_element(const std::vector<Stroke>& strokes, std::vector<int> ids, FitMode mode) {
    if (ids.empty()) throw Error("fit_element: no strokes");
    const WeightedPoints wp = element_points(strokes, ids, mode);
    if (wp.points.empty()) throw Error("fit_element: the strokes have no points");
    // Weighted mean and covariance (§2.1: the Gaussian fitted to the points).
    double total = 0.0;
    glm::dvec2 mean(0.0);
    for (size_t i = 0; i < wp.points.size(); ++i) {
        mean += double(wp.weights[i]) * glm::dvec2(wp.points[i]);
        total += wp.weights[i];
    }
    mean /= total;
    double cxx = 0.0, cxy = 0.0, cyy = 0.0;
    for (size_t i = 0; i < wp.points.size(); ++i) {
        const glm::dvec2 d = glm::dvec2(wp.points[i]) - mean;
        cxx += wp.weights[i] * d.x * d.x;
        cxy += wp.weights[i] * d.x * d.y;
        cyy += wp.weights[i] * d.y * d.y;
    }
    // The eigenvector of the larger eigenvalue of [[cxx, cxy], [cxy, cyy]].
    const double theta = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
    Element e;
    e.strokes = std::move(ids);
    e.axis = glm::vec2(float(std::cos(theta)), float(std::sin(theta)));
    const glm::vec2 b = e.minor_axis();
    float lo_a = INFINITY, hi_a = -INFINITY, lo_b = INFINITY, hi_b = -INFINITY;
    for (const glm::vec2& p : wp.points) {
        const glm::vec2 d = p - glm::vec2(mean);
        lo_a = std::min(lo_a, glm::dot(d, e.axis));
        hi_a = std::max(hi_a, glm::dot(d, e.axis));
        lo_b = std::min(lo_b, glm::dot(d, b));
        hi_b = std::max(hi_b, glm::dot(d, b));
    }
    e.center = glm::vec2(mean) + 0.5f * (lo_a + hi_a) * e.axis + 0.5f * (lo_b + hi_b) * b;
    e.half_length = 0.5f * (hi_a - lo_a);
    e.half_width = 0.5f * (hi_b - lo_b);
    if (e.half_width > e.half_length) {  // PCA's axis of larger variance need not be the longer box side
        std::swap(e.half_width, e.half_length);
        e.axis = b;
    }
    // Colour: weighted by stroke length (a dot counts as its width).
    glm::vec3 color(0.0f);
    float weight = 0.0f;
    for (int id : e.strokes) {
        const Stroke& s = strokes[size_t(id)];
        const float l = std::max(stroke_length(s), mean_width(s)) + 1e-6f;
        color += l * s.color;
        weight += l;
    }
    e.color = color / weight;
    return e;
}

float box_distance(const Element& e, glm::vec2 p) {
    const glm::vec2 d = p - e.center;
    const float u = std::max(std::abs(glm::dot(d, e.axis)) - e.half_length, 0.0f);
    const float v = std::max(std::abs(glm::dot(d, e.minor_axis())) - e.half_width, 0.0f);
    return std::sqrt(u * u + v * v);
}

float directed_hausdorff(const Element& e1, const Element& e2, glm::vec2 shift) {
    Element moved = e2;
    moved.center += shift;
    float d = 0.0f;
    for (const glm::vec2& q : e1.corners()) d = std::max(d, box_distance(moved, q));
    return d;
}

float axis_angle(glm::vec2 a, glm::vec2 b) {
    const float c = std::clamp(std::abs(glm::dot(a, b)) / std::max(glm::length(a) * glm::length(b), 1e-12f), 0.0f, 1.0f);
    return std::acos(c);
}

}  // namespace lw
