// RANSAC fit of T(s) = ρs + φ (Bénard et al. 2010, §4.2): recovery under outliers, and the
// GPU pass against the CPU reference.
#include <algorithm>
#include <random>

#include "coherence/ransac.h"
#include "coherence/ransac_gpu.h"
#include "test_support.h"

namespace lw {
namespace {

// Votes along a path of `count` samples every 2 px: t = ρs + φ with small noise, and a
// share of outliers drawn uniformly over the t range (as overlapping paths produce).
std::vector<Vote> synthetic_votes(float rho, float phi, size_t count, float outlier_share, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> noise(0.0f, 0.2f * std::abs(rho));  // 0.2 px of jitter
    std::vector<Vote> votes;
    for (size_t i = 0; i < count; ++i) {
        const float s = 2.0f * float(i);
        float t = rho * s + phi + noise(rng);
        if (unit(rng) < outlier_share) t = phi + rho * 2.0f * float(count) * (unit(rng) * 2.0f - 0.5f);
        votes.push_back({t, s});
    }
    return votes;
}

TEST(Ransac, RecoversTheLineUnderThirtyPercentOutliers) {
    const RansacParams params;
    int trials = 0;
    for (const float rho : {0.01f, 0.0037f, 0.05f, -0.02f})
        for (const float phi : {0.0f, 0.4f, -3.2f})
            for (uint32_t seed = 1; seed <= 3; ++seed) {
                const auto votes = synthetic_votes(rho, phi, 200, 0.3f, seed * 17 + 3);
                const PathFit fit = fit_path_reference(votes, seed, params);
                ASSERT_TRUE(fit.fitted);
                EXPECT_NEAR(fit.rho, rho, 0.01f * std::abs(rho)) << rho << " " << phi;
                // φ within 1 % of a period's worth at the path's scale (|ρ|·length).
                EXPECT_NEAR(fit.phi, phi, 0.01f * std::max(std::abs(phi), std::abs(rho) * 400.0f)) << rho << " " << phi;
                EXPECT_GE(fit.inliers, 120u);
                ++trials;
            }
    EXPECT_EQ(trials, 36);
}

TEST(Ransac, FewerThanTwoVotesGiveNoFit) {
    const std::vector<Vote> one{{0.5f, 3.0f}};
    EXPECT_FALSE(fit_path_reference(one, 0, {}).fitted);
    EXPECT_FALSE(fit_path_reference({}, 0, {}).fitted);
}

TEST(Ransac, IterationCountFollowsTheProbability) {
    // w = 0.7, p = 0.99: log(0.01)/log(1 − 0.49) = 6.84 → 7.
    EXPECT_EQ(ransac_iterations(0.7f, 0.99f, 1000), 7u);
    EXPECT_EQ(ransac_iterations(1.0f, 0.99f, 1000), 1u);
    EXPECT_EQ(ransac_iterations(0.01f, 0.99f, 500), 500u);
    for (uint32_t h = 0; h < 200; ++h) {
        const glm::uvec2 pair = ransac_pair(7, 3, h, 5);
        EXPECT_NE(pair.x, pair.y);
        EXPECT_LT(pair.x, 5u);
        EXPECT_LT(pair.y, 5u);
    }
}

class RansacGpu : public test::GpuTest {};

TEST_F(RansacGpu, MatchesTheCpuReference) {
    // Many paths of varied size and outlier share, including degenerate ones.
    VoteSet set;
    std::mt19937 rng(11);
    for (uint32_t p = 0; p < 300; ++p) {
        const size_t count = p % 7 == 0 ? p % 3 : 5 + (rng() % 200);
        const float rho = 0.002f + 0.05f * float(rng() % 1000) / 1000.0f;
        const auto votes = synthetic_votes(p % 2 ? rho : -rho, float(rng() % 100) / 10.0f, count,
                                           0.1f * float(p % 6), p + 5);
        set.votes.insert(set.votes.end(), votes.begin(), votes.end());
        set.offsets.push_back(uint32_t(set.votes.size()));
    }
    const RansacParams params;
    // A small set first, so that the second fit grows the fitter's kept buffers.
    RansacFitter fitter(ctx(), ComputeSite::Device);
    VoteSet small{.votes = std::vector<Vote>(set.votes.begin(), set.votes.begin() + set.offsets[3]),
                  .offsets = std::vector<uint32_t>(set.offsets.begin(), set.offsets.begin() + 4)};
    const auto small_gpu = fitter.fit(small, params), small_cpu = fit_paths_reference(small, params);
    for (size_t p = 0; p < small_cpu.size(); ++p) EXPECT_EQ(small_gpu[p].inliers, small_cpu[p].inliers) << p;
    const auto cpu = fit_paths_reference(set, params);
    const auto gpu = fitter.fit(set, params);
    ASSERT_EQ(gpu.size(), cpu.size());
    size_t fitted = 0;
    for (size_t p = 0; p < cpu.size(); ++p) {
        ASSERT_EQ(gpu[p].fitted, cpu[p].fitted) << p;
        EXPECT_EQ(gpu[p].votes, cpu[p].votes) << p;
        EXPECT_EQ(gpu[p].iterations, cpu[p].iterations) << p;
        EXPECT_EQ(gpu[p].inliers, cpu[p].inliers) << p;
        if (!cpu[p].fitted) continue;
        ++fitted;
        EXPECT_NEAR(gpu[p].rho, cpu[p].rho, 1e-4f * std::abs(cpu[p].rho)) << p;
        EXPECT_NEAR(gpu[p].phi, cpu[p].phi, 1e-3f * std::max(1.0f, std::abs(cpu[p].phi))) << p;
    }
    EXPECT_GT(fitted, 200u);
}

// The phase alone (a scale known from the view): the window of width 2·inlier·|ρ| holding the
// most votes' phases, its median. Against a brute force that tries every vote's phase as the
// window's lower end, and robust to 40 % outliers.
TEST(Ransac, PhaseFitIsTheDensestWindowsMedian) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 200; ++trial) {
        const float rho = (trial % 2 ? -1.0f : 1.0f) * (0.002f + 0.01f * unit(rng));
        const size_t count = 1 + size_t(unit(rng) * 12.0f);
        std::vector<Vote> votes;
        for (size_t k = 0; k < count; ++k) votes.push_back({unit(rng) * 0.05f, 2.0f * float(k)});
        const PhaseFit fit = fit_phase(votes, rho, 1.5f);
        // Brute force: every phase as a window's lower end, the most votes (the lowest end on
        // ties), then the median (the upper one of an even count) of that window.
        std::vector<float> phases;
        for (const Vote& v : votes) phases.push_back(v.t - rho * v.s);
        std::sort(phases.begin(), phases.end());
        size_t best = 0;
        float best_low = 0.0f;
        for (const float low : phases) {
            size_t n = 0;
            for (const float q : phases) n += q >= low && q - low <= 2.0f * 1.5f * std::abs(rho);
            if (n > best) {
                best = n;
                best_low = low;
            }
        }
        std::vector<float> window;
        for (const float q : phases)
            if (q >= best_low && q - best_low <= 2.0f * 1.5f * std::abs(rho)) window.push_back(q);
        ASSERT_EQ(fit.inliers, best) << trial;
        EXPECT_EQ(fit.phi, window[window.size() / 2]) << trial;
    }
    EXPECT_EQ(fit_phase({}, 0.01f, 1.5f).inliers, 0u);
    // 120 votes of one line (0.2 px jitter) and 40 % outliers: φ within half a pixel.
    for (uint32_t seed = 1; seed <= 5; ++seed) {
        const std::vector<Vote> votes = synthetic_votes(0.005f, 0.3f, 120, 0.4f, seed);
        const PhaseFit fit = fit_phase(votes, 0.005f, 1.5f);
        EXPECT_NEAR(fit.phi, 0.3f, 0.5f * 0.005f) << seed;
        EXPECT_GE(fit.inliers, 60u) << seed;
    }
}

}  // namespace
}  // namespace lw
