#include "stroke/stroke_geometry.h"

#include <algorithm>
#include <cmath>

namespace lw {

namespace {

// ---- The line-set builder (caps, joins, per-sample attributes) ----

constexpr float kPi = 3.14159265358979f;
constexpr float kMergePx = 1e-4f;         // closer samples are one node
constexpr float kStraightCos = 0.99985f;  // cos 1°: straighter turns need no round-join fan
constexpr int kHalfDiscSegments = 16;

glm::vec2 unit_or_zero(glm::vec2 d) {
    const float len = glm::length(d);
    return len > 0.0f ? d / len : glm::vec2(0.0f);
}
// The normal of a direction d: (−dy, dx), the v = 0 side.
glm::vec2 perp(glm::vec2 d) { return {-d.y, d.x}; }
glm::vec2 rotate(glm::vec2 v, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}
float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// One sample after coincident samples are merged.
struct Node {
    glm::vec2 p;
    float s;
    float half;      // half width of the outline, pixels (at least 1e-3, so that it has directions)
    float ink_half;  // the sample's half width, ≥ 0: a zero-width stroke is drawn without ink
    glm::vec4 color;
    glm::vec2 d_in{0.0f}, d_out{0.0f};  // unit directions of the adjacent segments; 0 at open ends
};

std::vector<Node> make_nodes(const ScreenPath& path, const StrokeAttributes& attributes) {
    std::vector<Node> nodes;
    for (size_t i = 0; i < path.samples.size(); ++i) {
        const ScreenSample& q = path.samples[i];
        if (!nodes.empty() && glm::length(q.pixel - nodes.back().p) <= kMergePx) continue;
        const float half = 0.5f * std::max(attributes.width[i], 0.0f);
        nodes.push_back({q.pixel, q.s, std::max(half, 1e-3f), half, glm::vec4(attributes.color[i], attributes.alpha[i])});
    }
    if (path.closed)
        while (nodes.size() > 1 && glm::length(nodes.back().p - nodes.front().p) <= kMergePx) nodes.pop_back();
    // An open path of one segment gets a middle node: its end segments carry the distance
    // past their end for the coverage (append_body), one end each.
    if (!path.closed && nodes.size() == 2) {
        Node middle = nodes[0];
        middle.p = 0.5f * (nodes[0].p + nodes[1].p);
        middle.s = 0.5f * (nodes[0].s + nodes[1].s);
        middle.half = 0.5f * (nodes[0].half + nodes[1].half);
        middle.ink_half = 0.5f * (nodes[0].ink_half + nodes[1].ink_half);
        middle.color = 0.5f * (nodes[0].color + nodes[1].color);
        nodes.insert(nodes.begin() + 1, middle);
    }
    const size_t n = nodes.size();
    const size_t segments = n < 2 ? 0 : path.closed ? n : n - 1;
    for (size_t i = 0; i < segments; ++i) {
        const size_t j = (i + 1) % n;
        nodes[i].d_out = nodes[j].d_in = unit_or_zero(nodes[j].p - nodes[i].p);
    }
    return nodes;
}

float polyline_length(const std::vector<Node>& nodes, bool closed) {
    float length = 0.0f;
    for (size_t i = 1; i < nodes.size(); ++i) length += glm::length(nodes[i].p - nodes[i - 1].p);
    if (closed && nodes.size() > 1) length += glm::length(nodes.front().p - nodes.back().p);
    return length;
}

// How far a node's triangles reach out, over its outline: the coverage margin past it.
float outset_scale(const Node& nd, float margin) { return (nd.half + margin) / nd.half; }

struct Emitter {
    const StrokeParams& params;
    std::vector<StrokeVertex>& out;

