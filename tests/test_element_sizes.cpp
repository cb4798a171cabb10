// Element sizes (slam_synth/element_sizes.h): the exemplar's statistic (whole elements only,
// the smallest and largest, how deep), and the step on planes whose answer is known: a
// speck and its halo become paper, a merged pair is cut into two blobs that do not touch,
// a thin hook comes off a dot, elements within the range are left bit for bit, columns
// wrap, and exemplars of unlike elements change nothing.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "slam_synth/element_sizes.h"
#include "slam_synth/slam_fidelity.h"

using namespace lw::synth;

namespace {

// A disc of ink 1 of radius 3 centred on texel (r, c): 29 texels; columns wrap.
void dot(Plane& p, int r, int c) {
    for (int dr = -3; dr <= 3; ++dr)
        for (int dc = -3; dc <= 3; ++dc)
            if (dr * dr + dc * dc <= 9) p.at(r + dr, (c + dc + p.cols) % p.cols) = 1.0f;
}

// Three whole dots of 29 texels: the exemplar of the tests below.
ElementSizes three_dots() {
    Plane p(16, 64);
    for (int c : {10, 30, 50}) dot(p, 8, c);
    return element_sizes(p);
}

int count_elements(const Plane& p) { return element_statistics(p, true).count; }

// The areas of the elements of a periodic plane, by flood fill (8-connected, columns wrap).
std::vector<int> element_areas(const Plane& p) {
    std::vector<int> seen(p.size(), 0), areas;
    for (int start = 0; start < int(p.size()); ++start) {
        if (seen[size_t(start)] || !(p.v[size_t(start)] > kElementInk)) continue;
        std::vector<int> stack{start};
        seen[size_t(start)] = 1;
        int area = 0;
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            ++area;
            for (int dr = -1; dr <= 1; ++dr)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int r = i / p.cols + dr, c = (i % p.cols + dc + p.cols) % p.cols, j = r * p.cols + c;
                    if (r < 0 || r >= p.rows || seen[size_t(j)] || !(p.v[size_t(j)] > kElementInk)) continue;
                    seen[size_t(j)] = 1;
                    stack.push_back(j);
                }
        }
        areas.push_back(area);
    }
    return areas;
}

}  // namespace

TEST(ElementSizes, AnExemplarsWholeElementsOnly) {
    Plane p(16, 80);
    for (int c : {12, 30, 50}) dot(p, 8, c);
    dot(p, 8, 1);                                    // cut by the first column: not whole
    for (int c = 0; c < 80; ++c) p.at(14, c) = 1.0f;  // a line from end to end: not an element
    const ElementSizes s = element_sizes(p);
    EXPECT_EQ(s.count, 3);
    EXPECT_EQ(s.min_area, 29);
    EXPECT_EQ(s.max_area, 29);
    EXPECT_NEAR(s.min_depth, std::sqrt(10.0f), 1e-6);  // the centre's nearest paper is (±1, ±3) away
    EXPECT_TRUE(s.alike());
    // The bound: the largest at most 1.5 times the smallest.
    EXPECT_TRUE((ElementSizes{.count = 2, .min_area = 40, .max_area = 60}).alike());
    EXPECT_FALSE((ElementSizes{.count = 2, .min_area = 40, .max_area = 61}).alike());
    EXPECT_FALSE((ElementSizes{.count = 1, .min_area = 40, .max_area = 40}).alike());
    // A dot of 45 texels beside them (radius √13): 45 > 1.5 × 29, not alike; one of 37
    // (radius √11) is.
    Plane q = p;
    for (int dr = -4; dr <= 4; ++dr)
        for (int dc = -4; dc <= 4; ++dc) {
            if (dr * dr + dc * dc <= 13) p.at(7 + dr, 68 + dc) = 1.0f;
            if (dr * dr + dc * dc <= 11) q.at(7 + dr, 68 + dc) = 1.0f;
        }
    EXPECT_EQ(element_sizes(p).max_area, 45);
    EXPECT_FALSE(element_sizes(p).alike());
    EXPECT_EQ(element_sizes(q).max_area, 37);
    EXPECT_TRUE(element_sizes(q).alike());
}

