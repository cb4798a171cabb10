#include "stroke/outline.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>

#include "stroke/modifiers.h"

namespace lw {

namespace {

// The runs drawn into a grid of `cell` px, each segment covering the cells whose centres lie
// within `radius` of it.
struct Grid {
    glm::vec2 origin;
    float cell;
    int width = 0, height = 0;
    std::vector<uint8_t> line, outside;
    glm::vec2 centre(int x, int y) const { return origin + cell * glm::vec2(float(x) + 0.5f, float(y) + 0.5f); }
    size_t at(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
};

void draw_segment(Grid& g, glm::vec2 a, glm::vec2 b, float radius) {
    const glm::vec2 lo = (glm::min(a, b) - radius - g.origin) / g.cell, hi = (glm::max(a, b) + radius - g.origin) / g.cell;
    for (int y = std::max(0, int(lo.y)); y <= std::min(g.height - 1, int(hi.y)); ++y)
        for (int x = std::max(0, int(lo.x)); x <= std::min(g.width - 1, int(hi.x)); ++x) {
            const glm::vec2 c = g.centre(x, y);
            if (glm::distance(c, a + nearest_on_segment(c, a, b) * (b - a)) <= radius) g.line[g.at(x, y)] = 1;
        }
}

// The outer boundary of the region of cells that are not outside, by radial sweep: from
// `start` (its first cell in row order, so the cells left of and above it are outside), each
// next cell is the first inside neighbour clockwise after the one we came from, until the
// walk is back at `start` about to make its first move again (a start cell that joins two
// parts of the region is passed twice).
std::vector<glm::ivec2> trace_boundary(const Grid& g, glm::ivec2 start) {
    static const glm::ivec2 step[8] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    const auto inside = [&](glm::ivec2 p) {
        return p.x >= 0 && p.y >= 0 && p.x < g.width && p.y < g.height && !g.outside[g.at(p.x, p.y)];
    };
    std::vector<glm::ivec2> boundary{start};
    glm::ivec2 p = start;
    int from = 4;  // entered from the left (the cell to the left is outside)
    int first = -1;  // the first move: the walk ends when it would make it again (Jacob's rule)
    const size_t limit = 4 * g.line.size();
    for (size_t n = 0; n < limit; ++n) {
        // Clockwise (in y-down axes) from the neighbour we came from.
        int found = -1;
        for (int k = 1; k <= 8; ++k) {
            const int d = (from + k) % 8;
            if (inside(p + step[d])) {
                found = d;
                break;
            }
        }
        if (found < 0) return boundary;  // a single cell
        if (first < 0) first = found;
        else if (p == start && found == first) break;
        else boundary.push_back(p);
        p += step[found];
        from = (found + 4) % 8;  // the next sweep starts just past the cell we came from
    }
    return boundary;
}

// The runs' segments in square buckets, to find the one nearest a point.
class SegmentIndex {
public:
    // Buckets at least as wide as the farthest a boundary cell can be from its run.
    SegmentIndex(const std::vector<ScreenPath>& runs, glm::vec2 origin, glm::vec2 size, float reach)
        : runs_(runs), origin_(origin), bucket_(std::max(8.0f, reach)) {
        columns_ = int(size.x / bucket_) + 1;
        rows_ = int(size.y / bucket_) + 1;
        buckets_.resize(size_t(columns_) * size_t(rows_));
        for (uint32_t r = 0; r < runs.size(); ++r) {
            const size_t n = runs[r].samples.size();
            for (uint32_t i = 0; i < n; ++i) {  // segment i: samples i and i + 1 (or 0, closing a loop)
                if (i + 1 == n && !(runs[r].closed && n > 2) && n > 1) break;
                const glm::vec2 a = runs[r].samples[i].pixel, b = runs[r].samples[(i + 1) % n].pixel;
                const glm::ivec2 lo = bucket(glm::min(a, b)), hi = bucket(glm::max(a, b));
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) buckets_[size_t(y) * size_t(columns_) + size_t(x)].push_back({r, i});
            }
        }
    }

