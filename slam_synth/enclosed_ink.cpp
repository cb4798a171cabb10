#include "enclosed_ink.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "components.h"

namespace lw::synth {

namespace {

double mean_difference(const Plane& fill, const Plane& ink) {
    double sum = 0.0;
    for (size_t i = 0; i < ink.size(); ++i) sum += double(fill.v[i]) - double(ink.v[i]);
    return ink.size() ? sum / double(ink.size()) : 0.0;
}

// The texel's four neighbours (columns wrap); -1 past the first or last row.
std::array<int, 4> neighbours(int i, int rows, int cols) {
    const int r = i / cols, x = i % cols;
    return {x > 0 ? i - 1 : i + cols - 1, x + 1 < cols ? i + 1 : i - cols + 1, r > 0 ? i - cols : -1,
            r + 1 < rows ? i + cols : -1};
}

}  // namespace

Plane fill_enclosed(const Plane& ink) {
    Plane fill = ink;
    if (ink.rows < 3) return fill;  // every texel is on the first or last row
    const int cols = ink.cols;
    std::vector<uint8_t> done(ink.size(), 0);
    // Least level first. (Ties may pop in any order: a texel's fill is its minimax path
    // value whichever way the flood reaches it.)
    using Entry = std::pair<float, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (int i : {0, (ink.rows - 1) * cols})
        for (int x = 0; x < cols; ++x) {
            done[size_t(i + x)] = 1;
            queue.push({fill.v[size_t(i + x)], i + x});
        }
    while (!queue.empty()) {
        const auto [level, i] = queue.top();
        queue.pop();
        for (int j : neighbours(i, ink.rows, cols)) {
            if (j < 0 || done[size_t(j)]) continue;
            done[size_t(j)] = 1;
            // Reached from a texel filled to `level`: a basin below it fills to it.
            fill.v[size_t(j)] = std::max(fill.v[size_t(j)], level);
            queue.push({fill.v[size_t(j)], j});
        }
    }
    return fill;
}

Plane fill_small_basins(const Plane& ink, int max_texels) {
    const Plane fill = fill_enclosed(ink);
    // The basins: 4-connected texels that the fill raises, across the seam as the flood goes.
    std::vector<int> label;
    const std::vector<Component> basins =
        components(ink, true, false, [&](size_t i) { return fill.v[i] > ink.v[i]; }, &label);
    Plane out = ink;
    for (size_t i = 0; i < ink.size(); ++i)
        if (label[i] >= 0 && basins[size_t(label[i])].area <= max_texels) out.v[i] = fill.v[i];
    return out;
}

double enclosed_deficit(const Plane& ink, int max_texels) {
    return mean_difference(fill_small_basins(ink, max_texels), ink);
}

void impose_enclosed_deficit(Plane& ink, double target, int max_texels) {
    // The flood orders texels by value, which NaN would break; a plane with non-finite ink
    // is left for the caller's checks to report.
    if (!std::all_of(ink.v.begin(), ink.v.end(), [](float v) { return std::isfinite(v); })) return;
    const Plane fill = fill_small_basins(ink, max_texels);
    const double deficit = mean_difference(fill, ink);
    if (!(deficit > std::max(target, 0.0))) return;
    // fill − μ (fill − x): a target of 0 gives the fill exactly.
    const float keep = float(std::max(target, 0.0) / deficit);
    for (size_t i = 0; i < ink.size(); ++i) ink.v[i] = fill.v[i] - keep * (fill.v[i] - ink.v[i]);
}

}  // namespace lw::synth
