#include "stroke/slam.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.h"

namespace lw {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Ink of a soft-edged disc/segment: 1 inside, 0 outside, a 1.5-texel ramp between.
float soft(float inside_distance) { return std::clamp(inside_distance / 1.5f + 0.5f, 0.0f, 1.0f); }

// Periodic distance along u in texels of the level-0.5 texture (which is `length`/2 long on
// screen at native density: one u period = `half_length` texels).
float periodic_dx(float u, float center, float half_length) {
    float d = u - center;
    d -= std::round(d);
    return d * half_length;
}

struct Element {
    float center;  // u
    float size;    // radius (dots) or half length (dashes), texels
    float thickness;
    float weight = 1.0f;  // ink of an element growing from nothing, which fades in with its size
};

// The level-0.5 pattern P(u, v), u ∈ [0, 1) periodic, v ∈ [0, 1] across the stroke.
struct Pattern {
    SlamPattern kind;
    float half_length;  // on-screen texels of one period at level 0.5
    float height;
    std::vector<Element> elements;
    std::vector<float> grain_phase;  // pencil: phases of the periodic grain

    float operator()(float u, float v) const { return ink(u, v, elements, 1.0f); }

    // The ink of `shown` elements at (u, v), u's distances scaled by `squeeze` (a level's
    // period spans 1 + a times the screen length of level 0.5's, so that an element keeps
    // its shape on the screen; 1 at level 0.5).
    float ink(float u, float v, const std::vector<Element>& shown, float squeeze) const {
        const float dy = (v - 0.5f) * height;
        switch (kind) {
            case SlamPattern::Dots: {
                float ink = 0.0f;
                for (const auto& e : shown) {
                    const float dx = squeeze * periodic_dx(u, e.center, half_length);
                    ink = std::max(ink, e.weight * soft(e.size - std::sqrt(dx * dx + dy * dy)));
                }
                return ink;
            }
            case SlamPattern::Dashes: {
                float ink = 0.0f;
                for (const auto& e : shown) {
                    // A capsule: a segment of half length e.size with round ends.
                    const float dx = std::max(std::abs(squeeze * periodic_dx(u, e.center, half_length)) - e.size, 0.0f);
                    ink = std::max(ink, e.weight * soft(e.thickness - std::sqrt(dx * dx + dy * dy)));
                }
                return ink;
            }
            case SlamPattern::Pencil: {
                // A soft core across the width, broken by grain periodic in u (integer
                // frequencies keep the texture seamless).
                const float across = std::exp(-(dy * dy) / (2.0f * 0.16f * height * 0.16f * height));
                float grain = 0.0f;
                for (size_t k = 0; k < grain_phase.size(); ++k) {
                    const float f = float(8 + 13 * k);
                    grain += std::sin(2.0f * kPi * f * u + grain_phase[k] + 3.1f * v * float(k + 1));
                }
                grain /= float(std::max<size_t>(grain_phase.size(), 1));
                return std::clamp(across * (0.72f + 0.45f * grain), 0.0f, 1.0f);
            }
        }
        return 0.0f;
    }
};

Pattern make_pattern(SlamPattern kind, int length, int height, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-1.0f, 1.0f);
    Pattern p{kind, 0.5f * float(length), float(height), {}, {}};
    const int count = kind == SlamPattern::Dots ? 8 : kind == SlamPattern::Dashes ? 5 : 0;
    for (int i = 0; i < count; ++i) {
        const float center = (float(i) + 0.5f + 0.2f * jitter(rng)) / float(count);
        if (kind == SlamPattern::Dots)
            p.elements.push_back({center, float(height) * (0.24f + 0.06f * jitter(rng)), 0.0f});
        else
            p.elements.push_back({center, p.half_length / float(count) * (0.28f + 0.06f * jitter(rng)),
                                  float(height) * (0.16f + 0.03f * jitter(rng))});
    }
    if (kind == SlamPattern::Pencil)
        for (int k = 0; k < 5; ++k) p.grain_phase.push_back(kPi * (1.0f + jitter(rng)));
    return p;
}

