#include "coherence/path_dump.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/text.h"
#include "types/line_type.h"

namespace lw {

namespace {

void append_paths(nlohmann::json& out, const std::vector<ScreenPath>& paths, const std::vector<PathParam>& params,
                  const char* type_override, const std::string& line_set, int layer = -1) {
    using nlohmann::json;
    for (size_t p = 0; p < paths.size(); ++p) {
        const ScreenPath& path = paths[p];
        if (!path.visible) continue;
        const PathParam& param = p < params.size() ? params[p] : PathParam{};
        json samples = json::array();
        for (size_t k = 0; k < path.samples.size(); ++k) {
            const ScreenSample& s = path.samples[k];
            const float arclength = path_arclength(path, k);
            const float t = param.rho * arclength + param.phi;
            samples.push_back({{"x", s.pixel.x}, {"y", s.pixel.y}, {"s", arclength}, {"t", t},
                               {"u", param.fold.scale * t}, {"p", {s.position.x, s.position.y, s.position.z}}});
        }
        json entry = {{"type", type_override ? type_override : line_type_name(path.type)}};
        if (!line_set.empty()) entry["line_set"] = line_set;
        if (layer >= 0) entry["layer"] = layer;
        entry.update(json{{"closed", path.closed}, {"rho", param.rho}, {"phi", param.phi},
                                {"level", param.fold.level}, {"votes", param.votes}, {"samples", std::move(samples)}});
        out["paths"].push_back(std::move(entry));
    }
}

}  // namespace

std::string path_dump_json(int frame, int width, int height, const std::vector<DumpGroup>& sets,
                           const std::vector<ParameterizedPaths>& layers) {
    nlohmann::json out = {{"frame", frame}, {"width", width}, {"height", height}, {"paths", nlohmann::json::array()}};
    static const std::vector<PathParam> none;
    for (const DumpGroup& set : sets)
        if (set.paths) append_paths(out, *set.paths, set.params ? *set.params : none, nullptr, set.line_set);
    for (size_t i = 0; i < layers.size(); ++i)
        append_paths(out, layers[i].paths, layers[i].params, "layer", "", int(i));
    return out.dump();
}

PathDump read_path_dump(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw Error(file.string() + ": cannot open path dump");
    std::stringstream text;
    text << in.rdbuf();
    return parse_path_dump(text.str(), file.string());
}

PathDump parse_path_dump(const std::string& text, const std::string& name) {
    PathDump dump;
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        dump.frame = j.at("frame").get<int>();
        dump.width = j.value("width", 0);
        dump.height = j.value("height", 0);
        for (const auto& p : j.at("paths")) {
            DumpPath path{p.at("type").get<std::string>(), p.value("line_set", std::string()), p.at("rho").get<float>(), {}};
            // Each layer is measured on its own, as a line set is (dumps before the index: one group).
            if (p.contains("layer")) path.line_set = "layers[" + std::to_string(p.at("layer").get<int>()) + "]";
            for (const auto& s : p.at("samples")) {
                DumpSample sample{{s.at("x").get<float>(), s.at("y").get<float>()}, s.at("s").get<float>(),
                                  s.at("t").get<float>(), s.at("u").get<float>()};
                if (s.contains("p")) {
                    const auto& q = s.at("p");
                    sample.position = {q.at(0).get<float>(), q.at(1).get<float>(), q.at(2).get<float>()};
                }
                path.samples.push_back(sample);
            }
            dump.paths.push_back(std::move(path));
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error(name + ": malformed path dump: " + json_message(e.what()));
    }
    return dump;
}

namespace {

// |a − b| wrapped to half a period.
double wrapped_dt(double a, double b) {
    const double dt = a - b;
    return std::abs(dt - std::round(dt));
}

// Where a sample lies for a grid and a match: on the screen (N = 2, pixels) or on the
// surface (N = 3, the model's units).
template <int N>
using Point = glm::vec<N, float>;
template <int N>
Point<N> where(const DumpSample& s) {
    if constexpr (N == 2)
        return s.pixel;
    else
        return s.position;
}

// Samples of a frame in a grid of `cell`-sized buckets for neighbour queries.
template <int N>
struct SampleGrid {
    struct Entry {
        const DumpPath* path = nullptr;
        size_t k = 0;
        const DumpSample& sample() const { return path->samples[k]; }
        Point<N> at() const { return where<N>(sample()); }
    };
    float cell;
    std::unordered_map<int64_t, std::vector<Entry>> buckets;
    static int64_t key(glm::ivec3 c) {  // 21 bits a coordinate
        constexpr int64_t mask = (int64_t(1) << 21) - 1;
        return (int64_t(c.x) & mask) << 42 | (int64_t(c.y) & mask) << 21 | (int64_t(c.z) & mask);
    }
    glm::ivec3 cell_of(Point<N> p) const {
        glm::ivec3 c(0);
        for (int i = 0; i < N; ++i) c[i] = int(std::floor(p[i] / cell));
        return c;
    }
    // `keep(path)`: the paths the grid holds.
    template <class Keep>
    SampleGrid(const PathDump& frame, float c, Keep keep) : cell(c) {
        for (const auto& path : frame.paths)
            if (keep(path))
                for (size_t k = 0; k < path.samples.size(); ++k)
                    buckets[key(cell_of(where<N>(path.samples[k])))].push_back({&path, k});
    }
    SampleGrid(const PathDump& frame, float c) : SampleGrid(frame, c, [](const DumpPath&) { return true; }) {}
    // Every entry within `radius` (at most a cell) of `p`.
    template <class F>
    void for_each_within(Point<N> p, float radius, F&& f) const {
        const glm::ivec3 c = cell_of(p);
        const glm::ivec3 reach(1, 1, N == 3 ? 1 : 0);
        for (int z = c.z - reach.z; z <= c.z + reach.z; ++z)
            for (int y = c.y - reach.y; y <= c.y + reach.y; ++y)
                for (int x = c.x - reach.x; x <= c.x + reach.x; ++x) {
                    const auto it = buckets.find(key({x, y, z}));
                    if (it == buckets.end()) continue;
                    for (const Entry& e : it->second)
                        if (glm::length(e.at() - p) <= radius) f(e);
                }
    }
    // Of the samples of `line_set` within `radius`, those whose `distance(entry)` is within
    // `tie` (0.05 px on the screen) of the least: the least `score(entry)` among them (none: no
    // sample within `radius`). Equally near samples are the ends two paths share (a chain cut
    // at a vertex: one point ends a path and starts the next, each with its own phase) or a run
    // in two pieces; the callers score by phase difference, so that the point's own path is
    // the one compared.
    template <class Distance, class Score>
    std::optional<double> least_score_of_nearest(Point<N> p, float radius, float tie, const std::string& line_set,
                                                 Distance distance, Score score) const {
        float nearest_d = radius;
        for_each_within(p, radius, [&](const Entry& e) {
            if (e.path->line_set == line_set) nearest_d = std::min(nearest_d, distance(e));
        });
        std::optional<double> best;
        for_each_within(p, radius, [&](const Entry& e) {
            if (e.path->line_set != line_set || distance(e) > nearest_d + tie) return;
            const double sc = score(e);
            if (!best || sc < *best) best = sc;
        });
        return best;
    }
};

// The point of the matched sample's path nearest to `p`, projected on the segments to its
// neighbours: its distance to `p` and T interpolated there, so that samples placed at other
// phases still compare.
struct PathPoint {
    float distance;
    double t;
};
template <int N>
PathPoint point_on_path(const typename SampleGrid<N>::Entry& e, Point<N> p) {
    const std::vector<DumpSample>& s = e.path->samples;
    double t = s[e.k].t;
    float best = glm::length(e.at() - p);
    for (const size_t other : {e.k - 1, e.k + 1}) {
        if (other >= s.size()) continue;  // e.k - 1 wraps past 0
        const Point<N> a = e.at(), b = where<N>(s[other]);
        const float len2 = glm::dot(b - a, b - a);
        if (len2 <= 0.0f) continue;
        const float alpha = std::clamp(glm::dot(p - a, b - a) / len2, 0.0f, 1.0f);
        const float d = glm::length(a + alpha * (b - a) - p);
        if (d < best) {
            best = d;
            t = double(s[e.k].t) + double(alpha) * (double(s[other].t) - double(s[e.k].t));
        }
    }
    return {best, t};
}

// The median, 90th percentile, largest value and share over a quarter period of |Δt| values
// (sorted here); zeros for none.
struct Quantiles {
    double median = 0.0, p90 = 0.0, max = 0.0, over_quarter = 0.0;
};
Quantiles quantiles(std::vector<double>& values) {
    Quantiles q;
    if (values.empty()) return q;
    std::sort(values.begin(), values.end());
    q.median = values[values.size() / 2];
    q.p90 = values[std::min(values.size() - 1, values.size() * 9 / 10)];
    q.max = values.back();
    q.over_quarter = double(values.end() - std::upper_bound(values.begin(), values.end(), 0.25)) / double(values.size());
    return q;
}

}  // namespace

namespace {

SlidingStats sliding_stats(std::vector<double>& dts, std::vector<double>& pixels) {
    const Quantiles periods = quantiles(dts), along = quantiles(pixels);
    return {.median_dt = periods.median, .p90_dt = periods.p90, .pops = periods.over_quarter,
            .median_px = along.median, .p90_px = along.p90, .pairs = dts.size()};
}

using ScreenGrid = SampleGrid<2>;
constexpr float kTiePx = 0.05f;  // samples this much farther than the nearest are as near

// Whether a sample of another path of `line_set` than `path` lies within `radius` of `p`.
bool crowded(const ScreenGrid& grid, glm::vec2 p, float radius, const DumpPath* path) {
    bool found = false;
    grid.for_each_within(p, radius, [&](const ScreenGrid::Entry& e) {
        found = found || (e.path != path && e.path->line_set == path->line_set);
    });
    return found;
}

}  // namespace

SlidingMeasure measure_sliding(const std::vector<PathDump>& frames, float match_px) {
    std::vector<double> dts, pixels, alone_dts, alone_pixels;
    std::optional<ScreenGrid> previous;
    for (size_t f = 1; f < frames.size(); ++f) {
        if (!previous) previous.emplace(frames[f - 1], std::max(match_px, 1.0f));
        ScreenGrid current(frames[f], std::max(match_px, 1.0f));
        for (const auto& path : frames[f].paths)
            for (const auto& s : path.samples) {
                auto distance = [&](const ScreenGrid::Entry& e) { return point_on_path<2>(e, s.pixel).distance; };
                const ScreenGrid::Entry* matched = nullptr;
                double best_dt = 0.0;
                auto phase = [&](const ScreenGrid::Entry& e) {
                    const double dt = wrapped_dt(s.t, point_on_path<2>(e, s.pixel).t);
                    if (!matched || dt < best_dt) matched = &e, best_dt = dt;
                    return dt;
                };
                const std::optional<double> dt =
                    previous->least_score_of_nearest(s.pixel, match_px, kTiePx, path.line_set, distance, phase);
                if (!dt) continue;
                const double px = path.rho != 0.0f ? *dt / std::abs(double(path.rho)) : -1.0;
                dts.push_back(*dt);
                if (px >= 0.0) pixels.push_back(px);
                if (crowded(current, s.pixel, match_px, &path) ||
                    crowded(*previous, matched->sample().pixel, match_px, matched->path))
                    continue;
                alone_dts.push_back(*dt);
                if (px >= 0.0) alone_pixels.push_back(px);
            }
        previous.emplace(std::move(current));
    }
    SlidingMeasure m;
    static_cast<SlidingStats&>(m) = sliding_stats(dts, pixels);
    m.alone = sliding_stats(alone_dts, alone_pixels);
    return m;
}

bool attached_to_surface(const DumpPath& path) {
    const std::optional<LineType> type = line_type_from_name(path.type);
    return type && attached_to_surface(*type);
}

namespace {

// Model units per pixel at sample k of `path`: the lengths of its segments on the surface
// over their lengths on the screen (segments under a quarter pixel on the screen left out);
// 0 where none is left.
float units_per_pixel(const DumpPath& path, size_t k) {
    float units = 0.0f, pixels = 0.0f;
    for (const size_t other : {k - 1, k + 1}) {
        if (other >= path.samples.size()) continue;  // k - 1 wraps past 0
        const float on_screen = glm::length(path.samples[other].pixel - path.samples[k].pixel);
        if (on_screen < 0.25f) continue;
        units += glm::length(path.samples[other].position - path.samples[k].position);
        pixels += on_screen;
    }
    return pixels > 0.0f ? units / pixels : 0.0f;
}

}  // namespace

SlidingStats measure_sliding_on_surface(const std::vector<PathDump>& frames, float match_px) {
    std::vector<double> dts, pixels;
    if (!(match_px > 0.0f)) return {};
    for (size_t f = 1; f < frames.size(); ++f) {
        // The match radius is `match_px` in model units at each sample. The grid's cells are
        // twice the frame's median radius; a farther sample's radius is clamped to a cell.
        std::vector<float> scales;
        for (const DumpPath& path : frames[f].paths)
            if (attached_to_surface(path))
                for (size_t k = 0; k < path.samples.size(); ++k)
                    if (const float upp = units_per_pixel(path, k); upp > 0.0f) scales.push_back(upp);
        if (scales.empty()) continue;
        std::nth_element(scales.begin(), scales.begin() + std::ptrdiff_t(scales.size() / 2), scales.end());
        const float cell = 2.0f * match_px * scales[scales.size() / 2];
        const SampleGrid<3> previous(frames[f - 1], cell, [](const DumpPath& p) { return attached_to_surface(p); });
        for (const DumpPath& path : frames[f].paths) {
            if (!attached_to_surface(path)) continue;
            for (size_t k = 0; k < path.samples.size(); ++k) {
                const float upp = units_per_pixel(path, k);
                if (upp <= 0.0f) continue;
                const DumpSample& s = path.samples[k];
                auto distance = [&](const SampleGrid<3>::Entry& e) { return point_on_path<3>(e, s.position).distance; };
                auto phase = [&](const SampleGrid<3>::Entry& e) { return wrapped_dt(s.t, point_on_path<3>(e, s.position).t); };
                const std::optional<double> dt = previous.least_score_of_nearest(
                    s.position, std::min(match_px * upp, cell), kTiePx * upp, path.line_set, distance, phase);
                if (!dt) continue;
                dts.push_back(*dt);
                if (path.rho != 0.0f) pixels.push_back(*dt / std::abs(double(path.rho)));
            }
        }
    }
    return sliding_stats(dts, pixels);
}

PhaseError measure_phase_error(const PathDump& frame, const PathDump& reference, float match_px) {
    std::vector<double> dts;
    const ScreenGrid grid(reference, std::max(match_px, 1.0f));
    for (const auto& path : frame.paths)
        for (const auto& s : path.samples) {
            // The nearest reference path of the same set; where several lie as near (shared
            // ends, a run in two pieces), the closest phase among them counts.
            auto distance = [&](const ScreenGrid::Entry& e) { return point_on_path<2>(e, s.pixel).distance; };
            auto phase = [&](const ScreenGrid::Entry& e) { return wrapped_dt(s.t, point_on_path<2>(e, s.pixel).t); };
            if (const std::optional<double> dt = grid.least_score_of_nearest(s.pixel, match_px, kTiePx, path.line_set, distance, phase))
                dts.push_back(*dt);
        }
    const Quantiles q = quantiles(dts);
    return {.median = q.median, .p90 = q.p90, .max = q.max, .over_quarter = q.over_quarter, .pairs = dts.size()};
}

StretchMeasure measure_stretch(const std::vector<PathDump>& frames) {
    std::vector<double> ds_du;
    for (const auto& frame : frames)
        for (const auto& path : frame.paths)
            for (size_t k = 1; k < path.samples.size(); ++k) {
                const double du = std::abs(double(path.samples[k].u) - double(path.samples[k - 1].u));
                const double ds = double(path.samples[k].s) - double(path.samples[k - 1].s);
                if (du > 0.0 && ds > 0.0) ds_du.push_back(ds / du);
            }
    StretchMeasure m;
    m.samples = ds_du.size();
    if (ds_du.empty()) return m;
    std::sort(ds_du.begin(), ds_du.end());
    m.median_ds_du = ds_du[ds_du.size() / 2];
    // The factor-of-2 window holding the most samples (two pointers over the sorted values).
    size_t best = 0, j = 0;
    for (size_t i = 0; i < ds_du.size(); ++i) {
        while (j < ds_du.size() && ds_du[j] < 2.0 * ds_du[i]) ++j;
        if (j - i > best) {
            best = j - i;
            m.band_low = ds_du[i];
        }
    }
    m.share_in_band = double(best) / double(ds_du.size());
    return m;
}

namespace {

template <class Key>
std::vector<PathDump> paths_where(const std::vector<PathDump>& frames, Key key, const std::string& value) {
    std::vector<PathDump> out;
    for (const PathDump& frame : frames) {
        PathDump subset{.frame = frame.frame};
        for (const DumpPath& path : frame.paths)
            if (key(path) == value) subset.paths.push_back(path);
        out.push_back(std::move(subset));
    }
    return out;
}

template <class Key>
std::vector<std::string> values_in(const std::vector<PathDump>& frames, Key key) {
    std::vector<std::string> values;
    for (const PathDump& frame : frames)
        for (const DumpPath& path : frame.paths)
            if (std::find(values.begin(), values.end(), key(path)) == values.end()) values.push_back(key(path));
    return values;
}

const std::string& set_of(const DumpPath& path) { return path.line_set; }
const std::string& type_of(const DumpPath& path) { return path.type; }

}  // namespace

std::vector<PathDump> paths_of_line_set(const std::vector<PathDump>& frames, const std::string& line_set) {
    return paths_where(frames, set_of, line_set);
}
std::vector<std::string> line_sets_in(const std::vector<PathDump>& frames) { return values_in(frames, set_of); }
std::vector<PathDump> paths_of_type(const std::vector<PathDump>& frames, const std::string& type) {
    return paths_where(frames, type_of, type);
}
std::vector<std::string> types_in(const std::vector<PathDump>& frames) { return values_in(frames, type_of); }

}  // namespace lw
