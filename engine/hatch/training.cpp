#include "hatch/training.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

namespace {

// Four points at equal arc length along the stroke, ends included; the centre is the mean of
// 16 points at equal arc length, so that the density of the file's points does not move it.
void resample(const Stroke& s, std::vector<glm::vec2>& four, glm::vec2& centre) {
    std::vector<glm::vec2> pts = s.points;
    if (s.closed && pts.size() > 2) pts.push_back(pts.front());
    std::vector<float> cum{0.0f};
    for (size_t i = 1; i < pts.size(); ++i) cum.push_back(cum.back() + glm::length(pts[i] - pts[i - 1]));
    auto at = [&](float x) {
        if (pts.size() == 1 || cum.back() <= 0.0f) return pts.front();
        const size_t i = size_t(std::upper_bound(cum.begin(), cum.end(), x) - cum.begin());
        const size_t k = std::clamp<size_t>(i, 1, pts.size() - 1);
        const float span = cum[k] - cum[k - 1];
        const float f = span > 0.0f ? std::clamp((x - cum[k - 1]) / span, 0.0f, 1.0f) : 0.0f;
        return glm::mix(pts[k - 1], pts[k], f);
    };
    four.clear();
    for (int k = 0; k < 4; ++k) four.push_back(at(cum.back() * float(k) / 3.0f));
    centre = glm::vec2(0.0f);
    for (int k = 0; k < 16; ++k) centre += at(cum.back() * (float(k) + 0.5f) / 16.0f);
    centre /= 16.0f;
}

}  // namespace

HatchTraining make_training(std::vector<Stroke> strokes) {
    if (strokes.size() < 3) throw Error("hatching needs a training sequence of at least 3 strokes");
    HatchTraining t;
    t.strokes = std::move(strokes);
    const size_t n = t.strokes.size();
    std::vector<std::vector<glm::vec2>> four(n);
    t.centers.resize(n);
    for (size_t i = 0; i < n; ++i) resample(t.strokes[i], four[i], t.centers[i]);

    // The sequence frame: principal direction of the centres, pointing first → last.
    glm::dvec2 mean(0.0);
    for (const glm::vec2& c : t.centers) mean += glm::dvec2(c);
    mean /= double(n);
    double cxx = 0, cxy = 0, cyy = 0;
    for (const glm::vec2& c : t.centers) {
        const glm::dvec2 d = glm::dvec2(c) - mean;
        cxx += d.x * d.x, cxy += d.x * d.y, cyy += d.y * d.y;
    }
    const double theta = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
    t.origin = glm::vec2(mean);
    t.u = glm::vec2(float(std::cos(theta)), float(std::sin(theta)));
    if (glm::dot(t.centers.back() - t.centers.front(), t.u) < 0.0f) t.u = -t.u;
    t.v = glm::vec2(-t.u.y, t.u.x);

    t.step.resize(n);
    t.offset.resize(n);
    for (size_t i = 1; i < n; ++i) t.step[i] = glm::dot(t.centers[i] - t.centers[i - 1], t.u);
    std::vector<float> steps(t.step.begin() + 1, t.step.end());
    std::nth_element(steps.begin(), steps.begin() + long(steps.size() / 2), steps.end());
    t.step[0] = steps[steps.size() / 2];
    for (size_t i = 0; i < n; ++i) t.offset[i] = glm::dot(t.centers[i] - t.origin, t.v);

    // Raw vectors, then standardized; constant dimensions dropped.
    const int raw = t.raw_dim;
    std::vector<double> x(n * size_t(raw));
    for (size_t i = 0; i < n; ++i) {
        double* r = &x[i * size_t(raw)];
        r[0] = t.step[i];
        r[1] = t.offset[i];
        for (int k = 0; k < 4; ++k) {
            const glm::vec2 d = four[i][size_t(k)] - t.centers[i];
            r[2 + 2 * k] = glm::dot(d, t.u);
            r[3 + 2 * k] = glm::dot(d, t.v);
        }
        r[10] = mean_width(t.strokes[i]);
        r[11] = t.strokes[i].color.r;
        r[12] = t.strokes[i].color.g;
        r[13] = t.strokes[i].color.b;
    }
    std::vector<int> kept;
    std::vector<double> mu(static_cast<size_t>(raw)), sigma(static_cast<size_t>(raw));
    for (int k = 0; k < raw; ++k) {
        double m = 0, s = 0;
        for (size_t i = 0; i < n; ++i) m += x[i * size_t(raw) + size_t(k)];
        m /= double(n);
        for (size_t i = 0; i < n; ++i) s += (x[i * size_t(raw) + size_t(k)] - m) * (x[i * size_t(raw) + size_t(k)] - m);
        s = std::sqrt(s / double(n));
        mu[size_t(k)] = m;
        sigma[size_t(k)] = s;
        if (s > 1e-6 * (1.0 + std::abs(m))) kept.push_back(k);
    }
    if (kept.empty()) {
        kept.push_back(0);
        sigma[0] = 1.0;
    }  // identical strokes: one (constant) dimension
    t.vectors.dim = int(kept.size());
    t.vectors.values.reserve(n * kept.size());
    for (size_t i = 0; i < n; ++i)
        for (int k : kept) t.vectors.values.push_back((x[i * size_t(raw) + size_t(k)] - mu[size_t(k)]) / sigma[size_t(k)]);
    return t;
}

Samples sequence_vectors(const HatchTraining& t, const std::vector<int>& ids) {
    Samples s;
    s.dim = t.vectors.dim;
    s.values.reserve(ids.size() * size_t(s.dim));
    for (int id : ids) s.values.insert(s.values.end(), t.vectors.row(size_t(id)), t.vectors.row(size_t(id)) + s.dim);
    return s;
}

}  // namespace lw