TEST(ElementSizes, ASpeckIsErasedWithItsHaloAndTheDotsAreLeftAsTheyWere) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    for (int c : {10, 30, 50}) dot(p, 8, c);
    const Plane dots = p;
    // A 2 × 2 speck with a halo that runs down from it, across the seam.
    for (int r = 6; r <= 11; ++r)
        for (int c = -2; c <= 3; ++c) p.at(r, (c + 64) % 64) = 0.3f;
    for (int r = 8; r <= 9; ++r)
        for (int c : {63, 0}) p.at(r, c) = 0.9f;
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.erased, 1);
    EXPECT_EQ(changes.split + changes.trimmed, 0);
    for (size_t i = 0; i < p.size(); ++i) ASSERT_EQ(p.v[i], dots.v[i]) << "texel " << i;
}

TEST(ElementSizes, AMergedPairIsCutIntoTwoBlobsThatDoNotTouch) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 20);
    dot(p, 8, 26);  // touching at the rims: one element of 57 texels with a one-texel neck
    dot(p, 8, 50);
    ASSERT_EQ(count_elements(p), 2);
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.split, 1);
    // The cut takes the texels beside the neck, not a dot's worth: each blob keeps 27 or more.
    for (int area : element_areas(p)) EXPECT_GE(area, 27);
    EXPECT_EQ(element_areas(p).size(), 3u);
    // The dot on its own is untouched.
    Plane alone(16, 64);
    dot(alone, 8, 50);
    for (int r = 0; r < 16; ++r)
        for (int c = 40; c < 60; ++c) EXPECT_EQ(p.at(r, c), alone.at(r, c));
}

TEST(ElementSizes, AThinHookComesOffADot) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 20);
    for (int c = 24; c <= 30; ++c) p.at(8, c) = 1.0f;  // 7 texels of a one-texel line, off the rim
    ASSERT_EQ(element_statistics(p, true).mean_area, 29.0 + 7.0);
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.trimmed, 1);
    EXPECT_EQ(changes.split, 0);
    const ElementStatistics after = element_statistics(p, true);
    EXPECT_EQ(after.count, 1);
    EXPECT_LE(after.mean_area, 29.0);
    EXPECT_GE(after.mean_area, 27.0);  // the dot keeps its body (the texel the hook leaves from may go with it)
}

TEST(ElementSizes, WithinTheRangeOrUnlikeNothingChanges) {
    Plane p(16, 64);
    dot(p, 8, 1);  // across the seam: whole on a periodic plane
    dot(p, 8, 30);
    p.at(3, 45) = 0.8f;  // a one-texel speck
    const Plane before = p;
    ElementSizes unlike{.count = 5, .min_area = 2, .max_area = 200, .min_depth = 1.0f};
    ASSERT_FALSE(unlike.alike());
    EXPECT_EQ(impose_element_sizes(p, unlike, 0.0f, 4).erased, 0);
    for (size_t i = 0; i < p.size(); ++i) ASSERT_EQ(p.v[i], before.v[i]);
    // Alike sizes: only the speck goes; the dot across the seam stays whole.
    const ElementChanges changes = impose_element_sizes(p, three_dots(), 0.0f, 4);
    EXPECT_EQ(changes.erased, 1);
    EXPECT_EQ(p.at(3, 45), 0.0f);
    p.at(3, 45) = 0.8f;
    for (size_t i = 0; i < p.size(); ++i) ASSERT_EQ(p.v[i], before.v[i]);
}

