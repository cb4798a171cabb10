#include "stroke/modifiers.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/random.h"
#include "stroke/outline.h"

namespace lw {

float nearest_on_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    return len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
}

ScreenSample lerp_sample(const ScreenSample& a, const ScreenSample& b, float t) {
    ScreenSample q = t < 0.5f ? a : b;  // face: of the nearer sample
    q.pixel = glm::mix(a.pixel, b.pixel, t);
    q.depth = glm::mix(a.depth, b.depth, t);
    q.s = glm::mix(a.s, b.s, t);
    q.position = glm::mix(a.position, b.position, t);
    q.bary = glm::mix(a.bary, b.bary, t);
    q.alpha = glm::mix(a.alpha, b.alpha, t);
    q.width = glm::mix(a.width, b.width, t);
    return q;
}

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr float kCoincidentPx = 1e-4f;  // samples closer than this define no direction
constexpr double kMaxDashPeriods = 1 << 20;  // more periods than this on one path: no dashes

// ---- Path helpers ----

glm::vec2 unit_or_zero(glm::vec2 d) {
    const float len = glm::length(d);
    return len > 0.0f ? d / len : glm::vec2(0.0f);
}
// The stroke builder's normal convention: (−dy, dx) of the direction d.
glm::vec2 perp(glm::vec2 d) { return {-d.y, d.x}; }

// Cumulative pixel arclength of the samples (open: the closing segment is not counted).
std::vector<float> pixel_arclength(const ScreenPath& path) {
    std::vector<float> keys(path.samples.size(), 0.0f);
    for (size_t i = 1; i < keys.size(); ++i)
        keys[i] = keys[i - 1] + glm::length(path.samples[i].pixel - path.samples[i - 1].pixel);
    return keys;
}

float pixel_length(const ScreenPath& path) {
    const std::vector<float> keys = pixel_arclength(path);
    return (keys.empty() ? 0.0f : keys.back()) + closing_length(path);
}

std::vector<float> s_keys(const ScreenPath& path) {
    std::vector<float> keys;
    keys.reserve(path.samples.size());
    for (const ScreenSample& q : path.samples) keys.push_back(q.s);
    return keys;
}

// The sample at key k (keys: one per sample, nondecreasing; ≥ 2 samples), interpolated.
ScreenSample sample_at(const ScreenPath& path, const std::vector<float>& keys, float k) {
    const auto it = std::lower_bound(keys.begin() + 1, keys.end(), k);
    const size_t j = it == keys.end() ? keys.size() - 1 : size_t(it - keys.begin());
    const float span = keys[j] - keys[j - 1];
    const float t = span > 0.0f ? std::clamp((k - keys[j - 1]) / span, 0.0f, 1.0f) : 0.0f;
    return lerp_sample(path.samples[j - 1], path.samples[j], t);
}

// The open piece of `path` with keys in [a, b]: interpolated samples at a and b and the
// samples strictly between.
ScreenPath extract(const ScreenPath& path, const std::vector<float>& keys, float a, float b) {
    ScreenPath piece = empty_like(path);
    piece.samples.push_back(sample_at(path, keys, a));
    for (size_t i = 0; i < keys.size(); ++i)
        if (keys[i] > a && keys[i] < b) piece.samples.push_back(path.samples[i]);
    piece.samples.push_back(sample_at(path, keys, b));
    return piece;
}

// Unit normal per sample: the bisector of its segments' normals (one at open ends).
std::vector<glm::vec2> sample_normals(const ScreenPath& path) {
    const auto& s = path.samples;
    const size_t n = s.size();
    std::vector<glm::vec2> normals(n, glm::vec2(0.0f));
    for (size_t i = 0; i < n && n > 1; ++i) {
        const bool has_prev = i > 0 || path.closed, has_next = i + 1 < n || path.closed;
        const glm::vec2 n_prev = has_prev ? perp(unit_or_zero(s[i].pixel - s[(i + n - 1) % n].pixel)) : glm::vec2(0.0f);
        const glm::vec2 n_next = has_next ? perp(unit_or_zero(s[(i + 1) % n].pixel - s[i].pixel)) : glm::vec2(0.0f);
        normals[i] = unit_or_zero(n_prev + n_next);
    }
    return normals;
}

