#include "element_sizes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <queue>
#include <tuple>
#include <vector>

#include "components.h"

namespace lw::synth {

namespace {

// An attached piece is trimmed from this many texels: fewer are the odd texel of an edge,
// which the opening's digital disc leaves outside on any element.
constexpr int kLeastTrim = 4;
// A blob's peak: a maximum of the distance to paper over 5 × 5 texels, at least this deep
// (a one- or two-texel-thick curl has no peak of its own).
constexpr float kPeakDepth = 2.0f;
constexpr int kPeakRadius = 2;
// Two blobs are one where the boundary between them is at most this much shallower than
// the lower of their peaks: a neck is narrower than both blobs, a ridge of equal maxima
// (a fat oval) is not.
constexpr float kNeckDrop = 1.0f;
// Elements over this many times the exemplar's largest are neither split nor trimmed.
constexpr int kMostMerged = 4;

// One element's texels on a grid of its own: its bounding box in unwrapped columns, one
// texel of paper round it.
struct LocalGrid {
    int r0 = 0, u0 = 0, rows = 0, cols = 0;
    std::vector<int> texel;  // the plane's index, or −1 outside the element

    bool inside(int k) const { return texel[size_t(k)] >= 0; }
    // f(j) for every grid texel j ≠ k within `radius` rows and columns of k.
    template <class F>
    void neighbours(int k, int radius, F f) const {
        const int r = k / cols, u = k % cols;
        for (int dr = -radius; dr <= radius; ++dr)
            for (int du = -radius; du <= radius; ++du) {
                const int rr = r + dr, uu = u + du;
                if ((dr || du) && rr >= 0 && rr < rows && uu >= 0 && uu < cols) f(rr * cols + uu);
            }
    }
};

LocalGrid local_grid(const std::vector<int>& members, const std::vector<int>& column, int plane_cols) {
    LocalGrid g;
    int r1 = 0, u1 = 0;
    g.r0 = g.u0 = 1 << 30;
    for (int i : members) {
        const int r = i / plane_cols, u = column[size_t(i)];
        g.r0 = std::min(g.r0, r), g.u0 = std::min(g.u0, u);
        r1 = std::max(r1, r), u1 = std::max(u1, u);
    }
    g.r0 -= 1, g.u0 -= 1;
    g.rows = r1 - g.r0 + 2, g.cols = u1 - g.u0 + 2;
    g.texel.assign(size_t(g.rows) * size_t(g.cols), -1);
    for (int i : members) g.texel[size_t(i / plane_cols - g.r0) * size_t(g.cols) + size_t(column[size_t(i)] - g.u0)] = i;
    return g;
}

// Each component's texels (plane indices), from the labels components() gives.
std::vector<std::vector<int>> members_of(const std::vector<int>& label, size_t count) {
    std::vector<std::vector<int>> members(count);
    for (int i = 0; i < int(label.size()); ++i)
        if (label[size_t(i)] >= 0) members[size_t(label[size_t(i)])].push_back(i);
    return members;
}

// Each texel's distance to the nearest texel outside the element (0 outside), by comparing
// every pair on the element's grid: area × box texels, which is small for the elements the
// step touches (like elements of a stroke at most 64 rows wide, a few hundred texels).
std::vector<float> distance_to_paper(const LocalGrid& g) {
    std::vector<int> outside;
    for (int k = 0; k < int(g.texel.size()); ++k)
        if (!g.inside(k)) outside.push_back(k);
    std::vector<float> d(g.texel.size(), 0.0f);
    for (int k = 0; k < int(g.texel.size()); ++k) {
        if (!g.inside(k)) continue;
        int best = 1 << 30;
        for (int o : outside) {
            const int dr = k / g.cols - o / g.cols, du = k % g.cols - o % g.cols;
            best = std::min(best, dr * dr + du * du);
        }
        d[size_t(k)] = std::sqrt(float(best));
    }
    return d;
}

struct Blobs {
    std::vector<int> of;  // each grid texel's blob, 1 … count (0 outside)
    int count = 0;
};

// Peaks (a plateau of 8-connected peak texels is one) grown by a watershed of the distance,
// deepest texels first; ties go by index, so the result does not depend on the queue.
Blobs watershed(const LocalGrid& g, const std::vector<float>& d) {
    const int n = int(g.texel.size());
    Blobs b;
    b.of.assign(size_t(n), 0);
    std::vector<uint8_t> peak(size_t(n), 0);
    for (int k = 0; k < n; ++k) {
        if (d[size_t(k)] < kPeakDepth) continue;
        bool highest = true;
        g.neighbours(k, kPeakRadius, [&](int j) { highest = highest && d[size_t(j)] <= d[size_t(k)]; });
        peak[size_t(k)] = highest;
    }
    using Entry = std::tuple<float, int, int>;  // distance, −index, blob
    std::priority_queue<Entry> queue;
    for (int k = 0; k < n; ++k) {
        if (!peak[size_t(k)] || b.of[size_t(k)]) continue;
        const int id = ++b.count;
        std::vector<int> plateau{k};
        b.of[size_t(k)] = id;
        for (size_t q = 0; q < plateau.size(); ++q) {
            queue.push({d[size_t(plateau[q])], -plateau[q], id});
            g.neighbours(plateau[q], 1, [&](int j) {
                if (peak[size_t(j)] && !b.of[size_t(j)]) b.of[size_t(j)] = id, plateau.push_back(j);
            });
        }
    }
    while (!queue.empty()) {
        const auto [depth, negative, id] = queue.top();
        queue.pop();
        g.neighbours(-negative, 1, [&, id = id](int j) {
            if (!g.inside(j) || b.of[size_t(j)]) return;
            b.of[size_t(j)] = id;
            queue.push({d[size_t(j)], -j, id});
        });
    }
    return b;
}

// Joins blobs whose boundary lies within kNeckDrop of the lower peak, and numbers the rest
// 1 … count. A boundary's depth is its deepest pair of touching texels, each counted at the
// shallower of the two. Boundaries are taken deepest first and each compared with the
// peaks of the groups joined so far (the "dynamics" of a peak), so that a shallow blob
// between two dots joins one of them and does not chain them together.
void join_shallow_necks(Blobs& b, const LocalGrid& g, const std::vector<float>& d) {
    std::vector<float> top(size_t(b.count) + 1, 0.0f);
    for (size_t k = 0; k < b.of.size(); ++k) top[size_t(b.of[k])] = std::max(top[size_t(b.of[k])], d[k]);
    std::vector<std::vector<float>> boundary(size_t(b.count) + 1, std::vector<float>(size_t(b.count) + 1, -1.0f));
    for (int k = 0; k < int(b.of.size()); ++k) {
        const int own = b.of[size_t(k)];
        if (!own) continue;
        g.neighbours(k, 1, [&](int j) {
            const int other = b.of[size_t(j)];
            if (other > own) boundary[size_t(own)][size_t(other)] =
                                 std::max(boundary[size_t(own)][size_t(other)], std::min(d[size_t(k)], d[size_t(j)]));
        });
    }
    std::vector<std::tuple<float, int, int>> edges;  // depth, blob, blob
    for (int x = 1; x <= b.count; ++x)
        for (int y = x + 1; y <= b.count; ++y)
            if (boundary[size_t(x)][size_t(y)] >= 0.0f) edges.emplace_back(boundary[size_t(x)][size_t(y)], x, y);
    std::sort(edges.begin(), edges.end(), [](const auto& p, const auto& q) {
        return std::get<0>(p) != std::get<0>(q) ? std::get<0>(p) > std::get<0>(q) : p < q;
    });
    std::vector<int> root(size_t(b.count) + 1);
    std::iota(root.begin(), root.end(), 0);
    const auto find = [&](int x) {
        while (root[size_t(x)] != x) x = root[size_t(x)] = root[size_t(root[size_t(x)])];
        return x;
    };
    for (const auto& [depth, x, y] : edges) {
        const int rx = find(x), ry = find(y);
        if (rx == ry || depth < std::min(top[size_t(rx)], top[size_t(ry)]) - kNeckDrop) continue;
        root[size_t(ry)] = rx;
        top[size_t(rx)] = std::max(top[size_t(rx)], top[size_t(ry)]);
    }
    std::vector<int> number(size_t(b.count) + 1, 0);
    int count = 0;
    for (int id = 1; id <= b.count; ++id)
        if (find(id) == id) number[size_t(id)] = ++count;
    for (int& id : b.of)
        if (id) id = number[size_t(find(id))];
    b.count = count;
}

// The 8-connected pieces of the grid texels marked in `in` (each piece's texels in order).
std::vector<std::vector<int>> pieces_of(const LocalGrid& g, const std::vector<uint8_t>& in) {
    std::vector<int> label;
    const Plane shape(g.rows, g.cols);  // components() reads the grid's dimensions off a plane
    const size_t count = components(shape, false, true, [&](size_t k) { return in[k] != 0; }, &label).size();
    return members_of(label, count);
}

// Splits one element into its blobs when it has two or more: texels with a neighbour of a
// later blob become paper, so no two blobs touch even diagonally. Only when every piece the
// cut leaves has at least `min_piece` texels and every blob keeps one (cuts on two sides of
// a thin blob could break it into fragments, or leave nothing of it). Returns whether it
// split.
bool split_element(Plane& ink, const LocalGrid& g, const std::vector<float>& d, int min_piece, float paper) {
    Blobs b = watershed(g, d);
    join_shallow_necks(b, g, d);
    if (b.count < 2) return false;
    std::vector<int> cut;
    std::vector<uint8_t> kept(b.of.size(), 0);
    for (int k = 0; k < int(b.of.size()); ++k) {
        const int own = b.of[size_t(k)];
        if (!own) continue;
        bool boundary = false;
        g.neighbours(k, 1, [&](int j) { boundary = boundary || b.of[size_t(j)] > own; });
        if (boundary)
            cut.push_back(k);
        else
            kept[size_t(k)] = 1;
    }
    std::vector<uint8_t> has_piece(size_t(b.count) + 1, 0);
    for (const std::vector<int>& piece : pieces_of(g, kept)) {
        if (int(piece.size()) < min_piece) return false;
        has_piece[size_t(b.of[size_t(piece.front())])] = 1;  // kept texels of two blobs never touch
    }
    for (int id = 1; id <= b.count; ++id)
        if (!has_piece[size_t(id)]) return false;
    for (int k : cut) ink.v[size_t(g.texel[size_t(k)])] = paper;
    return true;
}

// Trims what is thinner than an exemplar's element off one element: the morphological
// opening by a disc of radius `rho` (every texel within rho of a texel at least rho deep)
// keeps the element's body; each piece left outside it of `min_piece` texels or more (an
// attached curl or half dot, not the odd texel of an edge) becomes paper. Returns whether
// anything was trimmed.
bool trim_element(Plane& ink, const LocalGrid& g, const std::vector<float>& d, float rho, int min_piece, float paper) {
    const int n = int(g.texel.size()), reach = int(std::ceil(rho));
    std::vector<uint8_t> body(size_t(n), 0);
    for (int k = 0; k < n; ++k) {
        if (d[size_t(k)] < rho) continue;
        body[size_t(k)] = 1;
        g.neighbours(k, reach, [&](int j) {
            const int dr = j / g.cols - k / g.cols, du = j % g.cols - k % g.cols;
            if (float(dr * dr + du * du) < rho * rho) body[size_t(j)] = 1;
        });
    }
    std::vector<uint8_t> outside_body(size_t(n), 0);
    for (int k = 0; k < n; ++k) outside_body[size_t(k)] = g.inside(k) && !body[size_t(k)];
    bool trimmed = false;
    for (const std::vector<int>& piece : pieces_of(g, outside_body)) {
        if (int(piece.size()) < min_piece) continue;
        for (int j : piece) ink.v[size_t(g.texel[size_t(j)])] = paper;
        trimmed = true;
    }
    return trimmed;
}

// The ink that runs down from each element: texels reached from it by steps (8-connected,
// columns wrapping) that do not climb, within `reach` steps, in no element. Every element
// floods at once, a step at a time, whole elements before fragments at each step, and a
// texel is the first claimant's: a dot's grey rim stays the dot's where a speck's ink runs
// down into it at the same level. Returns each texel's element (−1 for none).
std::vector<int> catchments(const Plane& ink, const std::vector<int>& label, const std::vector<uint8_t>& fragment,
                            float paper, int reach) {
    std::vector<int> owner(label), frontier;
    for (int pass = 0; pass < 2; ++pass)  // whole elements first
        for (int i = 0; i < int(ink.size()); ++i)
            if (label[size_t(i)] >= 0 && bool(fragment[size_t(label[size_t(i)])]) == bool(pass)) frontier.push_back(i);
    for (int step = 0; step < reach && !frontier.empty(); ++step) {
        std::vector<int> next;
        for (int i : frontier) {
            const int r = i / ink.cols, x = i % ink.cols;
            for (int dr = -1; dr <= 1; ++dr)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int rr = r + dr;
                    if (rr < 0 || rr >= ink.rows) continue;
                    const int j = rr * ink.cols + (x + dx + ink.cols) % ink.cols;
                    if (owner[size_t(j)] >= 0 || !(ink.v[size_t(j)] <= ink.v[size_t(i)]) || !(ink.v[size_t(j)] > paper))
                        continue;
                    owner[size_t(j)] = owner[size_t(i)];
                    next.push_back(j);
                }
        }
        std::stable_partition(next.begin(), next.end(), [&](int j) { return !fragment[size_t(owner[size_t(j)])]; });
        frontier = std::move(next);
    }
    return owner;
}

}  // namespace

