// Enclosed paper (slam_synth/enclosed_ink.h): the priority flood against a plain fixed-point
// reference on random planes, fills whose answer is known (a hollow dot, a diagonal gap, a
// ring across the seam), the bound on basin size, and the step that imposes a deficit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "slam_synth/enclosed_ink.h"

using namespace lw::synth;

namespace {

// The definition, computed plainly: fill = x on the first and last rows, and elsewhere the
// largest fixed point of f(p) = max(x(p), min over the 4 neighbours (wrapping along the
// columns) of f(q)), reached by relaxing from +∞ until nothing changes.
Plane reference_fill(const Plane& x) {
    Plane f(x.rows, x.cols, std::numeric_limits<float>::infinity());
    for (int c = 0; c < x.cols; ++c) {
        f.at(0, c) = x.at(0, c);
        f.at(x.rows - 1, c) = x.at(x.rows - 1, c);
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (int r = 1; r + 1 < x.rows; ++r)
            for (int c = 0; c < x.cols; ++c) {
                const float low = std::min({f.at(r - 1, c), f.at(r + 1, c), f.at(r, (c + x.cols - 1) % x.cols),
                                            f.at(r, (c + 1) % x.cols)});
                const float v = std::max(x.at(r, c), low);
                if (v < f.at(r, c)) f.at(r, c) = v, changed = true;
            }
    }
    return f;
}

// A square ring of ink 1 around (r, c), half-size 2, its centre at `centre`.
void ring(Plane& p, int r, int c, float centre) {
    for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc) {
            const bool edge = std::abs(dr) == 2 || std::abs(dc) == 2;
            p.at(r + dr, (c + dc + p.cols) % p.cols) = edge ? 1.0f : centre;
        }
}

}  // namespace

TEST(EnclosedInk, FloodEqualsTheFixedPointReference) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        const int rows = 3 + int(rng() % 10), cols = 1 + int(rng() % 17);
        Plane x(rows, cols);
        // Few distinct values, so that ties and plateaus occur.
        for (float& v : x.v) v = float(rng() % 6) / 5.0f;
        const Plane got = fill_enclosed(x), want = reference_fill(x);
        ASSERT_EQ(got.v, want.v) << "trial " << trial << ", " << rows << "x" << cols;
    }
}

TEST(EnclosedInk, AHollowDotFillsToTheLowestInkOnItsRim) {
    Plane p(9, 12);
    ring(p, 4, 5, 0.1f);
    p.at(2, 5) = 0.8f;  // the rim's lowest texel: the centre spills there
    const Plane f = fill_enclosed(p);
    for (int r = 3; r <= 5; ++r)
        for (int c = 4; c <= 6; ++c) EXPECT_EQ(f.at(r, c), 0.8f);
    for (size_t i = 0; i < p.size(); ++i) {
        if (p.v[i] != 0.1f) {
            EXPECT_EQ(f.v[i], p.v[i]);  // the rim and the open paper are as they were
        }
    }
    EXPECT_NEAR(enclosed_deficit(p, 81), 9 * 0.7 / double(p.size()), 1e-6);
}

TEST(EnclosedInk, PaperDoesNotLeakThroughADiagonalGapButDoesThroughAnOpenSide) {
    Plane p(9, 12);
    ring(p, 4, 5, 0.0f);
    p.at(2, 3) = 0.0f;  // a corner of the ring missing: ink still joins diagonally
    EXPECT_EQ(fill_enclosed(p).at(4, 5), 1.0f);
    p.at(2, 5) = 0.0f;  // a gap in a side: the centre's paper reaches the first row
    EXPECT_EQ(fill_enclosed(p).at(4, 5), 0.0f);
}

TEST(EnclosedInk, ColumnsWrap) {
    Plane p(9, 12);
    ring(p, 4, 0, 0.0f);  // straddles the first and last columns: enclosed only if they join
    EXPECT_EQ(fill_enclosed(p).at(4, 0), 1.0f);
    EXPECT_EQ(fill_enclosed(p).at(4, 11), 1.0f);
    // Open on the far side of the seam: the centre's paper leaks across it to column 5.
    Plane open(9, 12);
    ring(open, 4, 1, 0.0f);
    open.at(4, 11) = 0.0f;  // the ring's left side lies in column 11
    EXPECT_EQ(fill_enclosed(open).at(4, 1), 0.0f);
    EXPECT_EQ(fill_enclosed(open).at(4, 0), 0.0f);
}