// The catchment runs down from the speck only: ink that climbs again is not the speck's,
// and stays.
TEST(ElementSizes, AnErasedSpecksCatchmentDoesNotClimb) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 40);
    p.at(8, 20) = 0.9f;                               // the speck
    const float ramp[] = {0.4f, 0.3f, 0.35f, 0.45f};  // down from it, then up again
    for (int k = 0; k < 4; ++k) p.at(8, 21 + k) = ramp[k];
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.erased, 1);
    EXPECT_EQ(p.at(8, 20), 0.0f);
    EXPECT_EQ(p.at(8, 21), 0.0f);
    EXPECT_EQ(p.at(8, 22), 0.0f);
    EXPECT_EQ(p.at(8, 23), 0.35f);  // climbs: not the speck's
    EXPECT_EQ(p.at(8, 24), 0.45f);
}

// A speck beside a dot: the dot's grey rim, as low as the speck's own slope, is the dot's.
TEST(ElementSizes, ADotKeepsItsRimBesideAnErasedSpeck) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 30);
    for (int dr = -4; dr <= 4; ++dr)  // a rim of 0.4 one texel round the dot
        for (int dc = -4; dc <= 4; ++dc)
            if (dr * dr + dc * dc > 9 && dr * dr + dc * dc <= 17) p.at(8 + dr, 30 + dc) = 0.4f;
    p.at(8, 36) = 0.9f;  // a speck two texels off the rim, its slope at the rim's level
    p.at(8, 35) = 0.4f;
    Plane expected = p;
    expected.at(8, 36) = 0.0f;
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.erased, 1);
    int rim_lost = 0;
    for (size_t i = 0; i < p.size(); ++i) rim_lost += p.v[i] != expected.v[i];
    EXPECT_LE(rim_lost, 1) << "only the texel between speck and rim may go";
    EXPECT_EQ(p.at(8, 36), 0.0f);
}

// `reach` bounds the catchment: a long slope down from a speck keeps what lies beyond it.
TEST(ElementSizes, TheCatchmentEndsAtItsReach) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 50);
    p.at(8, 10) = 0.9f;
    for (int k = 1; k <= 6; ++k) p.at(8, 10 + k) = 0.45f - 0.05f * float(k);
    impose_element_sizes(p, sizes, 0.0f, 2);
    EXPECT_EQ(p.at(8, 11), 0.0f);
    EXPECT_EQ(p.at(8, 12), 0.0f);
    EXPECT_FLOAT_EQ(p.at(8, 13), 0.30f);  // three steps away
    EXPECT_FLOAT_EQ(p.at(8, 16), 0.15f);
}

// Two dots joined by a bar with a bulge: the bulge is a shallow peak of its own, and its
// boundaries with the dots are close to its depth; it must not chain the dots into one.
TEST(ElementSizes, AShallowBulgeDoesNotChainTwoDotsTogether) {
    const auto disc4 = [](Plane& q, int r0, int c0) {  // radius 4: 49 texels
        for (int dr = -4; dr <= 4; ++dr)
            for (int dc = -4; dc <= 4; ++dc)
                if (dr * dr + dc * dc <= 16) q.at(r0 + dr, c0 + dc) = 1.0f;
    };
    Plane exemplar(20, 80);
    for (int c : {12, 40, 68}) disc4(exemplar, 10, c);
    const ElementSizes sizes = element_sizes(exemplar);
    ASSERT_EQ(sizes.max_area, 49);
    Plane p(20, 64);
    for (int c : {20, 36}) disc4(p, 10, c);
    for (int c = 24; c <= 32; ++c)
        for (int r = 9; r <= 11; ++r) p.at(r, c) = 1.0f;  // a bar three rows thick
    for (int r = 7; r <= 13; ++r)
        for (int c = 27; c <= 29; ++c) p.at(r, c) = 1.0f;  // with a bulge in its middle
    ASSERT_EQ(element_areas(p).size(), 1u);
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.split, 1);
    EXPECT_EQ(element_areas(p).size(), 2u);
}