    // The run sample (interpolated) nearest `q` among the segments within a bucket of it.
    ScreenSample nearest(glm::vec2 q) const {
        float best = std::numeric_limits<float>::max();
        ScreenSample out = runs_.front().samples.front();
        const glm::ivec2 c = bucket(q);
        for (int y = std::max(0, c.y - 1); y <= std::min(rows_ - 1, c.y + 1); ++y)
            for (int x = std::max(0, c.x - 1); x <= std::min(columns_ - 1, c.x + 1); ++x)
                for (const auto& [r, i] : buckets_[size_t(y) * size_t(columns_) + size_t(x)]) {
                    const std::vector<ScreenSample>& s = runs_[r].samples;
                    const ScreenSample &a = s[i], &b = s[(i + 1) % s.size()];
                    const float t = nearest_on_segment(q, a.pixel, b.pixel);
                    const float d = glm::distance(q, a.pixel + t * (b.pixel - a.pixel));
                    if (d < best) best = d, out = lerp_sample(a, b, t);
                }
        return out;
    }

private:
    glm::ivec2 bucket(glm::vec2 p) const {
        const glm::ivec2 c((p - origin_) / bucket_);
        return glm::clamp(c, glm::ivec2(0), glm::ivec2(columns_ - 1, rows_ - 1));
    }
    const std::vector<ScreenPath>& runs_;
    glm::vec2 origin_;
    float bucket_;
    int columns_ = 0, rows_ = 0;
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> buckets_;
};

// The runs drawn into a grid of half-pixel cells, coarser on drawings over ~2000 × 2000 px
// (16 million cells at most), lines `tolerance` wide so that gaps up to that close. None
// (false) for a drawing whose cells would be wider than half the tolerance (runs far off
// screen) or whose bounds are not finite: it is left as it is.
bool draw_runs(const std::vector<ScreenPath>& runs, float tolerance, Grid& g) {
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const ScreenPath& r : runs)
        for (const ScreenSample& s : r.samples) lo = glm::min(lo, s.pixel), hi = glm::max(hi, s.pixel);
    const float margin = tolerance + 2.0f;
    const double w = double(hi.x) - double(lo.x) + 2.0 * margin, h = double(hi.y) - double(lo.y) + 2.0 * margin;
    if (!(w > 0.0 && h > 0.0 && std::isfinite(w * h))) return false;
    g.cell = float(std::max(0.5, std::sqrt(w * h / 16e6)));
    if (g.cell > 0.5f * tolerance) return false;
    g.origin = lo - margin;
    g.width = int(std::ceil(w / g.cell));
    g.height = int(std::ceil(h / g.cell));
    g.line.assign(size_t(g.width) * size_t(g.height), 0);
    for (const ScreenPath& r : runs) {
        const size_t n = r.samples.size();
        for (size_t i = 0; i + 1 < n + (r.closed && n > 2 ? 1 : 0); ++i)
            draw_segment(g, r.samples[i].pixel, r.samples[(i + 1) % n].pixel, 0.5f * tolerance);
    }
    return true;
}

// The outside: the cells reached from the border without crossing a line.
void fill_outside(Grid& g) {
    g.outside.assign(g.line.size(), 0);
    std::deque<glm::ivec2> todo;
    for (int x = 0; x < g.width; ++x) todo.insert(todo.end(), {{x, 0}, {x, g.height - 1}});
    for (int y = 0; y < g.height; ++y) todo.insert(todo.end(), {{0, y}, {g.width - 1, y}});
    while (!todo.empty()) {
        const glm::ivec2 p = todo.front();
        todo.pop_front();
        if (p.x < 0 || p.y < 0 || p.x >= g.width || p.y >= g.height) continue;
        const size_t i = g.at(p.x, p.y);
        if (g.outside[i] || g.line[i]) continue;
        g.outside[i] = 1;
        todo.insert(todo.end(), {p + glm::ivec2(1, 0), p - glm::ivec2(1, 0), p + glm::ivec2(0, 1), p - glm::ivec2(0, 1)});
    }
}

// The regions the fill does not reach (8-connected), each from its first cell in row order.
// One encloses something when it has cells off the lines, at least a tolerance-wide square
// of them: a loose run is all line.
struct Regions {
    std::vector<int32_t> of_cell;  // -1: outside
    std::vector<glm::ivec2> first_cell;
    std::vector<bool> encloses;
};

Regions find_regions(const Grid& g, float tolerance) {
    Regions out;
    out.of_cell.assign(g.line.size(), -1);
    const size_t min_enclosed = size_t(std::ceil(tolerance * tolerance / (g.cell * g.cell)));
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            if (g.outside[g.at(x, y)] || out.of_cell[g.at(x, y)] >= 0) continue;
            const auto id = int32_t(out.first_cell.size());
            size_t enclosed = 0;
            std::deque<glm::ivec2> cells{{x, y}};
            out.of_cell[g.at(x, y)] = id;
            while (!cells.empty()) {
                const glm::ivec2 p = cells.front();
                cells.pop_front();
                enclosed += g.line[g.at(p.x, p.y)] == 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const glm::ivec2 q = p + glm::ivec2(dx, dy);
                        if (q.x < 0 || q.y < 0 || q.x >= g.width || q.y >= g.height) continue;
                        const size_t i = g.at(q.x, q.y);
                        if (!g.outside[i] && out.of_cell[i] < 0) out.of_cell[i] = id, cells.push_back(q);
                    }
            }
            out.first_cell.push_back({x, y});
            out.encloses.push_back(enclosed >= min_enclosed);
        }
    return out;
}

