#include "pattern/synthesis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "core/error.h"
#include "core/random.h"
#include "core/text.h"
#include "core/timer.h"
#include "pattern/lloyd.h"
#include "pattern/variation.h"

namespace lw {

namespace {

glm::vec2 rotate(glm::vec2 v, float a) {
    const float c = std::cos(a), s = std::sin(a);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// A path with arc length, for (s, t) frame coordinates: s along the path, t along its left
// normal (−tangent.y, tangent.x).
struct PathFrame {
    ArclengthCurve curve;
    float h;  // half chord for tangents
    explicit PathFrame(const Curve2D& c) : curve(c), h(std::max(1e-3f, 0.01f * curve.length())) {}

    float tangent_angle(float s) const {
        const glm::vec2 t = curve.tangent_at(s, h);
        return std::atan2(t.y, t.x);
    }
    glm::vec2 to_world(glm::vec2 st) const {
        const glm::vec2 t = curve.tangent_at(st.x, h);
        return curve.point_at(st.x) + st.y * glm::vec2(-t.y, t.x);
    }
    // The nearest point of the polyline: its arc length and the signed offset.
    glm::vec2 to_frame(glm::vec2 p) const {
        const auto& pts = curve.points();
        const size_t segments = curve.closed() ? pts.size() : pts.size() - 1;
        float best = INFINITY, best_s = 0.0f, run = 0.0f;
        for (size_t i = 0; i < segments; ++i) {
            const glm::vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
            const glm::vec2 ab = b - a;
            const float l2 = glm::dot(ab, ab), l = std::sqrt(l2);
            const float f = l2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / l2, 0.0f, 1.0f) : 0.0f;
            const float d = glm::length(p - (a + f * ab));
            if (d < best) best = d, best_s = run + f * l;
            run += l;
        }
        const glm::vec2 t = curve.tangent_at(best_s, h);
        return {best_s, glm::dot(p - curve.point_at(best_s), glm::vec2(-t.y, t.x))};
    }
};

std::vector<glm::vec2> region_polygon(const PatternFrame& f) {
    std::vector<glm::vec2> poly = f.curve.points;
    if (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    return poly;
}

float median(std::vector<float> v) {
    if (v.empty()) return 0.0f;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The §3.1 score of averaged measures: below 1 iff col ∧ (shape ∨ (par ∧ ov ∧ sup)).
float combine(float shape, float par, float ov, float sup, float col, const PatternThresholds& s, float L) {
    const float geometric = std::max({par / s.par, (ov - 1.0f) / (s.ov - 1.0f), sup / (s.sup * L)});
    return std::max(col / s.col, std::min(shape / (s.shape * L), geometric));
}

}  // namespace

PatternFrame bounding_frame(const std::vector<Stroke>& strokes, bool along_path) {
    const Box2 b = stroke_bounds(strokes);
    PatternFrame f;
    f.along_path = along_path;
    if (along_path) {
        const glm::vec2 c = b.center();
        if (b.extent().x >= b.extent().y) f.curve.points = {{b.lo.x, c.y}, {b.hi.x, c.y}};
        else f.curve.points = {{c.x, b.lo.y}, {c.x, b.hi.y}};
    } else {
        f.curve.points = {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}};
        f.curve.closed = true;
    }
    return f;
}

float frame_measure(const PatternFrame& frame) {
    if (frame.along_path) return ArclengthCurve(frame.curve).length();
    const std::vector<glm::vec2> poly = region_polygon(frame);
    const float area = poly.size() >= 3 ? polygon_area(poly) : 0.0f;
    // No area (a line, a bow tie's cancelling halves) is the caller's message; an area that
    // is what is left of lobes cancelling is not the region's.
    if (area > 0.0f && !polygon_is_simple(poly))
        throw Error("the region crosses itself (or runs over its own edge): a region is a simple closed curve");
    return area;
}

PatternAnalysis analyze_pattern(std::vector<Stroke> strokes, const PatternFrame& frame, const PatternDesc& desc) {
    if (strokes.empty()) throw Error("the reference has no strokes");
    PatternAnalysis a;
    a.strokes = std::move(strokes);
    a.frame = frame;
    a.measure = frame_measure(frame);
    if (!(a.measure > 0.0f))
        throw Error(frame.along_path ? "the reference path has no length" : "the reference region has no area");
    if (desc.epsilon > 0.0f) {
        a.epsilon = desc.epsilon;
    } else {
        std::vector<float> widths;
        for (const Stroke& s : a.strokes) widths.push_back(mean_width(s));
        a.epsilon = std::max(2.0f * median(widths), 1e-3f);
    }
    a.elements = cluster_strokes(a.strokes, a.epsilon, desc.fit);  // §2.1, §2.2
    const size_t n = a.elements.size();

    // §2.3: the distribution, in frame coordinates.
    std::vector<glm::vec2> positions(n);
    a.frame_angle.assign(n, 0.0f);
    if (frame.along_path) {
        const PathFrame path(frame.curve);
        for (size_t i = 0; i < n; ++i) {
            positions[i] = path.to_frame(a.elements[i].center);
            a.frame_angle[i] = path.tangent_angle(positions[i].x);
        }
        a.distribution = chain_distribution(positions, path.curve.closed() ? path.curve.length() : 0.0f);
    } else {
        for (size_t i = 0; i < n; ++i) positions[i] = a.elements[i].center;
        a.distribution = delaunay_distribution(positions);
    }
    a.local = a.elements;
    float total_length = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        a.local[i].center = glm::vec2(0.0f);
        a.local[i].axis = rotate(a.elements[i].axis, -a.frame_angle[i]);
        total_length += a.elements[i].length();
    }
    a.mean_length = std::max(total_length / float(n), 1e-3f);