ElementSizes element_sizes(const Plane& exemplar) {
    std::vector<int> label, column;
    const std::vector<Component> all =
        components(exemplar, false, true, [&](size_t i) { return exemplar.v[i] > kElementInk; }, &label, &column);
    ElementSizes s;
    std::vector<size_t> whole;
    for (size_t e = 0; e < all.size(); ++e) {
        const Component& c = all[e];
        if (c.touches_ends || c.touches_edges) continue;
        s.min_area = s.count ? std::min(s.min_area, c.area) : c.area;
        s.max_area = s.count ? std::max(s.max_area, c.area) : c.area;
        ++s.count;
        whole.push_back(e);
    }
    if (!s.alike()) return s;  // the depth serves the step only, which unlike elements skip
    const std::vector<std::vector<int>> members = members_of(label, all.size());
    for (size_t k = 0; k < whole.size(); ++k) {
        float depth = 0.0f;
        for (float d : distance_to_paper(local_grid(members[whole[k]], column, exemplar.cols))) depth = std::max(depth, d);
        s.min_depth = k ? std::min(s.min_depth, depth) : depth;
    }
    return s;
}

ElementChanges impose_element_sizes(Plane& ink, const ElementSizes& sizes, float paper, int reach) {
    ElementChanges changes;
    if (!sizes.alike()) return changes;
    std::vector<int> label, column;
    const std::vector<Component> elements =
        components(ink, true, true, [&](size_t i) { return ink.v[i] > kElementInk; }, &label, &column);
    const std::vector<std::vector<int>> members = members_of(label, elements.size());
    const int half_smallest = (sizes.min_area + 1) / 2;
    std::vector<uint8_t> fragment(elements.size(), 0);
    for (size_t e = 0; e < elements.size(); ++e) {
        const Component& c = elements[e];
        fragment[e] = !c.touches_edges && !c.wraps && c.area < half_smallest;
        changes.erased += fragment[e];
    }
    if (changes.erased) {
        const std::vector<int> owner = catchments(ink, label, fragment, paper, reach);
        for (size_t i = 0; i < ink.size(); ++i)
            if (owner[i] >= 0 && fragment[size_t(owner[i])]) ink.v[i] = paper;
    }
    for (size_t e = 0; e < elements.size(); ++e) {
        const Component& c = elements[e];
        if (c.touches_edges || c.wraps || fragment[e]) continue;
        // A merged pair or a dot with a curl is at most a few elements' worth; a larger
        // component is a band or a smear the sizes say nothing about (and the distance to
        // paper, compared pair by pair, would cost its area squared).
        if (c.area > sizes.max_area && c.area <= kMostMerged * sizes.max_area) {
            const LocalGrid g = local_grid(members[e], column, ink.cols);
            const std::vector<float> d = distance_to_paper(g);
            if (split_element(ink, g, d, half_smallest, paper))
                ++changes.split;
            else if (trim_element(ink, g, d, 0.5f * sizes.min_depth, kLeastTrim, paper))
                ++changes.trimmed;
        }
    }
    return changes;
}

}  // namespace lw::synth
