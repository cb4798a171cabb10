// slam_synth/components.h — connected components of a plane's texels, by flood fill.
//
// Input: a plane's size, whether its columns wrap (a periodic level) and whether diagonal
// neighbours join (8- or 4-connected), and which texels belong (a predicate on the texel's
// index). Output: per component its area and where it reaches; optionally each texel's
// component (−1 for texels that do not belong). Used by the fidelity measures (elements and
// holes, slam_fidelity.h), the enclosed-paper step (basins, enclosed_ink.h) and the
// element-size step (element_sizes.h).
#pragma once

#include <utility>
#include <vector>

#include "fft.h"

namespace lw::synth {

struct Component {
    int area = 0;
    bool touches_ends = false;   // first or last column of a non-periodic plane
    bool touches_edges = false;  // first or last row
    bool wraps = false;          // periodic: goes all the way round the length (a band, not a blob)
};

// Each texel keeps the unwrapped column it was reached at: a component that reaches a texel
// again a whole length away goes round the strip. `columns`, when given, receives those
// unwrapped columns (a component that does not go round lies in one unbroken range of them).
template <class Inside>
std::vector<Component> components(const Plane& p, bool periodic, bool diagonal, Inside inside,
                                  std::vector<int>* labels = nullptr, std::vector<int>* columns = nullptr) {
    std::vector<int> label(p.size(), -1), unwrapped(p.size(), 0);
    std::vector<Component> out;
    std::vector<int> stack;
    for (int start = 0; start < int(p.size()); ++start) {
        if (label[size_t(start)] >= 0 || !inside(size_t(start))) continue;
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
                    if (!inside(size_t(j))) continue;
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
    if (labels) *labels = std::move(label);
    if (columns) *columns = std::move(unwrapped);
    return out;
}

}  // namespace lw::synth