    // The start element: nearest the centre of the reference elements.
    glm::vec2 centre(0.0f);
    for (const glm::vec2& p : positions) centre += p;
    centre /= float(n);
    float best = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        const float d = glm::length(a.distribution.wrapped(positions[i] - centre));
        if (d < best) best = d, a.start = int(i);
    }

    // §3.1 measures between every pair of reference elements, centres aligned.
    a.shape.resize(n * n);
    a.par.resize(n * n);
    a.ov.resize(n * n);
    a.sup.resize(n * n);
    a.col.resize(n * n);
    const float tiny = 1e-3f * a.mean_length;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) {
            const Element &ei = a.local[i], &ej = a.local[j];
            const size_t k = i * n + j;
            a.shape[k] = std::max(directed_hausdorff(ei, ej), directed_hausdorff(ej, ei));
            a.par[k] = axis_angle(ei.axis, ej.axis);
            const float li = std::max(ei.length(), tiny), lj = std::max(ej.length(), tiny);
            a.ov[k] = std::max(li / lj, lj / li);
            a.sup[k] = std::abs(ei.width() - ej.width());
            a.col[k] = glm::length(ei.color - ej.color);
        }
    return a;
}

std::string pattern_analysis_warning(const PatternAnalysis& a) {
    if (a.elements.size() != 1 || a.strokes.size() < 2) return {};
    return "its " + std::to_string(a.strokes.size()) + " strokes are one element at scale ε = " + number_text(a.epsilon) +
           ": there is no arrangement to follow, and the output copies the whole reference once per seed (a "
           "smaller scale parts it into elements)";
}