// Split and trim find their element across the seam, where its columns wrap.
TEST(ElementSizes, SplitAndTrimAcrossTheSeam) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 64);
    dot(p, 8, 61);
    dot(p, 8, 3);  // the pair's neck at column 0
    ASSERT_EQ(count_elements(p), 1);
    EXPECT_EQ(impose_element_sizes(p, sizes, 0.0f, 4).split, 1);
    EXPECT_EQ(element_areas(p).size(), 2u);
    for (int area : element_areas(p)) EXPECT_GE(area, 27);

    Plane q(16, 64);
    dot(q, 8, 62);
    for (int c = 2; c <= 8; ++c) q.at(8, c) = 1.0f;  // a hook leaving the dot's rim at column 1
    EXPECT_EQ(impose_element_sizes(q, sizes, 0.0f, 4).trimmed, 1);
    ASSERT_EQ(element_areas(q).size(), 1u);
    EXPECT_LE(element_areas(q)[0], 29);
    EXPECT_EQ(q.at(8, 8), 0.0f);
}

// A fat oval (two discs of radius 4 two rows and four columns apart): its distance to paper
// has a ridge of equal maxima, not a neck. It is one blob, not three with a strip between.
TEST(ElementSizes, AFatOvalIsNotCutAlongItsRidge) {
    const ElementSizes sizes = three_dots();
    Plane p(20, 64);
    for (const auto& [r0, c0] : {std::pair{9, 28}, std::pair{11, 32}})
        for (int dr = -4; dr <= 4; ++dr)
            for (int dc = -4; dc <= 4; ++dc)
                if (dr * dr + dc * dc <= 16) p.at(r0 + dr, c0 + dc) = 1.0f;
    ASSERT_EQ(element_areas(p).size(), 1u);
    const int area = element_areas(p)[0];
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.split, 0);
    EXPECT_EQ(changes.trimmed, 0);  // it is all body: nothing thinner than the dots sticks out
    ASSERT_EQ(element_areas(p).size(), 1u);
    EXPECT_EQ(element_areas(p)[0], area);
}

// A band far larger than a few elements is not a merged pair: left as it is (and not
// compared texel pair by texel pair).
TEST(ElementSizes, ABandIsNotCutOrTrimmed) {
    const ElementSizes sizes = three_dots();
    Plane p(16, 128);
    for (int r = 6; r <= 10; ++r)
        for (int c = 10; c < 100; ++c) p.at(r, c) = 1.0f;  // 450 texels, over 4 × 29
    for (int c = 100; c < 104; ++c) p.at(8, c) = 1.0f;     // with a thin tail
    const Plane before = p;
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.split + changes.trimmed, 0);
    for (size_t i = 0; i < p.size(); ++i) ASSERT_EQ(p.v[i], before.v[i]);
}

// A small lobe on a dot, a peak of its own past a neck: split off, it would keep fewer
// texels than half the exemplar's smallest element. Not split.
TEST(ElementSizes, ALobeTooSmallToBeAnElementIsNotSplitOff) {
    const auto disc = [](Plane& q, int r0, int c0, int r2) {
        for (int dr = -4; dr <= 4; ++dr)
            for (int dc = -4; dc <= 4; ++dc)
                if (dr * dr + dc * dc <= r2) q.at(r0 + dr, c0 + dc) = 1.0f;
    };
    Plane exemplar(20, 80);
    for (int c : {12, 40, 68}) disc(exemplar, 10, c, 16);  // 49 texels: a piece needs 25
    const ElementSizes sizes = element_sizes(exemplar);
    Plane p(20, 64);
    disc(p, 10, 20, 16);
    disc(p, 10, 27, 6);  // 21 texels, touching the dot's rim
    ASSERT_EQ(element_areas(p).size(), 1u);
    ASSERT_GT(element_areas(p)[0], sizes.max_area);
    const ElementChanges changes = impose_element_sizes(p, sizes, 0.0f, 4);
    EXPECT_EQ(changes.split, 0);
    EXPECT_EQ(element_areas(p).size(), 1u);
}