// The nearest sample before (step −1) or after (+1) i that is not where i is; n if none.
size_t distinct_neighbour(const ScreenPath& path, size_t i, int step) {
    const auto& s = path.samples;
    const size_t n = s.size();
    size_t j = i;
    for (size_t k = 1; k < n; ++k) {
        if (!path.closed && ((step < 0 && j == 0) || (step > 0 && j + 1 == n))) return n;
        j = step > 0 ? (j + 1) % n : (j + n - 1) % n;
        if (glm::length(s[j].pixel - s[i].pixel) > kCoincidentPx) return j;
    }
    return n;
}

double coherent_px(const StrokeParams& param, float period_px, float s) {
    return (double(param.rho) * double(s) + double(param.phi)) * double(period_px);
}

// ---- Chaining ----

// Samples where the polyline turns by more than max_turn_deg (the first of coincident ones).
std::vector<size_t> turn_samples(const ScreenPath& path, float max_turn_deg) {
    const auto& s = path.samples;
    const size_t n = s.size();
    const float cos_max = std::cos(glm::radians(max_turn_deg));
    std::vector<size_t> cuts;
    for (size_t i = path.closed ? 0 : 1; i + (path.closed ? 0 : 1) < n; ++i) {
        if (i > 0 && glm::length(s[i].pixel - s[i - 1].pixel) <= kCoincidentPx) continue;
        const size_t a = distinct_neighbour(path, i, -1), b = distinct_neighbour(path, i, 1);
        if (a == n || b == n) continue;
        const glm::vec2 d1 = unit_or_zero(s[i].pixel - s[a].pixel), d2 = unit_or_zero(s[b].pixel - s[i].pixel);
        if (glm::dot(d1, d2) < cos_max) cuts.push_back(i);
    }
    return cuts;
}

void split_at_turns(ScreenPath path, float max_turn_deg, std::vector<ScreenPath>& out) {
    std::vector<size_t> cuts = max_turn_deg < 180.0f && path.samples.size() > 2 ? turn_samples(path, max_turn_deg)
                                                                                 : std::vector<size_t>{};
    if (cuts.empty()) return out.push_back(std::move(path));
    if (path.closed) {
        // Open the loop at its first split; the split sample ends the last piece too.
        const size_t k0 = cuts.front(), n = path.samples.size();
        path = open_loop_at(path, k0);
        for (size_t& c : cuts) c -= k0;
        cuts.front() = 0;
        cuts.push_back(n);
    } else {
        cuts.insert(cuts.begin(), 0);
        cuts.push_back(path.samples.size() - 1);
    }
    for (size_t c = 0; c + 1 < cuts.size(); ++c) {
        ScreenPath piece = empty_like(path);
        piece.samples.assign(path.samples.begin() + std::ptrdiff_t(cuts[c]),
                             path.samples.begin() + std::ptrdiff_t(cuts[c + 1] + 1));
        out.push_back(std::move(piece));
    }
}

void cut_to_max_length(ScreenPath path, float max_length_px, std::vector<ScreenPath>& out) {
    if (!(max_length_px > 0.0f) || path.samples.size() < 2 || pixel_length(path) <= max_length_px)
        return out.push_back(std::move(path));
    const ScreenPath open = opened(path);
    const std::vector<float> keys = pixel_arclength(open);
    const float length = keys.back();
    const int pieces = int(std::ceil(length / max_length_px));
    for (int k = 0; k < pieces; ++k)
        out.push_back(extract(open, keys, length * float(k) / float(pieces), length * float(k + 1) / float(pieces)));
}

// ---- Geometry modifiers ----

template <class Offset>
void displace_along_normals(ScreenPath& path, Offset&& offset) {
    const std::vector<glm::vec2> normals = sample_normals(path);
    for (size_t i = 0; i < path.samples.size(); ++i)
        path.samples[i].pixel += normals[i] * offset(path.samples[i]);
}

