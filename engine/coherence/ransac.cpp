// Compiled with -ffp-contract=off so that hypothesis tests round as on the GPU.
#include "coherence/ransac.h"

#include <algorithm>
#include <cmath>

namespace lw {

namespace {

// A 32-bit integer hash (PCG output permutation), identical in GLSL.
uint32_t pcg_hash(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Two-vote model; false when the votes share their arclength (no slope).
bool hypothesis(const Vote& a, const Vote& b, float& rho, float& phi) {
    const float ds = b.s - a.s;
    if (ds == 0.0f) return false;
    rho = (b.t - a.t) / ds;
    phi = a.t - rho * a.s;
    return std::isfinite(rho) && rho != 0.0f;
}

// Inliers: residual in pixels along the path, |t − (ρs + φ)| / |ρ| ≤ inlier_px.
uint32_t count_inliers(std::span<const Vote> votes, float rho, float phi, float inlier_px) {
    const float limit = inlier_px * std::abs(rho);
    uint32_t count = 0;
    for (const Vote& v : votes) count += std::abs(v.t - (rho * v.s + phi)) <= limit;
    return count;
}

}  // namespace

uint32_t ransac_iterations(float inlier_ratio, float probability, uint32_t max_iterations) {
    const float w2 = inlier_ratio * inlier_ratio;
    if (w2 >= 1.0f) return 1;
    if (w2 <= 0.0f) return max_iterations;
    const float n = std::ceil(std::log(1.0f - probability) / std::log(1.0f - w2));
    return uint32_t(std::clamp(n, 1.0f, float(max_iterations)));
}

glm::uvec2 ransac_pair(uint32_t seed, uint32_t path, uint32_t h, uint32_t n) {
    const uint32_t base = pcg_hash(seed ^ pcg_hash(path * 2654435761u ^ pcg_hash(h)));
    const uint32_t a = base % n;
    uint32_t b = pcg_hash(base) % (n - 1);
    if (b >= a) ++b;
    return {a, b};
}

PathFit fit_path_reference(std::span<const Vote> votes, uint32_t path, const RansacParams& params) {
    PathFit fit;
    fit.votes = uint32_t(votes.size());
    const uint32_t n = fit.votes;
    if (n < 2) return fit;

    // Rounds of kRansacBatch hypotheses; after each round the best hypothesis so far (most
    // inliers, lowest index on ties) refines the inlier ratio and so the iteration count.
    uint32_t needed = ransac_iterations(1.0f - params.outlier_ratio, params.target_probability, params.max_iterations);
    uint32_t best_count = 0, best_h = 0;
    float best_rho = 0.0f, best_phi = 0.0f;
    uint32_t done = 0;
    while (done < needed) {
        for (uint32_t h = done; h < done + kRansacBatch; ++h) {
            const glm::uvec2 pair = ransac_pair(params.seed, path, h, n);
            float rho = 0.0f, phi = 0.0f;
            if (!hypothesis(votes[pair.x], votes[pair.y], rho, phi)) continue;
            const uint32_t count = count_inliers(votes, rho, phi, params.inlier_px);
            if (count > best_count || (count == best_count && count > 0 && h < best_h)) {
                best_count = count;
                best_h = h;
                best_rho = rho;
                best_phi = phi;
            }
        }
        done += kRansacBatch;
        if (best_count > 0)
            needed = std::min(needed, ransac_iterations(float(best_count) / float(n), params.target_probability,
                                                        params.max_iterations));
    }
    fit.iterations = done;
    if (best_count < 2) return fit;

    // Least squares on the inliers of the best hypothesis (s centred for conditioning).
    const float limit = params.inlier_px * std::abs(best_rho);
    double sum_s = 0.0, sum_t = 0.0;
    uint32_t m = 0;
    for (const Vote& v : votes)
        if (std::abs(v.t - (best_rho * v.s + best_phi)) <= limit) {
            sum_s += v.s;
            sum_t += v.t;
            ++m;
        }
    const double mean_s = sum_s / m, mean_t = sum_t / m;
    double sst = 0.0, sss = 0.0;
    for (const Vote& v : votes)
        if (std::abs(v.t - (best_rho * v.s + best_phi)) <= limit) {
            sss += (v.s - mean_s) * (v.s - mean_s);
            sst += (v.s - mean_s) * (v.t - mean_t);
        }
    if (sss <= 0.0) return fit;
    fit.rho = float(sst / sss);
    fit.phi = float(mean_t - sst / sss * mean_s);
    fit.inliers = m;
    fit.fitted = std::isfinite(fit.rho) && std::isfinite(fit.phi) && fit.rho != 0.0f;
    return fit;
}

std::vector<PathFit> fit_paths_reference(const VoteSet& set, const RansacParams& params) {
    std::vector<PathFit> fits(set.path_count());
    for (uint32_t p = 0; p < fits.size(); ++p)
        fits[p] = fit_path_reference(std::span(set.votes).subspan(set.offsets[p], set.offsets[p + 1] - set.offsets[p]),
                                     p, params);
    return fits;
}

PhaseFit fit_phase(std::span<const Vote> votes, float rho, float inlier_px) {
    PhaseFit fit;
    if (votes.empty() || !std::isfinite(rho)) return fit;
    std::vector<float> phases;
    phases.reserve(votes.size());
    for (const Vote& v : votes)
        if (const float phase = v.t - rho * v.s; std::isfinite(phase)) phases.push_back(phase);
    if (phases.empty()) return fit;
    std::sort(phases.begin(), phases.end());
    const float width = 2.0f * inlier_px * std::abs(rho);
    size_t best_first = 0, best_count = 0;
    for (size_t first = 0, end = 0; first < phases.size(); ++first) {
        end = std::max(end, first);
        while (end < phases.size() && phases[end] - phases[first] <= width) ++end;
        if (end - first > best_count) {
            best_count = end - first;
            best_first = first;
        }
    }
    fit.phi = phases[best_first + best_count / 2];
    fit.inliers = uint32_t(best_count);
    return fit;
}

}  // namespace lw
