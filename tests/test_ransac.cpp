// RANSAC fit of T(s) = ρs + φ (Bénard et al. 2010, §4.2): recovery under outliers, and the
// GPU pass against the CPU reference.
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

}  // namespace
}  // namespace lw