void stretch_backbone(ScreenPath& path, float length_px) {
    auto& s = path.samples;
    const size_t n = s.size();
    if (path.closed || n < 2 || length_px <= 0.0f) return;
    const size_t after_first = distinct_neighbour(path, 0, 1), before_last = distinct_neighbour(path, n - 1, -1);
    if (after_first == n || before_last == n) return;
    ScreenSample head = s.front(), tail = s.back();
    head.pixel += unit_or_zero(s.front().pixel - s[after_first].pixel) * length_px;
    head.s -= length_px;
    tail.pixel += unit_or_zero(s.back().pixel - s[before_last].pixel) * length_px;
    tail.s += length_px;
    s.insert(s.begin(), head);
    s.push_back(tail);
}

void remove_tips(ScreenPath& path, float length_px) {
    if (path.closed || path.samples.size() < 2 || length_px <= 0.0f) return;
    const std::vector<float> keys = pixel_arclength(path);
    if (keys.back() <= 2.0f * length_px) return path.samples.clear();
    path = extract(path, keys, length_px, keys.back() - length_px);
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    return glm::length(p - (a + nearest_on_segment(p, a, b) * (b - a)));
}

// Douglas–Peucker on an open run, with an explicit stack (no recursion depth limit).
void douglas_peucker(ScreenPath& path, float tolerance_px) {
    auto& s = path.samples;
    if (s.size() < 3) return;
    std::vector<char> keep(s.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<size_t, size_t>> stack{{0, s.size() - 1}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        size_t worst = a;
        float worst_distance = tolerance_px;
        for (size_t i = a + 1; i < b; ++i) {
            const float d = distance_to_segment(s[i].pixel, s[a].pixel, s[b].pixel);
            if (d > worst_distance) worst = i, worst_distance = d;
        }
        if (worst == a) continue;  // every sample within tolerance: the chord replaces them
        keep[worst] = 1;
        stack.push_back({a, worst});
        stack.push_back({worst, b});
    }
    size_t kept = 0;
    for (size_t i = 0; i < s.size(); ++i)
        if (keep[i]) s[kept++] = s[i];
    s.resize(kept);
}

void simplify(ScreenPath& path, float tolerance_px) {
    if (!path.closed || path.samples.size() < 3) return douglas_peucker(path, tolerance_px);
    ScreenPath open = opened(path);  // the loop from sample 0 round to a copy of it
    douglas_peucker(open, tolerance_px);
    open.samples.pop_back();
    path.samples = std::move(open.samples);
}

// ---- Noise ----

double lattice_gradient(uint64_t seed, int64_t i) {
    const uint64_t h = mix64(mix64(seed) ^ uint64_t(i));
    return double(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;  // 53 bits → [−1, 1)
}

// ---- Attributes ----

// The turn is measured over at least this much of the path each way. A dense mesh's screen
// path wiggles at the sample scale (its samples are 2 px apart), and the turn between
// adjacent segments read that wiggle as curvature: a curvature width modifier drew a smooth
// back as barbed wire. Over ±4 px the wiggle averages out, and a curve's turn over the window
// divided by its length is still its curvature.
constexpr float kCurvatureWindowPx = 4.0f;

// The point `distance` px along the polyline `p` (cumulative lengths `at`, `total` with a
// loop's closing segment) from its start; a loop wraps, an open path stops at its ends.
glm::vec2 point_along(const std::vector<glm::vec2>& p, const std::vector<float>& at, float total, bool closed,
                      float distance) {
    if (closed) distance -= total * std::floor(distance / total);
    distance = std::clamp(distance, 0.0f, total);
    const size_t n = p.size();
    const size_t j = size_t(std::upper_bound(at.begin(), at.end(), distance) - at.begin());  // 1 … n
    const size_t a = j - 1, b = j % n;
    const float length = (j < n ? at[j] : total) - at[a];
    return length > 0.0f ? glm::mix(p[a], p[b], (distance - at[a]) / length) : p[a];
}

// |turn angle| / window length at each sample, 1/px: the turn between the chords from the
// point a window back to the sample and from it to the point a window on (the window at
// least the neighbouring samples' distance, so that a coarse polyline reads its corners).
std::vector<float> screen_curvature(const ScreenPath& path) {
    const auto& s = path.samples;
    const size_t n = s.size();
    std::vector<float> k(n, 0.0f);
    if (n < 2) return k;
    std::vector<glm::vec2> p(n);
    std::vector<float> at(n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        p[i] = s[i].pixel;
        if (i > 0) at[i] = at[i - 1] + glm::length(p[i] - p[i - 1]);
    }
    const float total = at.back() + (path.closed ? glm::length(p.front() - p.back()) : 0.0f);
    if (!(total > kCoincidentPx)) return k;
    for (size_t i = 0; i < n; ++i) {
        const size_t a = distinct_neighbour(path, i, -1), b = distinct_neighbour(path, i, 1);
        if (a == n || b == n) continue;
        float back = std::max(kCurvatureWindowPx, glm::length(p[i] - p[a]));
        float on = std::max(kCurvatureWindowPx, glm::length(p[b] - p[i]));
        if (!path.closed) back = std::min(back, at[i]), on = std::min(on, total - at[i]);
        const glm::vec2 e1 = p[i] - point_along(p, at, total, path.closed, at[i] - back),
                        e2 = point_along(p, at, total, path.closed, at[i] + on) - p[i];
        if (!(glm::length(e1) > kCoincidentPx && glm::length(e2) > kCoincidentPx)) continue;
        const float turn = std::atan2(std::abs(e1.x * e2.y - e1.y * e2.x), glm::dot(e1, e2));
        k[i] = turn / (0.5f * (glm::length(e1) + glm::length(e2)));
    }
    if (!path.closed && n >= 3) k.front() = k[1], k.back() = k[n - 2];
    return k;
}

float map_range(float value, float lo, float hi) {
    if (!(hi > lo)) return value >= lo ? 1.0f : 0.0f;
    return std::clamp((value - lo) / (hi - lo), 0.0f, 1.0f);
}

struct SampleInputs {
    float along, depth, curvature;
};

float modifier_input(const SampleInputs& in, ModifierInput input, float lo, float hi) {
    switch (input) {
        case ModifierInput::Along: return in.along;
        case ModifierInput::Distance: return map_range(in.depth, lo, hi);
        case ModifierInput::Curvature: return map_range(in.curvature, lo, hi);
    }
    return 0.0f;
}

float apply_scalar_modifiers(float value, const std::vector<ScalarModifier>& mods, const SampleInputs& in) {
    for (const ScalarModifier& m : mods) {
        if (m.ramp.points.empty()) continue;
        const float r = ramp_value(m.ramp, modifier_input(in, m.input, m.range_min, m.range_max));
        switch (m.blend) {
            case ModifierBlend::Multiply: value *= r; break;
            case ModifierBlend::Replace: value = r; break;
            case ModifierBlend::Add: value += r; break;
        }
    }
    return value;
}

// The width tapers linearly towards each tapered end, as the stroke builder always has:
// over at most half the stroke (a short stroke still reaches full width in its middle), and
// to 15 % at the tip, so that tips stay visible.
float taper_factor(const StrokeSpan& whole, const LineSetStyle& style, float s) {
    if (whole.closed || (style.taper_in_px <= 0.0f && style.taper_out_px <= 0.0f)) return 1.0f;
    // A stroke drawn as a dot (stroke/stroke_geometry.h) has no ends to taper, and would
    // otherwise shrink to the tips' 15 %.
    if (whole.s_end - whole.s_begin <= kDotLengthPx) return 1.0f;
    const float half = 0.5f * std::max(whole.s_end - whole.s_begin, 1e-3f);
    float f = 1.0f;
    if (style.taper_in_px > 0.0f) f = std::min(f, (s - whole.s_begin) / std::min(style.taper_in_px, half));
    if (style.taper_out_px > 0.0f) f = std::min(f, (whole.s_end - s) / std::min(style.taper_out_px, half));
    return std::clamp(f, 0.15f, 1.0f);
}

}  // namespace

std::vector<ScreenPath> apply_chaining_options(std::vector<ScreenPath> paths, const ChainingOptions& options) {
    if (options.outline) paths = trace_outlines(paths);
    std::vector<ScreenPath> split, cut, kept;
    for (ScreenPath& path : paths) split_at_turns(std::move(path), options.split_angle_deg, split);
    for (ScreenPath& path : split) cut_to_max_length(std::move(path), options.max_length_px, cut);
    for (ScreenPath& path : cut)
        if (!(options.min_length_px > 0.0f) || pixel_length(path) >= options.min_length_px)
            kept.push_back(std::move(path));
    return kept;
}

float gradient_noise(uint64_t seed, double t) {
    if (!std::isfinite(t)) return 0.0f;
    const double cell = std::floor(t), f = t - cell;
    const int64_t i = int64_t(cell);
    const double fade = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    const double a = lattice_gradient(seed, i) * f, b = lattice_gradient(seed, i + 1) * (f - 1.0);
    // With gradients in [−1, 1] the blend stays within ±0.5 (reached at f = 0.5): scale by 2.
    return float(std::clamp(2.0 * (a + fade * (b - a)), -1.0, 1.0));
}

void apply_geometry_modifiers(ScreenPath& path, const StrokeParams& param, float period_px,
                              const std::vector<GeometryModifier>& mods) {
    using Kind = GeometryModifier::Kind;
    for (const GeometryModifier& m : mods) {
        if (path.samples.size() < 2) return;
        const bool waves = m.kind == Kind::Sinus || m.kind == Kind::Noise;
        if (waves && !(m.wavelength_px > 0.0f)) continue;
        switch (m.kind) {
            case Kind::Sinus:
                displace_along_normals(path, [&](const ScreenSample& q) {
                    const double x = coherent_px(param, period_px, q.s);
                    return float(double(m.amplitude_px) *
                                 std::sin(kTwoPi * (x / double(m.wavelength_px) + double(m.phase))));
                });
                break;
            case Kind::Noise:
                displace_along_normals(path, [&](const ScreenSample& q) {
                    const double x = coherent_px(param, period_px, q.s);
                    return m.amplitude_px * gradient_noise(m.seed, x / double(m.wavelength_px));
                });
                break;
            case Kind::BackboneStretch: stretch_backbone(path, m.length_px); break;
            case Kind::TipRemove: remove_tips(path, m.length_px); break;
            case Kind::Simplify: simplify(path, m.tolerance_px); break;
        }
    }
}

std::vector<ScreenPath> dash_path(const ScreenPath& path, const StrokeParams& param, float period_px,
                                  const std::vector<float>& pattern) {
    std::vector<float> dashes = pattern;
    if (dashes.size() % 2 == 1) dashes.insert(dashes.end(), pattern.begin(), pattern.end());
    const double total = std::accumulate(dashes.begin(), dashes.end(), 0.0);
    const bool valid = std::none_of(dashes.begin(), dashes.end(), [](float d) { return !(d >= 0.0f); });
    if (dashes.empty() || !valid || total < 1e-3 || path.samples.size() < 2) return {path};

    const ScreenPath open = opened(path);
    const std::vector<float> keys = s_keys(open);
    // x = a·s + b; without a parameterization the pattern runs along s.
    double a = double(param.rho) * double(period_px), b = double(param.phi) * double(period_px);
    if (a == 0.0 || !std::isfinite(a)) a = 1.0, b = 0.0;
    const double x_first = a * double(keys.front()) + b, x_last = a * double(keys.back()) + b;
    const double x_lo = std::min(x_first, x_last), x_hi = std::max(x_first, x_last);
    if ((x_hi - x_lo) / total > kMaxDashPeriods) return {path};

    std::vector<std::pair<float, float>> ranges;  // s ranges of the dashes
    for (double base = std::floor(x_lo / total) * total; base <= x_hi; base += total) {
        double offset = base;
        for (size_t j = 0; j < dashes.size(); offset += double(dashes[j]), ++j) {
            if (j % 2 == 1) continue;
            const double lo = std::max(offset, x_lo), hi = std::min(offset + double(dashes[j]), x_hi);
            if (hi < lo || (hi == lo && dashes[j] > 0.0f)) continue;
            const float s_a = float((lo - b) / a), s_b = float((hi - b) / a);
            ranges.push_back({std::min(s_a, s_b), std::max(s_a, s_b)});
        }
    }
    std::sort(ranges.begin(), ranges.end());
    const bool whole = ranges.size() == 1 && ranges[0].first <= keys.front() && ranges[0].second >= keys.back();
    if (whole) return {path};
    std::vector<ScreenPath> pieces;
    for (const auto& [s_a, s_b] : ranges) pieces.push_back(extract(open, keys, s_a, s_b));
    // A loop's first and last dashes meeting at its seam are one dash.
    if (path.closed && pieces.size() > 1 && ranges.front().first <= keys.front() &&
        ranges.back().second >= keys.back()) {
        const float loop = keys.back() - keys.front();
        for (auto it = pieces.front().samples.begin() + 1; it != pieces.front().samples.end(); ++it) {
            pieces.back().samples.push_back(*it);
            pieces.back().samples.back().s += loop;
        }
        pieces.erase(pieces.begin());
    }
    return pieces;
}

float ramp_value(const Ramp& ramp, float x) {
    const auto& p = ramp.points;
    if (x <= p.front().x) return p.front().y;
    if (x >= p.back().x) return p.back().y;
    const auto it = std::upper_bound(p.begin(), p.end(), x, [](float v, const glm::vec2& q) { return v < q.x; });
    const glm::vec2 a = *(it - 1), b = *it;
    return b.x > a.x ? glm::mix(a.y, b.y, (x - a.x) / (b.x - a.x)) : b.y;
}

glm::vec3 ramp_value(const ColorRamp& ramp, float x) {
    const auto& p = ramp.points;
    if (x <= p.front().first) return p.front().second;
    if (x >= p.back().first) return p.back().second;
    const auto it = std::upper_bound(p.begin(), p.end(), x, [](float v, const auto& q) { return v < q.first; });
    const auto &a = *(it - 1), &b = *it;
    return b.first > a.first ? glm::mix(a.second, b.second, (x - a.first) / (b.first - a.first)) : b.second;
}

StrokeSpan stroke_span(const ScreenPath& path) {
    if (path.samples.empty()) return {};
    return {path.samples.front().s, path.samples.back().s + closing_length(path), path.closed};
}

StrokeAttributes evaluate_attributes(const ScreenPath& path, const LineSetStyle& style) {
    return evaluate_attributes(path, style, stroke_span(path));
}

StrokeAttributes evaluate_attributes(const ScreenPath& piece, const LineSetStyle& style, const StrokeSpan& whole) {
    const size_t n = piece.samples.size();
    StrokeAttributes out;
    out.width.resize(n);
    out.alpha.resize(n);
    out.color.resize(n);
    const std::vector<float> curvature = screen_curvature(piece);
    const float length = whole.s_end - whole.s_begin;
    for (size_t i = 0; i < n; ++i) {
        const ScreenSample& q = piece.samples[i];
        const float along = length > 0.0f ? std::clamp((q.s - whole.s_begin) / length, 0.0f, 1.0f) : 0.0f;
        const SampleInputs in{along, q.depth, curvature[i]};
        const float width = apply_scalar_modifiers(style.width * q.width, style.width_modifiers, in);
        out.width[i] = std::max(0.0f, width * taper_factor(whole, style, q.s));
        const float alpha = style.alpha * (style.fade ? q.alpha : 1.0f);
        out.alpha[i] = std::clamp(apply_scalar_modifiers(alpha, style.alpha_modifiers, in), 0.0f, 1.0f);
        glm::vec3 color = style.color;
        for (const ColorModifier& m : style.color_modifiers)
            if (!m.ramp.points.empty())
                color = glm::mix(color, ramp_value(m.ramp, modifier_input(in, m.input, m.range_min, m.range_max)),
                                 m.influence);
        out.color[i] = color;
    }
    return out;
}

void append_styled_stroke(const ScreenPath& path, const StrokeParams& param, const LineSetStyle& style,
                          float period_px, std::vector<StrokeVertex>& out) {
    ScreenPath shaped = path;
    apply_geometry_modifiers(shaped, param, period_px, style.geometry);
    if (shaped.samples.empty()) return;
    const StrokeSpan whole = stroke_span(shaped);
    for (const ScreenPath& piece : dash_path(shaped, param, period_px, style.dashes)) {
        if (piece.samples.empty()) continue;
        append_stroke(piece, param, evaluate_attributes(piece, style, whole), style.cap, style.join, out);
    }
}

}  // namespace lw
