// Hatching by example (Jodoin et al. 2002): the KL2 estimator against analytic values, the
// N-gram plausible set, the window's effect on KL2 (Fig. 5), divergence caught and repaired
// block by block (Fig. 6), and sequences laid along paths (Fig. 8).
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/random.h"
#include "hatch/hatching.h"
#include "hatch/kl2.h"
#include "test_support.h"
#include "vector/stroke_io.h"

namespace lw {
namespace {

Samples normal_sample(size_t n, double mean, uint64_t seed) {
    Rng rng(seed);
    Samples s;
    s.dim = 1;
    for (size_t i = 0; i < n; ++i) s.values.push_back(mean + rng.normal());
    return s;
}

TEST(HatchKl2, MatchesTheAnalyticDivergenceOfTwoGaussians) {
    // KL(N(0,1) ‖ N(1,1)) = (μ1 − μ2)² / 2 = 0.5.
    const Samples p = normal_sample(2000, 0.0, 1), q = normal_sample(2000, 1.0, 2);
    const double kl = kl2_divergence(p, q);
    EXPECT_NEAR(kl, 0.5, 0.05) << kl;
    // A sample against itself: exactly 0; against another sample of the same law: near 0.
    EXPECT_DOUBLE_EQ(kl2_divergence(p, p), 0.0);
    EXPECT_LT(std::abs(kl2_divergence(p, normal_sample(2000, 0.0, 3))), 0.02);
    // Silverman's h for d = 1: 1.06 n^(−1/5).
    EXPECT_NEAR(silverman_h(1, 2000), 1.0592 * std::pow(2000.0, -0.2), 1e-3);
}

Stroke line(glm::vec2 c, float angle, float length, float width = 1.0f) {
    const glm::vec2 d = 0.5f * length * glm::vec2(std::cos(angle), std::sin(angle));
    return make_stroke({c - d, c + d}, width, glm::vec3(0.0f));
}

// 36 strokes whose slant and length drift smoothly, then five alternating X Y X Y X: with a
// short window the context "X Y X" recurs only inside that run, so the N-gram loops in it.
std::vector<Stroke> trap_training() {
    std::vector<Stroke> s;
    for (int i = 0; i < 36; ++i)
        s.push_back(line({10.0f + 8.0f * float(i), 40.0f}, 1.2f + 0.015f * float(i), 30.0f + 0.4f * float(i)));
    for (int i = 0; i < 5; ++i)
        s.push_back(i % 2 == 0 ? line({298.0f + 8.0f * float(i), 40.0f}, 0.3f, 14.0f, 2.5f)
                               : line({298.0f + 8.0f * float(i), 40.0f}, 2.6f, 44.0f, 1.0f));
    return s;
}

TEST(HatchNgram, PlausibleSetFollowsTheContext) {
    const HatchTraining t = make_training(trap_training());
    EXPECT_EQ(t.strokes.size(), 41u);
    EXPECT_GT(glm::dot(t.u, glm::vec2(1, 0)), 0.99f);  // the sequence runs left to right
    // The training's own context ending at stroke 20 makes stroke 21 plausible.
    std::vector<int> history;
    for (int i = 0; i <= 20; ++i) history.push_back(i);
    const std::vector<int> s = plausible_strokes(t, history, 6, 0.5f);
    EXPECT_NE(std::find(s.begin(), s.end(), 21), s.end());
    // Its neighbours in the smooth drift are plausible too, the far end and the X Y run not.
    for (int i : s) EXPECT_LT(std::abs(i - 21), 14) << i;
    // Window 1: no context, every stroke is plausible.
    EXPECT_EQ(plausible_strokes(t, history, 1, 0.5f).size(), 41u);
    EXPECT_THROW((void)plausible_strokes(t, history, 41, 0.5f), Error);
}

TEST(HatchBlocks, TooSmallAWindowGivesAManyTimesLargerKl2) {
    const HatchTraining t = make_training(trap_training());
    HatchDesc desc{.count = 50, .window = 3, .block = 50, .threshold = 0.0};  // no restarts
    Rng small_rng(1), large_rng(1);
    const HatchSequence small = generate_hatching(t, desc, small_rng);
    desc.window = 10;
    const HatchSequence large = generate_hatching(t, desc, large_rng);
    const double kl_small = small.blocks[0].kl2, kl_large = large.blocks[0].kl2;
    // Window 3 loops on the X Y run: two distinct strokes in 50.
    EXPECT_LE(std::set<int>(small.ids.begin(), small.ids.end()).size(), 3u);
    EXPECT_GT(std::set<int>(large.ids.begin(), large.ids.end()).size(), 20u);
    EXPECT_GT(kl_small, 5.0 * kl_large) << kl_small << " vs " << kl_large;  // the paper's Fig. 5: ~10×
}

TEST(HatchBlocks, LongRunDivergenceIsDetectedAndRepairedByRestarting) {
    const HatchTraining t = make_training(trap_training());
    HatchDesc desc{.count = 1000, .window = 3, .block = 50, .threshold = 0.0};
    Rng raw_rng(4);
    const HatchSequence raw = generate_hatching(t, desc, raw_rng);
    ASSERT_EQ(raw.blocks.size(), 20u);
    const double threshold = 3.0;  // looping blocks score ~50, good ones ~1 here
    size_t diverged = 0;
    for (const HatchBlock& b : raw.blocks) diverged += b.kl2 > threshold;
    EXPECT_GT(diverged, 10u);  // unwatched, the run stays in its loop

    desc.threshold = threshold;
    Rng rng(4);
    int discarded = 0;
    const HatchSequence watched =
        generate_hatching(t, desc, rng, [&](const HatchBlock&, bool kept) { discarded += kept ? 0 : 1; });
    ASSERT_EQ(watched.ids.size(), 1000u);
    ASSERT_EQ(watched.blocks.size(), 20u);
    EXPECT_GE(discarded, 1);
    EXPECT_GT(watched.blocks.front().attempts, 1);
    for (const HatchBlock& b : watched.blocks) {
        EXPECT_LE(b.kl2, threshold) << "block " << b.index;
        EXPECT_FALSE(b.over_threshold);
        EXPECT_GT(b.window, 3);  // the larger window stays
    }
    EXPECT_EQ(watched.blocks[19].first, 951u);
    EXPECT_EQ(watched.blocks[19].last, 1000u);
}

// KL2 grows as the sample shrinks: a last block of 5 strokes after blocks of 50 is held to a
// threshold made from blocks of its own size (held to the full blocks' it was made again
// every time and kept above it: the shipped training with --count 55 scored 5-6 against 2.3).
TEST(HatchBlocks, AShortLastBlockHasItsOwnThreshold) {
    const HatchTraining t =
        make_training(load_strokes(test::source_dir() / "scenes/patterns/hatch_training.svg").strokes);
    for (const int count : {51, 55, 60}) {
        HatchDesc desc{.count = count, .window = 6, .block = 50};
        Rng rng(1);
        const HatchSequence seq = generate_hatching(t, desc, rng);
        ASSERT_EQ(seq.blocks.size(), 2u);
        EXPECT_EQ(seq.blocks[0].threshold, seq.threshold);
        EXPECT_GT(seq.blocks[1].threshold, 2.0 * seq.blocks[0].threshold) << count;
        EXPECT_FALSE(seq.blocks[1].over_threshold) << count << ": KL2 " << seq.blocks[1].kl2;
    }
}

// The window grows for an attempt and stays only where the attempt passed: a run whose every
// attempt fails does not climb to the training's size (where the N-gram copies the training
// in a loop). Under a threshold few blocks meet, each block begins at the window the last
// block that passed kept, and where no attempt passed the window goes back.
TEST(HatchBlocks, AWindowThatDidNotHelpIsNotKept) {
    const HatchTraining t = make_training(trap_training());
    const int n = int(t.strokes.size());
    HatchDesc desc{.count = 1000, .window = 3, .block = 50, .threshold = 1e-9};
    Rng rng(2);
    std::vector<HatchBlock> attempts;
    const HatchSequence seq = generate_hatching(t, desc, rng, [&](const HatchBlock& b, bool kept) {
        if (!kept) attempts.push_back(b);
    });
    ASSERT_EQ(seq.blocks.size(), 20u);
    int expected_first = 3, over = 0;
    for (const HatchBlock& b : seq.blocks) {
        const auto first = std::find_if(attempts.begin(), attempts.end(), [&](const HatchBlock& a) { return a.index == b.index; });
        EXPECT_EQ(first == attempts.end() ? b.window : first->window, expected_first) << "block " << b.index;
        EXPECT_LT(b.window, n);
        over += b.over_threshold;
        if (!b.over_threshold) expected_first = b.window;
    }
    EXPECT_GT(over, 10);  // most blocks fail every attempt, and the window does not climb
    for (const HatchBlock& a : attempts) {
        if (a.next_window > 0) {
            EXPECT_EQ(a.next_window, std::min(a.window + 2, n - 1));
        }
    }
}

TEST(HatchPlacement, StrokesFollowTheLineAndThePaths) {
    const StrokeSet train = load_strokes(test::source_dir() / "scenes" / "patterns" / "hatch_training.svg");
    const HatchTraining t = make_training(train.strokes);
    Rng rng(2);
    const HatchSequence seq = generate_hatching(t, {.count = 120, .window = 6}, rng);
    // On the training's line: centres advance by the copied steps.
    const std::vector<Stroke> line_strokes = place_on_line(t, seq.ids);
    ASSERT_EQ(line_strokes.size(), 120u);
    const float last_u = glm::dot(line_strokes.back().points.front() - t.origin, t.u);
    EXPECT_GT(last_u, 100.0f * 6.0f);
    // Along a circle of radius 100 (Fig. 8): each stroke's centre stays at the training's
    // offset from the path, and strokes turn with the tangent.
    Curve2D circle;
    for (int i = 0; i < 256; ++i) {
        const float a = 6.2831853f * float(i) / 256.0f;
        circle.points.push_back({200.0f + 100.0f * std::cos(a), 200.0f + 100.0f * std::sin(a)});
    }
    circle.closed = true;
    const ArclengthCurve path(circle);
    size_t placed = 0;
    const std::vector<Stroke> along = place_along(t, seq.ids, path, &placed);
    EXPECT_EQ(along.size(), placed);
    EXPECT_GT(placed, 50u);
    EXPECT_LT(placed, 120u);  // the circle (628 px) ends before 120 steps of ~8 px
    float worst = 0.0f;
    for (size_t k = 0; k < along.size(); ++k) {
        glm::vec2 c(0.0f);
        for (const glm::vec2& p : along[k].points) c += p;
        c /= float(along[k].points.size());
        const float offset = t.offset[size_t(seq.ids[k])];
        worst = std::max(worst, std::abs(glm::length(c - glm::vec2(200.0f)) - (100.0f - offset)));  // the left normal points inward here
    }
    EXPECT_LT(worst, 3.0f);  // the curved strokes' point means differ a little from their centres
}

}  // namespace
}  // namespace lw
