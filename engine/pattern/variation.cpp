#include "pattern/variation.h"

#include <cmath>

namespace lw {

namespace {
constexpr float kPi = 3.14159265358979f;

// Signed angle turning undirected axis a onto b, in (−π/2, π/2].
float signed_axis_turn(glm::vec2 a, glm::vec2 b) {
    float t = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
    if (t > 0.5f * kPi) t -= kPi;
    if (t <= -0.5f * kPi) t += kPi;
    return t;
}
}  // namespace

void vary_parameters(std::vector<ElementPose>& poses, const PatternAnalysis& ref, float variation,
                     const PatternThresholds& sigma, Rng& rng) {
    if (variation <= 0.0f) return;
    const size_t n = ref.elements.size();
    const float L = ref.mean_length;
    std::vector<int> similar;
    auto pick = [&](int r, auto&& close) {
        similar.clear();
        for (size_t q = 0; q < n; ++q)
            if (close(size_t(r) * n + q)) similar.push_back(int(q));
        return similar.empty() ? r : similar[rng.index(similar.size())];
    };
    for (ElementPose& p : poses) {
        const int r = p.source;
        const Element& e = ref.local[size_t(r)];
        // Each parameter independently (§3.3).
        const int q_par = pick(r, [&](size_t k) { return ref.par[k] <= variation * sigma.par; });
        p.turn += signed_axis_turn(e.axis, ref.local[size_t(q_par)].axis);
        const int q_len = pick(r, [&](size_t k) { return ref.ov[k] <= 1.0f + variation * (sigma.ov - 1.0f); });
        if (e.half_length > 1e-6f) p.stretch *= ref.local[size_t(q_len)].half_length / e.half_length;
        const int q_wid = pick(r, [&](size_t k) { return ref.sup[k] <= variation * sigma.sup * L; });
        if (e.half_width > 1e-3f * std::max(L, 1e-6f)) p.thicken *= ref.local[size_t(q_wid)].half_width / e.half_width;
    }
}

void vary_positions(std::vector<ElementPose>& poses, const Distribution& target, const PatternAnalysis& ref,
                    float variation, bool along_path) {
    if (variation <= 0.0f) return;
    const size_t k = along_path ? 2 : 4;
    std::vector<glm::vec2> moved(poses.size());
    for (size_t i = 0; i < poses.size(); ++i) {
        moved[i] = poses[i].position;
        const auto& nbrs = target.neighbours[i];
        const int r = poses[i].source;
        const float ref_spacing = ref.distribution.spacing[size_t(r)];
        if (nbrs.size() < k || ref_spacing <= 0.0f) continue;
        glm::vec2 barycentre(0.0f);  // relative to the element; all in parallel: the unmoved positions
        for (int j : nbrs) barycentre += target.wrapped(poses[size_t(j)].position - poses[i].position);
        barycentre /= float(nbrs.size());
        const glm::vec2 shift = ref.distribution.shift[size_t(r)] * (target.spacing[i] / ref_spacing);
        moved[i] = poses[i].position + variation * (barycentre + shift);
    }
    for (size_t i = 0; i < poses.size(); ++i) poses[i].position = moved[i];
}

}  // namespace lw
