#include "vector/stroke.h"

#include <algorithm>
#include <cmath>

namespace lw {

Stroke make_stroke(std::vector<glm::vec2> points, float width, glm::vec3 color, bool closed) {
    Stroke s;
    s.widths.assign(points.size(), width);
    s.points = std::move(points);
    s.color = color;
    s.closed = closed;
    return s;
}

Box2 stroke_bounds(const std::vector<Stroke>& strokes) {
    Box2 b{glm::vec2(INFINITY), glm::vec2(-INFINITY)};
    bool any = false;
    for (const Stroke& s : strokes)
        for (const glm::vec2& p : s.points) {
            b.lo = glm::min(b.lo, p);
            b.hi = glm::max(b.hi, p);
            any = true;
        }
    return any ? b : Box2{};
}

float stroke_length(const Stroke& s) {
    float length = 0.0f;
    for (size_t i = 1; i < s.points.size(); ++i) length += glm::length(s.points[i] - s.points[i - 1]);
    if (s.closed && s.points.size() > 2) length += glm::length(s.points.front() - s.points.back());
    return length;
}

float mean_width(const Stroke& s) {
    if (s.widths.empty()) return 0.0f;
    double sum = 0.0, weight = 0.0;
    for (size_t i = 1; i < s.points.size(); ++i) {
        const double l = glm::length(s.points[i] - s.points[i - 1]);
        sum += l * 0.5 * (s.widths[i] + s.widths[i - 1]);
        weight += l;
    }
    if (weight <= 0.0) {
        for (float w : s.widths) sum += w;
        return float(sum / double(s.widths.size()));
    }
    return float(sum / weight);
}

void transform_stroke(Stroke& s, glm::vec2 pivot, float angle, glm::vec2 offset, float scale) {
    const float c = std::cos(angle), sn = std::sin(angle);
    for (glm::vec2& p : s.points) {
        const glm::vec2 d = (p - pivot) * scale;
        p = pivot + offset + glm::vec2(c * d.x - sn * d.y, sn * d.x + c * d.y);
    }
    for (float& w : s.widths) w *= std::abs(scale);
}

}  // namespace lw
