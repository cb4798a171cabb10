// engine/coherence/ransac.h — robust fit of T(s) = ρ·s + φ to a path's votes.
//
// Input:  votes (t_k, s_k) per path: t_k the parameterization splatted at the previous frame
//         (Σwt/Σw), s_k the sample's arclength now (Bénard et al. 2010, §4.2).
// Output: (ρ, φ) per path: RANSAC over two-vote hypotheses, the iteration count derived from
//         the inlier-ratio estimate and the target probability and refined as better
//         hypotheses are found, then least squares on the inliers of the best one. Fewer
//         than two votes: no fit. (The tracker keeps the fit's direction and inliers and
//         takes ρ from the view: coherence.h.)
//
// The GPU pass (ransac_gpu.h, shaders/coherence_ransac.comp, one workgroup per path) draws
// the same random sequence — a hash of (seed, path, hypothesis) — and evaluates hypotheses
// in batches of `kRansacBatch` exactly as `fit_path_reference` does, so both choose the same
// inliers; only the final least squares rounds differently (float on the GPU).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

constexpr uint32_t kRansacBatch = 64;  // hypotheses per round = the GPU workgroup size

struct Vote {
    float t;  // previous parameterization at this sample
    float s;  // arclength of the sample now, pixels
};

struct RansacParams {
    float outlier_ratio = 0.3f;       // initial estimate of the share of outlying votes
    float target_probability = 0.99f; // chance that some hypothesis is outlier-free
    float inlier_px = 1.5f;           // a vote is an inlier within this many pixels along the path
    uint32_t max_iterations = 1024;
    uint32_t seed = 1;
};

struct PathFit {
    float rho = 0.0f;
    float phi = 0.0f;
    uint32_t votes = 0;
    uint32_t inliers = 0;
    uint32_t iterations = 0;  // hypotheses evaluated
    bool fitted = false;      // false: fewer than two votes, or no usable hypothesis
};

// Hypotheses needed so that, with inlier ratio w, one of them is all-inlier with
// probability p: log(1 − p) / log(1 − w²), clamped to [1, max].
[[nodiscard]] uint32_t ransac_iterations(float inlier_ratio, float probability, uint32_t max_iterations);

// The two vote indices of hypothesis `h` of path `path` (a, b distinct, both < n; n ≥ 2).
[[nodiscard]] glm::uvec2 ransac_pair(uint32_t seed, uint32_t path, uint32_t h, uint32_t n);

[[nodiscard]] PathFit fit_path_reference(std::span<const Vote> votes, uint32_t path, const RansacParams& params);

// Votes of many paths in one array: path p owns votes[offsets[p], offsets[p + 1]).
struct VoteSet {
    std::vector<Vote> votes;
    std::vector<uint32_t> offsets{0};
    std::vector<uint32_t> sample;  // optional: the sample each vote came from (same order as votes)
    size_t path_count() const { return offsets.size() - 1; }
};

[[nodiscard]] std::vector<PathFit> fit_paths_reference(const VoteSet& set, const RansacParams& params);

// The phase alone, for a scale ρ known from elsewhere (the view's, coherence.h): the votes'
// phases t − ρ·s, the window of width 2·inlier_px·|ρ| holding the most of them (every
// hypothesis of a one-parameter RANSAC tried; the first such window on ties), and the median
// of that window. One vote is enough. A host function on every compute site.
struct PhaseFit {
    float phi = 0.0f;
    uint32_t inliers = 0;  // 0: no votes
};
[[nodiscard]] PhaseFit fit_phase(std::span<const Vote> votes, float rho, float inlier_px);

}  // namespace lw