// The elements of level a ∈ (0, 1) (a = 2l − 1) of a dots or dashes SLAM. Level 1 is level
// 0.5 twice over (P(2u)): each element c appears at c/2 and (c + 1)/2. Between, each element
// of level 0.5 moves to one of those places and the others grow from nothing, so that every
// level shows whole elements: an alpha blend of P(u) and P(2u) would show both patterns at
// once, half inked, the "blending artifacts" and "perceptually degraded high-contrast
// structured patterns" of the paper's §2 that its synthesized levels avoid. Each old element
// goes to a place in order (the matching of least total travel that keeps their order, so
// that no two cross), and moves and resizes linearly in a.
std::vector<Element> level_elements(const std::vector<Element>& base, float a) {
    std::vector<Element> old = base, doubled;
    std::sort(old.begin(), old.end(), [](const Element& x, const Element& y) { return x.center < y.center; });
    for (const Element& e : old) {
        doubled.push_back({e.center / 2.0f, e.size, e.thickness, 1.0f});
        doubled.push_back({(e.center + 1.0f) / 2.0f, e.size, e.thickness, 1.0f});
    }
    std::sort(doubled.begin(), doubled.end(), [](const Element& x, const Element& y) { return x.center < y.center; });
    const size_t n = old.size(), m = doubled.size();
    // cost[i][k]: old 0..i−1 matched in order into doubled 0..k−1.
    constexpr float kNone = std::numeric_limits<float>::infinity();
    std::vector<std::vector<float>> cost(n + 1, std::vector<float>(m + 1, kNone));
    for (size_t k = 0; k <= m; ++k) cost[0][k] = 0.0f;
    for (size_t i = 1; i <= n; ++i)
        for (size_t k = i; k <= m; ++k)
            cost[i][k] = std::min(cost[i][k - 1], cost[i - 1][k - 1] + std::abs(old[i - 1].center - doubled[k - 1].center));
    std::vector<int> match_of(m, -1);  // doubled place → old element
    for (size_t i = n, k = m; i > 0; --k)
        if (cost[i][k] != cost[i][k - 1]) match_of[k - 1] = int(--i);
    std::vector<Element> out;
    for (size_t k = 0; k < m; ++k) {
        const Element& to = doubled[k];
        if (match_of[k] < 0) {
            // Grows from nothing; its ink fades in while it is under the 1.5-texel edge ramp,
            // and is whole at a = 1 however thin the element (a SLAM a few texels high).
            const float full = to.thickness > 0.0f ? to.thickness : to.size;
            out.push_back({to.center, a * to.size, a * to.thickness, std::min(1.0f, a * std::max(full / 1.5f, 1.0f))});
            continue;
        }
        const Element& from = old[size_t(match_of[k])];
        out.push_back({from.center + a * (to.center - from.center), from.size + a * (to.size - from.size),
                       from.thickness + a * (to.thickness - from.thickness), 1.0f});
    }
    return out;
}

}  // namespace

Slam make_procedural_slam(SlamPattern pattern, int levels, int length, int height, uint32_t seed) {
    if (levels < 2 || length < 4 || height < 1 || length % 2 != 0)
        throw Error("procedural SLAM: needs at least 2 levels and an even length");
    const char* names[] = {"dots", "dashes", "pencil"};
    Slam slam{levels, length, height, std::vector<float>(size_t(levels) * height * length), "", seed};
    slam.exemplar = std::string("procedural:") + names[int(pattern)];
    const Pattern p = make_pattern(pattern, length, height, seed);
    const bool elements = pattern != SlamPattern::Pencil;
    std::vector<std::vector<Element>> shown(static_cast<size_t>(levels));
    for (int i = 1; elements && i + 1 < levels; ++i) shown[size_t(i)] = level_elements(p.elements, 2.0f * slam.level_value(i) - 1.0f);
    for (int row = 0; row < height; ++row) {
        const float v = (float(row) + 0.5f) / float(height);
        for (int x = 0; x < length; ++x) {
            const float u = float(x) / float(length);
            // Levels 0.5 and 1 exactly P(u) and P(2u), so that self-similarity holds to the bit.
            const float single = p(u, v), doubled = p(std::fmod(2.0f * u, 1.0f), v);
            for (int i = 0; i < levels; ++i) {
                const float a = 2.0f * slam.level_value(i) - 1.0f;
                if (i == 0 || i + 1 == levels || !elements)  // pencil's grain has no elements: blended
                    slam.at(i, row, x) = i == 0 ? single : i + 1 == levels ? doubled : (1.0f - a) * single + a * doubled;
                else
                    slam.at(i, row, x) = p.ink(u, v, shown[size_t(i)], 1.0f + a);
            }
        }
    }
    return slam;
}

float slam_self_similarity_error(const Slam& slam) {
    float worst = 0.0f;
    const int top = slam.levels - 1;
    for (int row = 0; row < slam.height; ++row)
        for (int x = 0; x < slam.length; ++x)
            worst = std::max(worst, std::abs(slam.at(top, row, x) - slam.at(0, row, (2 * x) % slam.length)));
    return worst;
}

float slam_max_level_step(const Slam& slam) {
    float worst = 0.0f;
    for (int i = 0; i + 1 < slam.levels; ++i)
        for (int row = 0; row < slam.height; ++row)
            for (int x = 0; x < slam.length; ++x)
                worst = std::max(worst, std::abs(slam.at(i, row, x) - slam.at(i + 1, row, x)));
    return worst;
}

std::vector<float> slam_level_steps(const Slam& slam) {
    std::vector<float> steps;
    const size_t per_level = size_t(slam.height) * size_t(slam.length);
    for (int i = 0; i + 1 < slam.levels; ++i) {
        double sum = 0.0;
        for (size_t t = 0; t < per_level; ++t)
            sum += std::abs(slam.ink[size_t(i) * per_level + t] - slam.ink[size_t(i + 1) * per_level + t]);
        steps.push_back(float(sum / double(per_level)));
    }
    return steps;
}

float slam_mean_level_step(const Slam& slam) {
    const std::vector<float> steps = slam_level_steps(slam);
    double sum = 0.0;
    for (const float step : steps) sum += step;
    return steps.empty() ? 0.0f : float(sum / double(steps.size()));
}

Slam solid_slam() {
    Slam slam{.levels = 2, .length = 4, .height = 2, .exemplar = "procedural:solid"};
    slam.ink.assign(size_t(slam.levels) * slam.length * slam.height, 1.0f);
    return slam;
}

}  // namespace lw