    // The vertex drawn at `drawn_offset` from the node, with arc length s, v and coverage
    // coordinates `edge` (xyz; w is the node's half width) where it is drawn.
    StrokeVertex drawn(const Node& nd, glm::vec2 drawn_offset, float s, float v, glm::vec3 edge) const {
        const float u = params.fold.scale * (params.rho * s + params.phi);
        return {nd.p + drawn_offset, glm::vec3(u, v, params.fold.w), nd.color, glm::vec4(edge, nd.ink_half)};
    }
    // The vertex of the outline point at `offset` from the node (v and the coverage
    // coordinates `edge_xy`, `edge_z` given there), pushed out from the node by the margin.
    StrokeVertex at(const Node& nd, glm::vec2 offset, float s, float v, glm::vec2 edge_xy,
                    float edge_z = kNoEndZ) const {
        const float k = outset_scale(nd, params.coverage_margin_px);
        return drawn(nd, offset * k, s, 0.5f + (v - 0.5f) * k,
                     glm::vec3(edge_xy * k, edge_z == kNoEndZ ? kNoEndZ : edge_z * k));
    }
    // Off an end along tangent t: s continues along t, v follows the offset across (0.5 at
    // the centre, 0 at +half·perp(t), 1 at −half·perp(t)). Round ends measure coverage by
    // the distance to the end point, square ones across and along separately.
    StrokeVertex off_end(const Node& nd, glm::vec2 t, glm::vec2 offset, Cap cap) const {
        const float across = glm::dot(offset, perp(t)), along = glm::dot(offset, t);
        const float v = std::clamp(0.5f - 0.5f * across / nd.half, 0.0f, 1.0f);
        const float s = nd.s + along * outset_scale(nd, params.coverage_margin_px);
        if (cap == Cap::Round) return at(nd, offset, s, v, {across, along});
        return at(nd, offset, s, v, {across, 0.0f}, std::abs(along));
    }
    void triangle(const StrokeVertex& a, const StrokeVertex& b, const StrokeVertex& c) {
        out.insert(out.end(), {a, b, c});
    }
    // The quad a b d c (a, b across one end; c, d across the other, c on a's side).
    void quad(const StrokeVertex& a, const StrokeVertex& b, const StrokeVertex& c, const StrokeVertex& d) {
        triangle(a, b, c);
        triangle(c, b, d);
    }
    // Triangles around `centre` whose rim turns from offset `from` by `sweep` radians and ends
    // exactly at `to` (so that it meets the neighbouring quads' vertices bit for bit).
    template <class Rim>
    void fan(const StrokeVertex& centre, glm::vec2 from, glm::vec2 to, float sweep, int segments, Rim&& rim) {
        StrokeVertex prev = rim(from);
        for (int k = 1; k <= segments; ++k) {
            const StrokeVertex next = k == segments ? rim(to) : rim(rotate(from, sweep * float(k) / float(segments)));
            triangle(centre, prev, next);
            prev = next;
        }
    }
};

// Where a node's incoming and outgoing quads end, as offsets from its centre. Mitre joins
// (and the inner side of round joins) share one clamped mitre point; a round join's outer
// side ends each quad square to its own segment and a fan fills the wedge between.
struct JoinEnds {
    glm::vec2 in_plus, in_minus, out_plus, out_minus;
    int outer = 0;  // +1: a round-join fan on the v = 0 side, −1: on the v = 1 side, 0: none
};

// The mitre of a node's two segments along their bisector, clamped to `limit` half widths; a
// full reversal keeps the half width.
glm::vec2 mitre_offset(const Node& nd, float limit) {
    const glm::vec2 n_in = perp(nd.d_in), n_out = perp(nd.d_out);
    const glm::vec2 reference = glm::length(n_out) > 0.0f ? n_out : n_in;
    glm::vec2 mitre = n_in + n_out;
    const float len = glm::length(mitre);
    if (len <= 1e-6f) return reference * nd.half;
    mitre /= len;
    const float cos_half = std::max(glm::dot(mitre, reference), 1e-3f);
    return mitre * std::min(nd.half / cos_half, limit * nd.half);
}

JoinEnds join_ends(const Node& nd, Join join, float mitre_limit) {
    const glm::vec2 m = mitre_offset(nd, mitre_limit);
    JoinEnds e{m, -m, m, -m, 0};
    const bool interior = glm::length(nd.d_in) > 0.0f && glm::length(nd.d_out) > 0.0f;
    if (join != Join::Round || !interior || glm::dot(nd.d_in, nd.d_out) > kStraightCos) return e;
    // The path turns towards perp(d) when cross(d_in, d_out) > 0: the outer side is the other.
    e.outer = cross(nd.d_in, nd.d_out) > 0.0f ? -1 : 1;
    const float o = float(e.outer) * nd.half;
    (e.outer > 0 ? e.in_plus : e.in_minus) = perp(nd.d_in) * o;
    (e.outer > 0 ? e.out_plus : e.out_minus) = perp(nd.d_out) * o;
    return e;
}

void append_round_join(Emitter& em, const Node& nd, const JoinEnds& e) {
    const bool plus = e.outer > 0;
    const float v_outer = plus ? 0.0f : 1.0f;
    const glm::vec2 from = plus ? e.in_plus : e.in_minus, to = plus ? e.out_plus : e.out_minus;
    const glm::vec2 inner = plus ? e.in_minus : e.in_plus;
    // Coverage by the distance to the node: the rim is the outline. The inner mitre point, on
    // the outline too, mirrors `from` in the triangle that meets the incoming quad and `to` in
    // the one that meets the outgoing quad, so that each ramps like the body it borders (and
    // both agree on their shared side, the bisector).
    auto rim = [&](glm::vec2 offset) { return em.at(nd, offset, nd.s, v_outer, offset); };
    const StrokeVertex centre = em.at(nd, glm::vec2(0.0f), nd.s, 0.5f, glm::vec2(0.0f));
    const StrokeVertex in_from = em.at(nd, inner, nd.s, 1.0f - v_outer, -from);
    const StrokeVertex in_to = em.at(nd, inner, nd.s, 1.0f - v_outer, -to);
    // The centre lies inside (inner, from, to): two triangles close the gap to the fan.
    em.triangle(in_from, rim(from), centre);
    em.triangle(in_to, centre, rim(to));
    float sweep = std::atan2(cross(from, to), glm::dot(from, to));
    // A U-turn has no shorter side: go round ahead of the incoming direction.
    if (std::abs(sweep) > kPi - 1e-4f) sweep = plus ? -kPi : kPi;
    const int segments = std::max(1, int(std::ceil(std::abs(sweep) / kPi * float(kHalfDiscSegments))));
    em.fan(centre, from, to, sweep, segments, rim);
}

// The cap at an open end: t is the path's forward direction there, ahead = −1 at the start
// (the cap lies behind it) and +1 at the end.
void append_cap(Emitter& em, const Node& nd, glm::vec2 t, float ahead, Cap cap) {
    const glm::vec2 side = perp(t) * nd.half, out = t * (ahead * nd.half);
    auto rim = [&](glm::vec2 offset) { return em.off_end(nd, t, offset, cap); };
    const float margin = em.params.coverage_margin_px;
    if (cap == Cap::Butt && margin > 0.0f) {
        // The end's fringe: the margin past the end, z the half width plus the distance past
        // it (so that the shader's share before the end, at half − z, is a box filter's).
        const float k = outset_scale(nd, margin), z0 = nd.ink_half;
        const glm::vec2 p = side * k, q = t * (ahead * margin);
        const float s_out = nd.s + ahead * margin, v0 = 0.5f - 0.5f * k, v1 = 0.5f + 0.5f * k;
        const float x = nd.half * k;
        const StrokeVertex a = em.drawn(nd, p, nd.s, v0, {x, 0.0f, z0}), b = em.drawn(nd, -p, nd.s, v1, {-x, 0.0f, z0});
        const StrokeVertex c = em.drawn(nd, p + q, s_out, v0, {x, 0.0f, z0 + margin});
        const StrokeVertex d = em.drawn(nd, -p + q, s_out, v1, {-x, 0.0f, z0 + margin});
        em.quad(a, b, c, d);
    } else if (cap == Cap::Square) {
        const StrokeVertex a = rim(side), b = rim(-side), c = rim(side + out), d = rim(-side + out);
        em.quad(a, b, c, d);
    } else if (cap == Cap::Round) {
        // perp(t) turned by +90° is −t: +π sweeps behind the start, −π ahead of the end.
        em.fan(rim(glm::vec2(0.0f)), side, -side, ahead < 0.0f ? kPi : -kPi, kHalfDiscSegments, rim);
    }
}

// A path with no length to speak of: a disc or square of the widest sample's width at the
// midpoint of its ends, oriented along its chord (x when it has none).
void append_dot(Emitter& em, const std::vector<Node>& nodes, Cap cap) {
    Node centre = nodes[nodes.size() / 2];
    centre.p = 0.5f * (nodes.front().p + nodes.back().p);
    centre.s = 0.5f * (nodes.front().s + nodes.back().s);
    for (const Node& nd : nodes) {
        centre.half = std::max(centre.half, nd.half);
        centre.ink_half = std::max(centre.ink_half, nd.ink_half);
    }
    const glm::vec2 chord = unit_or_zero(nodes.back().p - nodes.front().p);
    const glm::vec2 t = glm::length(chord) > 0.0f ? chord : glm::vec2(1.0f, 0.0f);
    const glm::vec2 side = perp(t) * centre.half;
    auto rim = [&](glm::vec2 offset) { return em.off_end(centre, t, offset, cap); };
    if (cap == Cap::Round) {
        em.fan(rim(glm::vec2(0.0f)), side, side, 2.0f * kPi, 2 * kHalfDiscSegments, rim);
    } else if (cap == Cap::Square) {
        // Two halves, so that the distance along runs from 0 on the middle to each end.
        const glm::vec2 out = t * centre.half;
        const StrokeVertex a = rim(side - out), b = rim(-side - out), c = rim(side), d = rim(-side);
        const StrokeVertex e = rim(side + out), f = rim(-side + out);
        em.quad(a, b, c, d);
        em.quad(c, d, e, f);
    }
}

// The end segments of an open path with butt or square caps carry the distance past their
// end in edge.z (plus the half width for butt ends, as the fringe has it), measured along the
// end's tangent from where each vertex is drawn: so the pixels just before an end ramp too,
// as a box filter has them, instead of staying full up to it.
void mark_end_distance(StrokeVertex& v, const Node& end, glm::vec2 outward, Cap cap) {
    v.edge.z = glm::dot(v.pixel - end.p, outward) + (cap == Cap::Butt ? end.ink_half : 0.0f);
}

void append_body(Emitter& em, const std::vector<Node>& nodes, const std::vector<JoinEnds>& ends, bool closed,
                 Cap cap) {
    const size_t n = nodes.size();
    const size_t segments = closed ? n : n - 1;
    const bool end_ramps = !closed && cap != Cap::Round && segments >= 2;
    for (size_t i = 0; i < segments; ++i) {
        const size_t j = (i + 1) % n;
        const Node &a = nodes[i], &b = nodes[j];
        // The closing segment continues the arclength past the last sample.
        const float sb = j == 0 ? a.s + glm::length(b.p - a.p) : b.s;
        // Coverage by the signed distance across (the outline is half a width from the centre
        // line, on either side), which interpolates through 0 on the centre line.
        StrokeVertex a_plus = em.at(a, ends[i].out_plus, a.s, 0.0f, {a.half, 0.0f});
        StrokeVertex a_minus = em.at(a, ends[i].out_minus, a.s, 1.0f, {-a.half, 0.0f});
        StrokeVertex b_plus = em.at(b, ends[j].in_plus, sb, 0.0f, {b.half, 0.0f});
        StrokeVertex b_minus = em.at(b, ends[j].in_minus, sb, 1.0f, {-b.half, 0.0f});
        if (end_ramps && (i == 0 || i + 1 == segments)) {
            const Node& end = i == 0 ? nodes.front() : nodes.back();
            const glm::vec2 outward = i == 0 ? -nodes.front().d_out : nodes.back().d_in;
            for (StrokeVertex* v : {&a_plus, &a_minus, &b_plus, &b_minus}) mark_end_distance(*v, end, outward, cap);
        }
        em.quad(a_plus, a_minus, b_plus, b_minus);
    }
}

}  // namespace

void append_stroke(const ScreenPath& path, const StrokeParams& params, const StrokeAttributes& attributes,
                   Cap cap, Join join, std::vector<StrokeVertex>& out) {
    const size_t count = path.samples.size();
    if (count == 0 || attributes.width.size() != count || attributes.alpha.size() != count ||
        attributes.color.size() != count)
        return;
    const std::vector<Node> nodes = make_nodes(path, attributes);
    Emitter em{params, out};
    if (nodes.size() < 2 || polyline_length(nodes, path.closed) <= kDotLengthPx) {
        // Round caps make a 1-px stroke a disc of its width; butt caps keep their sliver.
        if (cap != Cap::Butt) return append_dot(em, nodes, cap);
        if (nodes.size() < 2) return;
    }
    std::vector<JoinEnds> ends;
    ends.reserve(nodes.size());
    for (const Node& nd : nodes) ends.push_back(join_ends(nd, join, params.mitre_limit));
    append_body(em, nodes, ends, path.closed, cap);
    for (size_t i = 0; i < nodes.size(); ++i)
        if (ends[i].outer != 0) append_round_join(em, nodes[i], ends[i]);
    if (path.closed) return;
    append_cap(em, nodes.front(), nodes.front().d_out, -1.0f, cap);
    append_cap(em, nodes.back(), nodes.back().d_in, 1.0f, cap);
}

}  // namespace lw