PatternSynthesis synthesize_pattern(const PatternAnalysis& ref, const PatternFrame& target, const PatternDesc& desc) {
    Timer total;
    PatternSynthesis out;
    Rng rng(desc.seed);
    const size_t n_ref = ref.elements.size();
    const float target_measure = frame_measure(target);
    if (!(target_measure > 0.0f))
        throw Error(target.along_path ? "the target path has no length" : "the target region has no area");
    // §3.2: N_tar = N_ref · A_tar / A_ref.
    const double wanted = double(n_ref) * double(target_measure) / double(ref.measure);
    if (wanted > 200000.0) throw Error("the target would hold " + std::to_string(int64_t(wanted)) + " elements (over 200000)");
    const int count = std::max(1, int(std::lround(wanted)));

    // Seeds by Lloyd, then their distribution (§3.2).
    Timer lloyd;
    std::vector<glm::vec2> seeds;
    std::optional<PathFrame> path;
    if (target.along_path) {
        path.emplace(target.curve);
        for (float s : lloyd_1d(count, path->curve.length(), path->curve.closed(), desc.lloyd_iterations, rng))
            seeds.push_back({s, 0.0f});
        out.target = chain_distribution(seeds, path->curve.closed() ? path->curve.length() : 0.0f);
    } else {
        seeds = lloyd_2d(region_polygon(target), count, desc.lloyd_iterations, rng);
        out.target = delaunay_distribution(seeds);
    }
    out.lloyd_ms = lloyd.elapsed_ms();
    const Distribution& tar = out.target;
    const size_t n_tar = seeds.size();
    const int k = desc.rings > 0 ? desc.rings : (target.along_path ? 3 : 2);
    out.rings = k;

    // Reference neighbourhoods with offsets from their centre element.
    Timer match;
    std::vector<std::vector<int>> ref_ring(n_ref);
    std::vector<std::vector<glm::vec2>> ref_offset(n_ref);
    for (size_t r = 0; r < n_ref; ++r) {
        ref_ring[r] = k_ring(ref.distribution, int(r), k);
        for (int q : ref_ring[r]) ref_offset[r].push_back(ref.distribution.delta(int(r), q));
    }

    // Growing outward from the seed nearest the target's centre (Algorithm 1).
    glm::vec2 centre(0.0f);
    for (const glm::vec2& p : seeds) centre += p;
    centre /= float(n_tar);
    std::vector<int> order(n_tar);
    std::iota(order.begin(), order.end(), 0);
    std::vector<float> dist(n_tar);
    for (size_t i = 0; i < n_tar; ++i) dist[i] = glm::length(tar.wrapped(seeds[i] - centre));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist[size_t(a)] < dist[size_t(b)]; });

    std::vector<int> assigned(n_tar, -1);
    std::vector<int> known;
    std::vector<glm::vec2> known_offset;
    std::vector<int> candidates;
    std::vector<float> scores(n_ref);
    const float L = ref.mean_length;
    for (size_t step = 0; step < n_tar; ++step) {
        const int j = order[step];
        known.clear();
        known_offset.clear();
        for (int q : k_ring(tar, j, k))
            if (assigned[size_t(q)] >= 0) {
                known.push_back(q);
                known_offset.push_back(tar.delta(j, q));
            }
        if (known.empty()) {  // the first element, or one cut off from the others
            assigned[size_t(j)] = step == 0 ? ref.start : int(rng.index(n_ref));
            continue;
        }
        candidates.clear();
        for (size_t r = 0; r < n_ref; ++r) {
            // Relevant pairs (§3.1, Fig. 3): mutual nearest neighbours by relative position.
            const auto& offsets = ref_offset[r];
            float sum_shape = 0, sum_par = 0, sum_ov = 0, sum_sup = 0, sum_col = 0;
            int pairs = 0;
            for (size_t a = 0; a < offsets.size(); ++a) {
                int nearest_t = -1;
                float best = INFINITY;
                for (size_t b = 0; b < known.size(); ++b) {
                    const glm::vec2 d = offsets[a] - known_offset[b];
                    const float d2 = glm::dot(d, d);
                    if (d2 < best) best = d2, nearest_t = int(b);
                }
                // Is offsets[a] also the nearest reference element to that target element?
                bool mutual = true;
                for (size_t c = 0; c < offsets.size() && mutual; ++c) {
                    const glm::vec2 d = offsets[c] - known_offset[size_t(nearest_t)];
                    if (c != a && glm::dot(d, d) < best) mutual = false;
                }
                if (!mutual) continue;
                const size_t m = size_t(ref_ring[r][a]) * n_ref + size_t(assigned[size_t(known[size_t(nearest_t)])]);
                sum_shape += ref.shape[m];
                sum_par += ref.par[m];
                sum_ov += ref.ov[m];
                sum_sup += ref.sup[m];
                sum_col += ref.col[m];
                ++pairs;
            }
            if (pairs == 0) {
                scores[r] = INFINITY;
                continue;
            }
            const float inv = 1.0f / float(pairs);
            scores[r] = combine(sum_shape * inv, sum_par * inv, sum_ov * inv, sum_sup * inv, sum_col * inv, desc.sigma, L);
            if (scores[r] < 1.0f) candidates.push_back(int(r));
        }
        if (!candidates.empty()) {
            assigned[size_t(j)] = candidates[rng.index(candidates.size())];  // a random pick in Ω (§3.1)
            ++out.matched;
        } else {
            assigned[size_t(j)] = int(std::min_element(scores.begin(), scores.end()) - scores.begin());
            ++out.fallback;
        }
    }
    out.match_ms = match.elapsed_ms();

    // §3.3: variation, then the strokes.
    std::vector<ElementPose> poses(n_tar);
    for (size_t i = 0; i < n_tar; ++i) poses[i] = {assigned[i], seeds[i]};
    vary_parameters(poses, ref, desc.variation, desc.sigma, rng);
    vary_positions(poses, tar, ref, desc.variation, target.along_path);

    out.strokes.size = glm::vec2(0.0f);
    for (size_t i = 0; i < n_tar; ++i) {
        const ElementPose& p = poses[i];
        const Element& e = ref.elements[size_t(p.source)];
        glm::vec2 centre_world = p.position;
        float angle = p.turn;  // the turn from the reference element's frame to the target's
        if (target.along_path) {
            centre_world = path->to_world(p.position);
            angle += path->tangent_angle(p.position.x) - ref.frame_angle[size_t(p.source)];
        }
        const glm::vec2 a_axis = rotate(e.axis, angle), b_axis(-a_axis.y, a_axis.x);
        out.source.push_back(p.source);
        out.centers.push_back(centre_world);
        out.first_stroke.push_back(out.strokes.strokes.size());
        for (int id : e.strokes) {
            Stroke s = ref.strokes[size_t(id)];
            for (glm::vec2& q : s.points) {
                const glm::vec2 d = q - e.center;
                const float u = glm::dot(d, e.axis) * p.stretch, v = glm::dot(d, e.minor_axis()) * p.thicken;
                q = centre_world + u * a_axis + v * b_axis;
            }
            for (float& w : s.widths) w *= p.thicken;
            out.strokes.strokes.push_back(std::move(s));
        }
    }
    out.first_stroke.push_back(out.strokes.strokes.size());
    out.total_ms = total.elapsed_ms();
    return out;
}

}  // namespace lw
