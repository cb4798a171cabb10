#include "slam_fidelity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "components.h"
#include "core/error.h"

namespace lw::synth {

double grain(const Plane& ink, bool periodic) {
    const int n = ink.cols;
    if (n < 3) return 0.0;
    double sum = 0.0;
    size_t count = 0;
    for (int r = 0; r < ink.rows; ++r)
        for (int x = periodic ? 0 : 1; x < (periodic ? n : n - 1); ++x, ++count) {
            const float left = ink.at(r, (x + n - 1) % n), right = ink.at(r, (x + 1) % n);
            sum += std::abs(double(left) - 2.0 * double(ink.at(r, x)) + double(right));
        }
    return sum / double(count);
}

ElementStatistics element_statistics(const Plane& ink, bool periodic) {
    ElementStatistics e;
    std::vector<double> areas;
    for (const Component& c : components(ink, periodic, true, [&](size_t i) { return ink.v[i] > kElementInk; }))
        if (!c.touches_ends && !c.wraps) areas.push_back(double(c.area));  // cut by the ends, or a line: not an element
    e.count = int(areas.size());
    e.per_100_texels = 100.0 * double(e.count) / double(ink.cols);
    if (!areas.empty()) {
        double sum = 0.0, squares = 0.0;
        for (double a : areas) sum += a, squares += a * a;
        e.mean_area = sum / double(areas.size());
        const double variance = std::max(0.0, squares / double(areas.size()) - e.mean_area * e.mean_area);
        e.area_cv = std::sqrt(variance) / e.mean_area;
    }
    for (const Component& c : components(ink, periodic, false, [&](size_t i) { return ink.v[i] <= kElementInk; }))
        e.holes += !c.touches_edges && !c.touches_ends && !c.wraps;
    return e;
}

StrayInk stray_ink(const Plane& exemplar, const Plane& level) {
    if (exemplar.rows != level.rows) throw Error("stray_ink: the level and the exemplar have different row counts");
    StrayInk s;
    size_t texels = 0, stray = 0;
    for (int r = 0; r < exemplar.rows; ++r) {
        bool empty = true;
        for (int x = 0; x < exemplar.cols && empty; ++x) empty = exemplar.at(r, x) < kEmptyRowInk;
        if (!empty) continue;
        ++s.empty_rows;
        for (int x = 0; x < level.cols; ++x) stray += level.at(r, x) > kStrayInk;
        texels += size_t(level.cols);
    }
    s.share = texels ? double(stray) / double(texels) : 0.0;
    return s;
}

LevelFidelity level_fidelity(const Plane& exemplar, const Plane& level) {
    return {.grain = grain(level, true), .elements = element_statistics(level, true), .stray = stray_ink(exemplar, level)};
}

}  // namespace lw::synth
