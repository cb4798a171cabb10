#include "slam_fidelity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace lw::synth {

namespace {

struct Component {
    int area = 0;
    bool touches_ends = false;   // first or last column of a non-periodic plane
    bool touches_edges = false;  // first or last row
    bool wraps = false;          // periodic: goes all the way round the length (a band, not a blob)
};

// Connected components of the texels where `inside` holds, by flood fill; 8- or
// 4-connected, wrapping along the length when periodic. Each texel keeps the unwrapped
// column it was reached at: a component that reaches a texel again a whole length away
// goes round the strip.
template <class Inside>
std::vector<Component> components(const Plane& p, bool periodic, bool diagonal, Inside inside) {
    std::vector<int> label(p.size(), -1), unwrapped(p.size(), 0);
    std::vector<Component> out;
    std::vector<int> stack;
    for (int start = 0; start < int(p.size()); ++start) {
        if (label[size_t(start)] >= 0 || !inside(p.v[size_t(start)])) continue;
        const int id = int(out.size());
        Component c;
        label[size_t(start)] = id;
        unwrapped[size_t(start)] = start % p.cols;
        stack.assign(1, start);
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            const int r = i / p.cols, x = i % p.cols, u = unwrapped[size_t(i)];
            ++c.area;
            c.touches_edges = c.touches_edges || r == 0 || r == p.rows - 1;
            c.touches_ends = c.touches_ends || (!periodic && (x == 0 || x == p.cols - 1));
            for (int dr = -1; dr <= 1; ++dr)
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((dr == 0 && dx == 0) || (!diagonal && dr != 0 && dx != 0)) continue;
                    const int rr = r + dr;
                    int xx = x + dx;
                    if (rr < 0 || rr >= p.rows) continue;
                    if (xx < 0 || xx >= p.cols) {
                        if (!periodic) continue;
                        xx = (xx + p.cols) % p.cols;
                    }
                    const int j = rr * p.cols + xx;
                    if (!inside(p.v[size_t(j)])) continue;
                    if (label[size_t(j)] >= 0) {
                        c.wraps = c.wraps || unwrapped[size_t(j)] != u + dx;
                        continue;
                    }
                    label[size_t(j)] = id;
                    unwrapped[size_t(j)] = u + dx;
                    stack.push_back(j);
                }
        }
        out.push_back(c);
    }
    return out;
}

}  // namespace

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
    for (const Component& c : components(ink, periodic, true, [](float v) { return v > kElementInk; }))
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
    for (const Component& c : components(ink, periodic, false, [](float v) { return v <= kElementInk; }))
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
