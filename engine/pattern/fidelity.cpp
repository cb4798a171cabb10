#include "pattern/fidelity.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "pattern/lloyd.h"

namespace lw {

namespace {

constexpr double kPi = 3.141592653589793;

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Orientation of `axis` relative to the frame angle, folded into [0, π).
double relative_orientation(glm::vec2 axis, float frame_angle) {
    double a = std::atan2(double(axis.y), double(axis.x)) - double(frame_angle);
    a = std::fmod(a, kPi);
    if (a < 0.0) a += kPi;
    return a;
}

// Values are rounded to 1/100 (px, rad, colour) so that float rounding in copied strokes does
// not count as a difference: KS is sensitive to ties, and many references repeat one width.
double rounded(double v) { return std::round(v * 100.0) / 100.0; }

void add(ElementSample& s, const Element& e, float frame_angle) {
    s.orientation.push_back(rounded(relative_orientation(e.axis, frame_angle)));
    s.length.push_back(rounded(e.length()));
    s.thickness.push_back(rounded(e.width()));
    s.red.push_back(rounded(e.color.r));
    s.green.push_back(rounded(e.color.g));
    s.blue.push_back(rounded(e.color.b));
}

void add_nearest(ElementSample& s, const std::vector<glm::vec2>& centres) {
    for (float d : nearest_neighbour_distances(centres)) s.nearest.push_back(d);
}

}  // namespace

double ks_statistic(std::vector<double> a, std::vector<double> b) {
    if (a.empty() || b.empty()) return 0.0;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    size_t i = 0, j = 0;
    double d = 0.0;
    while (i < a.size() && j < b.size()) {
        const double x = std::min(a[i], b[j]);
        while (i < a.size() && a[i] <= x) ++i;
        while (j < b.size() && b[j] <= x) ++j;
        d = std::max(d, std::abs(double(i) / double(a.size()) - double(j) / double(b.size())));
    }
    return d;
}

double ks_critical_05(size_t n, size_t m) {
    if (n == 0 || m == 0) return 1.0;
    return 1.358 * std::sqrt(double(n + m) / (double(n) * double(m)));
}

PatternFidelity measure_fidelity(const PatternAnalysis& ref, const PatternSynthesis& s, const PatternFrame& target,
                                 FitMode fit) {
    PatternFidelity f;
    std::vector<glm::vec2> centres;
    for (size_t i = 0; i < ref.elements.size(); ++i) {
        add(f.reference, ref.elements[i], ref.frame_angle[i]);
        centres.push_back(ref.elements[i].center);
    }
    add_nearest(f.reference, centres);

    centres.clear();
    std::optional<ArclengthCurve> path;
    if (target.along_path) path.emplace(target.curve);
    for (size_t e = 0; e + 1 < s.first_stroke.size(); ++e) {
        std::vector<int> ids;
        for (size_t k = s.first_stroke[e]; k < s.first_stroke[e + 1]; ++k) ids.push_back(int(k));
        const Element el = fit_element(s.strokes.strokes, ids, fit);
        float frame_angle = 0.0f;
        if (path) {
            const glm::vec2 t = path->tangent_at(s.target.positions[e].x, std::max(1e-3f, 0.01f * path->length()));
            frame_angle = std::atan2(t.y, t.x);
        }
        add(f.output, el, frame_angle);
        centres.push_back(el.center);
    }
    add_nearest(f.output, centres);

    f.ks_orientation = ks_statistic(f.reference.orientation, f.output.orientation);
    f.ks_length = ks_statistic(f.reference.length, f.output.length);
    f.ks_thickness = ks_statistic(f.reference.thickness, f.output.thickness);
    f.ks_color = std::max({ks_statistic(f.reference.red, f.output.red), ks_statistic(f.reference.green, f.output.green),
                           ks_statistic(f.reference.blue, f.output.blue)});
    f.ks_nearest = ks_statistic(f.reference.nearest, f.output.nearest);
    f.critical = ks_critical_05(ref.elements.size(), centres.size());
    f.median_nn_reference = median(f.reference.nearest);
    f.median_nn_output = median(f.output.nearest);
    return f;
}

}  // namespace lw
