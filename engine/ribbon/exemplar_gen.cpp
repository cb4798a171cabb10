#include "ribbon/exemplar_gen.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/glm.hpp>

#include "core/color.h"
#include "core/error.h"
#include "core/random.h"
#include "ribbon/dp.h"

namespace lw {

namespace {

using glm::vec2;
using glm::vec3;

// What a pattern shows at a point: its signed distance (pixels, negative inside) and colour.
struct Sample {
    float d = 1e9f;
    vec3 rgb{0.0f};
};
using Shader = std::function<Sample(vec2)>;

// Deterministic uniform numbers in [lo, hi).
class Random {
public:
    explicit Random(uint64_t seed) : state_(mix64(seed)) {}
    float uniform(float lo, float hi) {
        state_ = mix64(state_);
        return lo + (hi - lo) * float(state_ >> 40) / float(1u << 24);
    }
    int pick(int n) { return std::min(n - 1, int(uniform(0.0f, float(n)))); }

private:
    uint64_t state_;
};

float segment_distance(vec2 p, vec2 a, vec2 b) {
    const vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

// Approximate signed distance to an axis-aligned ellipse with semi-axes `r` (Quilez).
float ellipse_distance(vec2 p, vec2 r) {
    const float k0 = glm::length(p / r), k1 = glm::length(p / (r * r));
    return k1 > 0.0f ? k0 * (k0 - 1.0f) / k1 : -std::min(r.x, r.y);
}

// Union keeping the colour of the nearer (more inside) shape.
void unite(Sample& s, float d, vec3 rgb) {
    if (d < s.d) s = {d, rgb};
}

// A bevel-like shading: lighter towards the middle of the stroke.
vec3 bevel(vec3 base, float d, float half_width) {
    const float f = std::clamp(-d / std::max(half_width, 1e-3f), 0.0f, 1.0f);
    return base * (0.55f + 0.45f * f) + vec3(0.25f) * f * f;
}

Shader chain(int width, int height, Random& rnd) {
    // Flat links (elliptical rings) in a row with gaps, and between each pair a link seen
    // edge-on (a flat ellipse) reaching into both rings. Elliptical, so that no two columns of
    // the exemplar are alike over a piece's width: straight link sides would let the
    // synthesizer repeat one column for ever.
    struct Link {
        float cx, a, b;
        bool flat;
    };
    const float cy = 0.5f * float(height), s = float(height) / 36.0f;
    const float t = 2.6f * s, r = 8.0f * s;  // ring half thickness, flat links' vertical semi-axis
    std::vector<Link> flat;
    for (float x = -20.0f * s; x < float(width) + 40.0f * s;) {
        const float a = rnd.uniform(11.0f, 14.5f) * s;
        flat.push_back({x + a + t, a, r, true});
        x += 2.0f * (a + t) + rnd.uniform(2.0f, 5.0f) * s;
    }
    std::vector<Link> links = flat;
    for (size_t i = 0; i + 1 < flat.size(); ++i) {
        const float gap_left = flat[i].cx + flat[i].a, gap_right = flat[i + 1].cx - flat[i + 1].a;
        const float reach = 0.45f * std::min(flat[i].a, flat[i + 1].a);
        links.push_back({0.5f * (gap_left + gap_right), 0.5f * (gap_right - gap_left) + reach, 2.8f * s, false});
    }
    return [=](vec2 p) {
        Sample out;
        for (const Link& l : links) {
            if (std::abs(p.x - l.cx) > l.a + 2.0f * t) continue;
            const vec2 q(p.x - l.cx, p.y - cy);
            if (l.flat) {
                const float d = std::abs(ellipse_distance(q, {l.a, l.b})) - t;
                unite(out, d, bevel({0.62f, 0.64f, 0.68f}, d, t));
            } else {
                const float d = ellipse_distance(q, {l.a, l.b});
                unite(out, d - 0.01f, bevel({0.50f, 0.52f, 0.56f}, d, l.b));
            }
        }
        return out;
    };
}

Shader lace(int width, int height, Random& rnd) {
    struct Scallop {
        float cx, r, eyelet;
    };
    const float s = float(height) / 36.0f, top = 0.3f * float(height);
    std::vector<Scallop> scallops;
    for (float x = -10.0f * s; x < float(width) + 20.0f * s;) {
        const float r = rnd.uniform(7.5f, 11.0f) * s;
        scallops.push_back({x + r, r, rnd.uniform(1.8f, 3.2f) * s});
        x += 2.0f * r;
    }
    const vec3 thread{0.42f, 0.32f, 0.62f};
    return [=](vec2 p) {
        Sample out;
        // The heading: two parallel threads.
        unite(out, std::abs(p.y - (top - 4.0f * s)) - 1.0f * s, thread * 0.9f);
        unite(out, std::abs(p.y - top) - 1.3f * s, thread);
        for (const Scallop& c : scallops) {
            if (std::abs(p.x - c.cx) > c.r + 4.0f * s) continue;
            const vec2 centre(c.cx, top);
            const float ring = std::abs(glm::length(p - centre) - c.r) - 1.3f * s;
            if (p.y >= top) unite(out, ring, thread);  // the lower half-circle
            const vec2 eye(c.cx, top + 0.5f * c.r);
            unite(out, std::abs(glm::length(p - eye) - c.eyelet) - 0.9f * s, thread * 0.95f);
            const vec2 picot(c.cx, top + c.r + 2.6f * s);
            unite(out, glm::length(p - picot) - 1.5f * s, thread);
            // A spoke from the eyelet up to the heading.
            unite(out, segment_distance(p, {c.cx, top}, {c.cx, top + 0.5f * c.r - c.eyelet}) - 0.7f * s, thread * 0.9f);
        }
        return out;
    };
}

Shader zigzag(int width, int height, Random& rnd) {
    const float s = float(height) / 36.0f, cy = 0.5f * float(height);
    std::vector<vec2> points;
    bool up = true;
    for (float x = -16.0f * s; x < float(width) + 32.0f * s; x += rnd.uniform(9.0f, 15.0f) * s) {
        points.push_back({x, cy + (up ? -1.0f : 1.0f) * rnd.uniform(7.0f, 10.0f) * s});
        up = !up;
    }
    const vec3 colours[2] = {{0.80f, 0.18f, 0.14f}, {0.92f, 0.52f, 0.10f}};
    return [=](vec2 p) {
        Sample out;
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            const vec2 a = points[i], b = points[i + 1];
            if (p.x < std::min(a.x, b.x) - 6.0f * s || p.x > std::max(a.x, b.x) + 6.0f * s) continue;
            const float d = segment_distance(p, a, b) - 2.2f * s;
            unite(out, d, bevel(colours[i % 2], d, 2.2f * s));
            if (i % 2 == 0 && i + 2 < points.size()) {  // a dot in every other bay
                const vec2 dot((a.x + points[i + 2].x) * 0.5f, (a.y + 2.0f * b.y) / 3.0f);
                unite(out, glm::length(p - dot) - 1.8f * s, {0.15f, 0.25f, 0.55f});
            }
        }
        return out;
    };
}

Shader beads(int width, int height, Random& rnd) {
    struct Bead {
        vec2 c;
        float rx, ry;
        vec3 rgb;
    };
    const float s = float(height) / 36.0f, cy = 0.5f * float(height);
    const vec3 palette[4] = {{0.75f, 0.12f, 0.16f}, {0.14f, 0.30f, 0.72f}, {0.85f, 0.66f, 0.18f}, {0.16f, 0.55f, 0.30f}};
    std::vector<Bead> list;
    for (float x = -10.0f * s; x < float(width) + 20.0f * s;) {
        const float r = rnd.uniform(4.0f, 9.0f) * s;
        const bool oval = rnd.uniform(0.0f, 1.0f) < 0.3f;
        const float rx = oval ? r * 1.4f : r;
        list.push_back({{x + rx, cy}, rx, r, palette[rnd.pick(4)]});
        x += 2.0f * rx + rnd.uniform(1.5f, 5.0f) * s;
    }
    return [=](vec2 p) {
        Sample out;
        unite(out, std::abs(p.y - cy) - 0.9f * s, {0.35f, 0.25f, 0.15f});  // the string
        for (const Bead& b : list) {
            if (std::abs(p.x - b.c.x) > b.rx + 2.0f) continue;
            const vec2 q = (p - b.c) / vec2(b.rx, b.ry);
            const float d = (glm::length(q) - 1.0f) * std::min(b.rx, b.ry);
            const float highlight = std::max(0.0f, 1.0f - glm::length(q - vec2(-0.35f, -0.35f)) * 2.2f);
            unite(out, d - 0.02f, glm::min(vec3(1.0f), bevel(b.rgb, d, std::min(b.rx, b.ry)) + vec3(0.6f) * highlight));
        }
        return out;
    };
}

Shader rope(int width, int height, Random& rnd) {
    const float s = float(height) / 36.0f, cy = 0.5f * float(height), radius = 10.0f * s;
    std::vector<float> strands;
    for (float x = -16.0f * s; x < float(width) + 32.0f * s; x += rnd.uniform(6.0f, 8.5f) * s) strands.push_back(x);
    const vec3 fibre{0.76f, 0.60f, 0.36f};
    return [=](vec2 p) {
        Sample out;
        float second = 1e9f;
        for (float x : strands) {
            if (std::abs(p.x - x) > radius + 8.0f * s) continue;
            const float d = segment_distance(p, {x - 5.0f * s, cy + radius - 2.5f * s}, {x + 5.0f * s, cy - radius + 2.5f * s}) -
                            3.4f * s;
            if (d < out.d) {
                second = out.d;
                out = {d, bevel(fibre, d, 3.4f * s)};
            } else {
                second = std::min(second, d);
            }
        }
        // A dark groove where two strands meet.
        if (out.d < 0.0f && second - out.d < 1.2f * s) out.rgb *= 0.55f;
        return out;
    };
}

}  // namespace

const std::vector<std::string>& exemplar_names() {
    static const std::vector<std::string> names{"chain", "lace", "zigzag", "beads", "rope"};
    return names;
}

ImageRGBA8 generate_exemplar(const std::string& name, int width, int height, uint64_t seed) {
    if (width < 16 || height < 16 || width > 4096 || height > 4096)
        throw ParameterError("exemplar size", " " + std::to_string(width) + "x" + std::to_string(height) +
                                                  ": must be between 16x16 and 4096x4096");
    uint64_t name_hash = 1469598103934665603ull;  // FNV-1a: the same on every platform
    for (char c : name) name_hash = (name_hash ^ uint8_t(c)) * 1099511628211ull;
    Random rnd(seed ^ name_hash);
    Shader shader;
    if (name == "chain") shader = chain(width, height, rnd);
    else if (name == "lace") shader = lace(width, height, rnd);
    else if (name == "zigzag") shader = zigzag(width, height, rnd);
    else if (name == "beads") shader = beads(width, height, rnd);
    else if (name == "rope") shader = rope(width, height, rnd);
    else throw usage_error("unknown exemplar \"" + name + "\" (chain, lace, zigzag, beads or rope)");

    ImageRGBA8 image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 0)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Sample sample = shader({float(x) + 0.5f, float(y) + 0.5f});
            const float alpha = std::clamp(0.5f - sample.d, 0.0f, 1.0f);
            const auto a = uint8_t(std::lround(alpha * 255.0f));
            if (a == 0) continue;
            uint8_t* px = image.at(x, y);
            for (int c = 0; c < 3; ++c) px[c] = unit_to_byte(sample.rgb[c]);
            px[3] = a;
        }
    return image;
}

}  // namespace lw