TEST(EnclosedInk, ImposingADeficitMovesTowardTheFillAndStopsAtTheTarget) {
    Plane p(16, 40);
    std::mt19937 rng(3);
    for (float& v : p.v) v = float(rng() % 1000) / 1000.0f;
    for (int c = 0; c < p.cols; ++c) p.at(0, c) = p.at(p.rows - 1, c) = 0.0f;
    constexpr int kAll = 16 * 40;
    const double deficit = enclosed_deficit(p, kAll);
    ASSERT_GT(deficit, 0.01);
    Plane same = p;
    impose_enclosed_deficit(same, deficit * 1.01, kAll);  // already under the target: untouched
    EXPECT_EQ(same.v, p.v);
    Plane moved = p;
    impose_enclosed_deficit(moved, deficit / 4, kAll);
    EXPECT_NEAR(enclosed_deficit(moved, kAll), deficit / 4, 1e-6);
    const Plane f = fill_enclosed(p), g = fill_enclosed(moved);
    for (size_t i = 0; i < p.size(); ++i) {
        EXPECT_NEAR(g.v[i], f.v[i], 1e-6);     // the fill is the same
        EXPECT_GE(moved.v[i], p.v[i] - 1e-7f);  // ink only raised,
        EXPECT_LE(moved.v[i], f.v[i] + 1e-7f);  // and never past the fill
    }
    impose_enclosed_deficit(moved, 0.0, kAll);
    EXPECT_NEAR(enclosed_deficit(moved, kAll), 0.0, 1e-6);
    EXPECT_EQ(moved.v, f.v);
}

// Basins larger than the bound are neither counted nor filled; smaller ones are, and the
// deficit of the result is measured over the same basins.
TEST(EnclosedInk, OnlyBasinsWithinTheBoundTakePart) {
    Plane p(20, 40);
    ring(p, 4, 5, 0.0f);  // a 3 × 3 hollow: 9 texels
    for (int r = 8; r <= 18; ++r)  // a box of ink around an 9 × 9 hollow: 81 texels
        for (int c = 20; c <= 30; ++c) p.at(r, c) = (r == 8 || r == 18 || c == 20 || c == 30) ? 1.0f : 0.0f;
    const Plane small = fill_small_basins(p, 80);
    EXPECT_EQ(small.at(4, 5), 1.0f);   // the small hollow filled
    EXPECT_EQ(small.at(13, 25), 0.0f); // the large one, one texel over the bound, not
    EXPECT_NEAR(enclosed_deficit(p, 80), 9.0 / double(p.size()), 1e-9);
    EXPECT_NEAR(enclosed_deficit(p, 81), 90.0 / double(p.size()), 1e-9);
    Plane q = p;
    impose_enclosed_deficit(q, 0.0, 80);
    EXPECT_EQ(q.v, small.v);
}

// The bound on a random plane: basins over it keep their ink while the small ones move,
// and the deficit over the small ones reaches the target.
TEST(EnclosedInk, ImposingWithABoundLeavesLargeBasinsAsTheyAre) {
    Plane p(16, 40);
    std::mt19937 rng(5);
    for (float& v : p.v) v = float(rng() % 1000) / 1000.0f;
    for (int c = 0; c < p.cols; ++c) p.at(0, c) = p.at(p.rows - 1, c) = 0.0f;
    constexpr int kBound = 4;
    const Plane all = fill_enclosed(p), small = fill_small_basins(p, kBound);
    size_t large = 0;  // texels of basins over the bound
    for (size_t i = 0; i < p.size(); ++i) large += all.v[i] > p.v[i] && small.v[i] == p.v[i];
    ASSERT_GT(large, 20u);
    const double deficit = enclosed_deficit(p, kBound);
    ASSERT_GT(deficit, 0.0);
    Plane moved = p;
    impose_enclosed_deficit(moved, deficit / 3, kBound);
    EXPECT_NEAR(enclosed_deficit(moved, kBound), deficit / 3, 1e-6);
    for (size_t i = 0; i < p.size(); ++i) {
        if (small.v[i] == p.v[i]) {
            EXPECT_EQ(moved.v[i], p.v[i]);  // outside the small basins: as it was
        } else {
            EXPECT_GT(moved.v[i], p.v[i]);
            EXPECT_LT(moved.v[i], small.v[i]);
        }
    }
}

// A basin across the seam is one basin: 81 texels, over a bound of 80 and within 81.
TEST(EnclosedInk, BasinsAreCountedAcrossTheSeam) {
    Plane p(20, 40);
    for (int r = 8; r <= 18; ++r)
        for (int c = -5; c <= 5; ++c) p.at(r, (c + 40) % 40) = (r == 8 || r == 18 || c == -5 || c == 5) ? 1.0f : 0.0f;
    EXPECT_EQ(fill_small_basins(p, 80).at(13, 0), 0.0f);
    EXPECT_EQ(fill_small_basins(p, 81).at(13, 0), 1.0f);
    EXPECT_EQ(fill_small_basins(p, 81).at(13, 38), 1.0f);
}

TEST(EnclosedInk, NonFiniteInkIsLeftAsItIs) {
    Plane p(9, 12);
    ring(p, 4, 5, 0.0f);
    p.at(0, 0) = std::numeric_limits<float>::quiet_NaN();
    Plane q = p;
    impose_enclosed_deficit(q, 0.0, 81);
    for (size_t i = 0; i < p.size(); ++i)
        EXPECT_TRUE(q.v[i] == p.v[i] || (std::isnan(q.v[i]) && std::isnan(p.v[i])));
}
