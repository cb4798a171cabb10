#include "stroke/slam.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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
};

// The level-0.5 pattern P(u, v), u ∈ [0, 1) periodic, v ∈ [0, 1] across the stroke.
struct Pattern {
    SlamPattern kind;
    float half_length;  // on-screen texels of one period at level 0.5
    float height;
    std::vector<Element> elements;
    std::vector<float> grain_phase;  // pencil: phases of the periodic grain

    float operator()(float u, float v) const {
        const float dy = (v - 0.5f) * height;
        switch (kind) {
            case SlamPattern::Dots: {
                float ink = 0.0f;
                for (const auto& e : elements) {
                    const float dx = periodic_dx(u, e.center, half_length);
                    ink = std::max(ink, soft(e.size - std::sqrt(dx * dx + dy * dy)));
                }
                return ink;
            }
            case SlamPattern::Dashes: {
                float ink = 0.0f;
                for (const auto& e : elements) {
                    // A capsule: a segment of half length e.size with round ends.
                    const float dx = std::max(std::abs(periodic_dx(u, e.center, half_length)) - e.size, 0.0f);
                    ink = std::max(ink, soft(e.thickness - std::sqrt(dx * dx + dy * dy)));
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

}  // namespace

Slam make_procedural_slam(SlamPattern pattern, int levels, int length, int height, uint32_t seed) {
    if (levels < 2 || length < 4 || height < 1 || length % 2 != 0)
        throw Error("procedural SLAM: needs at least 2 levels and an even length");
    const char* names[] = {"dots", "dashes", "pencil"};
    Slam slam{levels, length, height, std::vector<float>(size_t(levels) * height * length), "", seed};
    slam.exemplar = std::string("procedural:") + names[int(pattern)];
    const Pattern p = make_pattern(pattern, length, height, seed);
    for (int row = 0; row < height; ++row) {
        const float v = (float(row) + 0.5f) / float(height);
        for (int x = 0; x < length; ++x) {
            const float u = float(x) / float(length);
            const float single = p(u, v), doubled = p(std::fmod(2.0f * u, 1.0f), v);
            for (int i = 0; i < levels; ++i) {
                const float alpha = 2.0f * slam.level_value(i) - 1.0f;
                slam.at(i, row, x) = (1.0f - alpha) * single + alpha * doubled;
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

Slam solid_slam() {
    Slam slam{.levels = 2, .length = 4, .height = 2, .exemplar = "procedural:solid"};
    slam.ink.assign(size_t(slam.levels) * slam.length * slam.height, 1.0f);
    return slam;
}

}  // namespace lw