// The boundary of the region starting at `first_cell`, snapped onto the runs, a sample per
// pixel of outline or more, with its arc length; fewer than 3 samples: none.
std::optional<ScreenPath> snapped_outline(const Grid& g, glm::ivec2 first_cell, const SegmentIndex& index,
                                          const ScreenPath& like) {
    ScreenPath path{.type = like.type, .closed = true, .visible = like.visible, .qi = like.qi, .source = like.source};
    for (const glm::ivec2& c : trace_boundary(g, first_cell)) {
        const ScreenSample s = index.nearest(g.centre(c.x, c.y));
        if (!path.samples.empty() && glm::distance(s.pixel, path.samples.back().pixel) < 1.0f) continue;
        path.samples.push_back(s);
    }
    if (path.samples.size() < 3) return std::nullopt;
    float s = 0.0f;
    for (size_t i = 0; i < path.samples.size(); ++i) {
        if (i > 0) s += glm::distance(path.samples[i].pixel, path.samples[i - 1].pixel);
        path.samples[i].s = s;
    }
    return path;
}

// The outlines of runs of one occlusion level; runs in no enclosing drawing are kept as they are.
void trace_level(const std::vector<ScreenPath>& runs, float tolerance, std::vector<ScreenPath>& out) {
    Grid g;
    if (!draw_runs(runs, tolerance, g)) {
        out.insert(out.end(), runs.begin(), runs.end());
        return;
    }
    fill_outside(g);
    const Regions regions = find_regions(g, tolerance);
    // Runs whose region encloses nothing stay as they are.
    for (const ScreenPath& r : runs) {
        if (r.samples.empty()) continue;
        const glm::ivec2 c((r.samples.front().pixel - g.origin) / g.cell);
        const int32_t id = c.x >= 0 && c.y >= 0 && c.x < g.width && c.y < g.height ? regions.of_cell[g.at(c.x, c.y)] : -1;
        if (id < 0 || !regions.encloses[size_t(id)]) out.push_back(r);
    }
    // Boundary cells lie within half the tolerance and a cell of a run: its nearest segment
    // is in the cell's bucket or the next.
    const SegmentIndex index(runs, g.origin, glm::vec2(g.width, g.height) * g.cell, tolerance + 2.0f * g.cell);
    for (size_t id = 0; id < regions.first_cell.size(); ++id)
        if (regions.encloses[id])
            if (std::optional<ScreenPath> path = snapped_outline(g, regions.first_cell[id], index, runs.front()))
                out.push_back(std::move(*path));
}

}  // namespace

std::vector<ScreenPath> trace_outlines(const std::vector<ScreenPath>& runs, float tolerance_px) {
    // Each occlusion level on its own: a set may select visible and hidden runs.
    std::map<uint32_t, std::vector<ScreenPath>> levels;
    for (const ScreenPath& r : runs)
        if (!r.samples.empty()) levels[r.qi].push_back(r);
    std::vector<ScreenPath> out;
    for (const auto& [level, level_runs] : levels) trace_level(level_runs, tolerance_px, out);
    return out;
}

}  // namespace lw
