// Stroke patterns by example (Barla et al. 2006): element fitting, clustering at scale ε, the
// unskewed Delaunay distribution, Lloyd seeds, synthesis fidelity in numbers, variation.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/random.h"
#include "pattern/cluster.h"
#include "pattern/fidelity.h"
#include "pattern/lloyd.h"
#include "pattern/synthesis.h"
#include "test_support.h"
#include "vector/stroke_io.h"

namespace lw {
namespace {

constexpr float kPi = 3.14159265f;

Stroke segment(glm::vec2 c, float angle, float length, float width = 1.5f, glm::vec3 color = glm::vec3(0.0f)) {
    const glm::vec2 d = 0.5f * length * glm::vec2(std::cos(angle), std::sin(angle));
    return make_stroke({c - d, c + d}, width, color);
}

// Crosses of two strokes each (arms of 16) on a grid 40 apart.
std::vector<Stroke> crosses(int nx, int ny) {
    std::vector<Stroke> s;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const glm::vec2 c(20.0f + 40.0f * float(x), 20.0f + 40.0f * float(y));
            s.push_back(segment(c, 0.1f * float(x), 16.0f));
            s.push_back(segment(c, 0.1f * float(x) + 0.5f * kPi, 16.0f));
        }
    return s;
}

// Flowers: five closed petals around a heart dot, 50 apart.
std::vector<Stroke> flowers(int n) {
    std::vector<Stroke> s;
    for (int f = 0; f < n; ++f) {
        const glm::vec2 c(25.0f + 50.0f * float(f), 25.0f);
        for (int p = 0; p < 5; ++p) {
            const float a = 2.0f * kPi * float(p) / 5.0f;
            const glm::vec2 pc = c + 6.0f * glm::vec2(std::cos(a), std::sin(a));
            std::vector<glm::vec2> loop;
            for (int k = 0; k < 8; ++k) {
                const float t = 2.0f * kPi * float(k) / 8.0f;
                const glm::vec2 uv(4.5f * std::cos(t), 2.2f * std::sin(t));
                loop.push_back(pc + glm::vec2(uv.x * std::cos(a) - uv.y * std::sin(a), uv.x * std::sin(a) + uv.y * std::cos(a)));
            }
            s.push_back(make_stroke(loop, 1.2f, {0.8f, 0.2f, 0.1f}, true));
        }
        s.push_back(make_stroke({c - glm::vec2(0.5f, 0), c + glm::vec2(0.5f, 0)}, 3.0f, {0.2f, 0.1f, 0.0f}));
    }
    return s;
}

size_t strokes_in(const Element& e) { return e.strokes.size(); }

TEST(PatternElement, PcaBoxOfAStroke) {
    const std::vector<Stroke> s{segment({50, 30}, 0.6f, 40.0f, 2.0f)};
    const Element skeleton = fit_element(s, {0}, FitMode::Skeleton);
    EXPECT_NEAR(skeleton.center.x, 50.0f, 1e-3f);
    EXPECT_NEAR(skeleton.center.y, 30.0f, 1e-3f);
    EXPECT_NEAR(skeleton.angle(), 0.6f, 1e-4f);
    EXPECT_NEAR(skeleton.length(), 40.0f, 1e-3f);
    EXPECT_NEAR(skeleton.width(), 0.0f, 1e-3f);
    const Element contour = fit_element(s, {0}, FitMode::Contour);
    EXPECT_NEAR(contour.length(), 42.0f, 1e-2f);  // round caps reach w/2 beyond the ends
    EXPECT_NEAR(contour.width(), 2.0f, 1e-3f);
    // Distances between filled boxes: a point inside is at 0; a nested box is at 0 one way.
    EXPECT_FLOAT_EQ(box_distance(contour, {50, 30}), 0.0f);
    const std::vector<Stroke> two{segment({0, 0}, 0.0f, 20.0f), segment({0, 0}, 0.0f, 8.0f)};
    const Element big = fit_element(two, {0}, FitMode::Skeleton), small = fit_element(two, {1}, FitMode::Skeleton);
    EXPECT_FLOAT_EQ(directed_hausdorff(small, big), 0.0f);
    EXPECT_NEAR(directed_hausdorff(big, small), 6.0f, 1e-4f);
}

TEST(PatternCluster, CrossesMergeAtTheRightScaleAndSplitBelowIt) {
    const std::vector<Stroke> s = crosses(4, 3);
    // Two crossing arms of 16 (+ caps): prox ≈ 8 (half an arm), so ε = 10 groups each cross.
    const std::vector<Element> merged = cluster_strokes(s, 10.0f, FitMode::Contour);
    ASSERT_EQ(merged.size(), 12u);
    for (const Element& e : merged) {
        EXPECT_EQ(strokes_in(e), 2u);
        EXPECT_EQ(e.strokes[1], e.strokes[0] + 1);  // its own two strokes
    }
    EXPECT_EQ(cluster_strokes(s, 3.0f, FitMode::Contour).size(), 24u);
    // Far above the spacing everything is one element.
    EXPECT_EQ(cluster_strokes(s, 60.0f, FitMode::Contour).size(), 1u);
}

TEST(PatternCluster, FlowersBecomeOneElementEach) {
    const std::vector<Stroke> s = flowers(5);
    // A flower is about 22 across; its petals are ~6 apart at their tips (Hausdorff through the
    // boxes), so ε = 10 groups each flower (and not two flowers, 28 apart).
    const std::vector<Element> e = cluster_strokes(s, 10.0f, FitMode::Contour);
    ASSERT_EQ(e.size(), 5u);
    for (const Element& f : e) EXPECT_EQ(strokes_in(f), 6u);
    // At ε = 3 only the heart joins one petal: five elements per flower.
    EXPECT_EQ(cluster_strokes(s, 3.0f, FitMode::Contour).size(), 25u);
}

TEST(PatternCluster, OverlappingSketchyStrokesMergeAndDashesContinue) {
    // 10 hatches, each three overlapping jittered gestures, 16 apart.
    Rng rng(7);
    std::vector<Stroke> s;
    for (int i = 0; i < 10; ++i)
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 c(20.0f + 16.0f * float(i) + float(rng.uniform(-1.0, 1.0)), 40.0f + float(rng.uniform(-2.0, 2.0)));
            s.push_back(segment(c, 1.45f + float(rng.uniform(-0.05, 0.05)), 38.0f, 1.2f));
        }
    const std::vector<Element> e = cluster_strokes(s, 3.0f, FitMode::Contour);
    ASSERT_EQ(e.size(), 10u);
    for (const Element& h : e) EXPECT_EQ(strokes_in(h), 3u);
    // Collinear dashes with gaps of 4: continuation joins them at ε = 5, not at ε = 3.
    std::vector<Stroke> dashes;
    for (int i = 0; i < 5; ++i) dashes.push_back(segment({10.0f + 14.0f * float(i), 10.0f}, 0.0f, 10.0f, 1.0f));
    EXPECT_LT(continuation(fit_element(dashes, {0}, FitMode::Skeleton), fit_element(dashes, {1}, FitMode::Skeleton), 5.0f), 5.0f);
    EXPECT_EQ(cluster_strokes(dashes, 5.0f, FitMode::Skeleton).size(), 1u);
    EXPECT_EQ(cluster_strokes(dashes, 3.0f, FitMode::Skeleton).size(), 5u);
}

// A region must be simple: a figure eight's lobes cancel in the shoelace area (Lloyd's sample
// grid, spaced by that area, never ended), a bow tie's exactly (that one, of no area at all,
// keeps the "has no area" message of a flat region).
TEST(PatternDistribution, ARegionThatCrossesItselfIsRefused) {
    EXPECT_TRUE(polygon_is_simple({{0, 0}, {300, 0}, {300, 300}, {0, 300}}));
    EXPECT_TRUE(polygon_is_simple({{0, 0}, {300, 0}, {300, 0}, {300, 300}, {0, 300}, {0, 0}}));  // repeated corners
    EXPECT_FALSE(polygon_is_simple({{0, 0}, {200, 200}, {200, 0}, {0, 200}}));                   // bow tie
    EXPECT_FALSE(polygon_is_simple({{0, 0}, {100, 0}, {100, 100}, {50, 0}, {0, 100}}));          // touches an edge
    std::vector<glm::vec2> eight;
    for (int i = 0; i < 64; ++i) {
        const float t = 2.0f * kPi * float(i) / 64.0f;
        // Lobes of two sizes, so that their areas do not cancel to 0.
        eight.push_back({(i < 32 ? 100.0f : 60.0f) * std::sin(t), 60.0f * std::sin(t) * std::cos(t)});
    }
    EXPECT_FALSE(polygon_is_simple(eight));
    PatternFrame region;
    region.curve.points = eight;
    region.curve.closed = true;
    try {
        (void)frame_measure(region);
        ADD_FAILURE() << "a figure eight was measured";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the region crosses itself"), std::string::npos) << e.what();
    }
}

TEST(PatternDistribution, DelaunayKeepsOnlyUnskewedTrianglesAndLloydEvensTheSpacing) {
    const std::vector<glm::vec2> square{{0, 0}, {300, 0}, {300, 300}, {0, 300}};
    auto spread = [](const std::vector<glm::vec2>& p) {  // coefficient of variation of NN distances
        const std::vector<float> d = nearest_neighbour_distances(p);
        const double mean = std::accumulate(d.begin(), d.end(), 0.0) / double(d.size());
        double var = 0.0;
        for (float x : d) var += (x - mean) * (x - mean);
        return std::sqrt(var / double(d.size())) / mean;
    };
    double previous = 1e9;
    std::vector<double> spreads;
    for (int iterations : {0, 3, 10, 30}) {
        Rng rng(11);
        const std::vector<glm::vec2> seeds = lloyd_2d(square, 200, iterations, rng);
        ASSERT_EQ(seeds.size(), 200u);
        for (const glm::vec2& p : seeds) ASSERT_TRUE(inside_polygon(square, p));
        const double cv = spread(seeds);
        spreads.push_back(cv);
        EXPECT_LT(cv, previous) << iterations << " iterations";
        previous = cv;
        const Distribution d = delaunay_distribution(seeds);
        float smallest = kPi;
        for (const auto& t : d.triangles) {
            const glm::vec2 a = seeds[size_t(t[0])], b = seeds[size_t(t[1])], c = seeds[size_t(t[2])];
            EXPECT_LE(max_angle(a, b, c), kUnskewedMaxAngle + 1e-5f);
            smallest = std::min(smallest, min_angle(a, b, c));
        }
        if (iterations == 30) {
            // Close to a centroidal Voronoi tessellation: near-equilateral triangles. The
            // unskewed bound (no angle over 2π/3) alone allows angles down to 0; after Lloyd
            // the smallest kept angle stays above 20°, and only thin triangles along the hull
            // are dropped (over 85 % kept).
            EXPECT_GT(smallest, 20.0f * kPi / 180.0f);
            EXPECT_GT(d.triangles.size(), size_t(0.85 * double(delaunay_triangles(seeds).size())));
        }
    }
    EXPECT_LT(spreads.back(), 0.1);  // random points: about 0.5
    EXPECT_GT(spreads.front(), 0.3);
    // Every kept edge is symmetric; a 1D chain links neighbours in order of s.
    const Distribution chain = chain_distribution({{30, 0}, {10, 0}, {20, 1}}, 0.0f);
    EXPECT_EQ(chain.neighbours[1], std::vector<int>({2}));
    EXPECT_EQ(chain.neighbours[2], std::vector<int>({0, 1}));
    EXPECT_NEAR(chain.shift[2].y, 1.0f, 1e-6f);
    // Lloyd in 1D converges to even spacing (the ends inset by half a spacing).
    Rng rng(3);
    const std::vector<float> s = lloyd_1d(10, 100.0f, false, 200, rng);
    for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(s[i], 5.0f + 10.0f * float(i), 0.05f);
}

StrokeSet load_pattern(const char* name) { return load_strokes(test::source_dir() / "scenes" / "patterns" / name); }

PatternFrame straight_path(float x0, float x1, float y) {
    PatternFrame f;
    f.along_path = true;
    f.curve.points = {{x0, y}, {x1, y}};
    return f;
}

PatternFrame square_region(float size) {
    PatternFrame f;
    f.curve.points = {{0, 0}, {size, 0}, {size, size}, {0, size}};
    f.curve.closed = true;
    return f;
}

TEST(PatternSynthesis, TwoDimensionalDistributionsMatchTheReference) {
    // Bars in four directions: orientation, length, thickness, colour and spacing.
    const StrokeSet bars = load_pattern("multi_bars.svg");
    PatternDesc desc{.epsilon = 3.0f, .seed = 5};
    const PatternAnalysis ref = analyze_pattern(bars.strokes, bounding_frame(bars.strokes, false), desc);
    ASSERT_GT(ref.elements.size(), 80u);
    const PatternFrame target = square_region(400.0f);
    const PatternSynthesis s = synthesize_pattern(ref, target, desc);
    const double expected = double(ref.elements.size()) * 400.0 * 400.0 / double(ref.measure);
    EXPECT_NEAR(double(s.source.size()), expected, 1.0);
    const PatternFidelity f = measure_fidelity(ref, s, target, desc.fit);
    // Bound: the two-sample KS critical value at α = 0.05 (about 0.17 here).
    EXPECT_LT(f.ks_orientation, f.critical);
    EXPECT_LT(f.ks_length, f.critical);
    EXPECT_LT(f.ks_thickness, f.critical);
    EXPECT_LT(f.ks_color, f.critical);
    // Lloyd spaces the seeds as evenly as the reference on average (N_tar = N_ref·A_tar/A_ref).
    EXPECT_NEAR(f.median_nn_output / f.median_nn_reference, 1.0, 0.15);
    EXPECT_GT(s.matched, int(0.6 * double(s.source.size())));  // the rest take the closest neighbourhood
}

TEST(PatternSynthesis, AlternatingColoursStayAlternating) {
    const StrokeSet ref_set = load_pattern("alternating_colours.svg");
    PatternDesc desc{.rings = 2, .seed = 9};
    const PatternAnalysis ref = analyze_pattern(ref_set.strokes, bounding_frame(ref_set.strokes, true), desc);
    ASSERT_EQ(ref.elements.size(), 26u);
    const PatternFrame target = straight_path(0.0f, 800.0f, 100.0f);
    const PatternSynthesis s = synthesize_pattern(ref, target, desc);
    ASSERT_GT(s.source.size(), 40u);
    // Along the path, neighbours differ in colour.
    std::vector<size_t> order(s.source.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return s.target.positions[a].x < s.target.positions[b].x; });
    size_t alternations = 0;
    for (size_t i = 1; i < order.size(); ++i) {
        const glm::vec3 a = ref.elements[size_t(s.source[order[i - 1]])].color;
        const glm::vec3 b = ref.elements[size_t(s.source[order[i]])].color;
        alternations += glm::length(a - b) > 0.3f;
    }
    EXPECT_EQ(alternations, order.size() - 1);
    const PatternFidelity f = measure_fidelity(ref, s, target, desc.fit);
    EXPECT_LT(f.ks_color, f.critical);
    EXPECT_LT(f.ks_orientation, f.critical);
}

// Spearman rank correlation.
double spearman(const std::vector<double>& x, const std::vector<double>& y) {
    auto ranks = [](const std::vector<double>& v) {
        std::vector<size_t> idx(v.size());
        std::iota(idx.begin(), idx.end(), 0);
        std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
        std::vector<double> r(v.size());
        for (size_t i = 0; i < idx.size(); ++i) r[idx[i]] = double(i);
        return r;
    };
    const std::vector<double> rx = ranks(x), ry = ranks(y);
    const double n = double(x.size());
    double d2 = 0.0;
    for (size_t i = 0; i < x.size(); ++i) d2 += (rx[i] - ry[i]) * (rx[i] - ry[i]);
    return 1.0 - 6.0 * d2 / (n * (n * n - 1.0));
}

TEST(PatternSynthesis, SmoothOrientationChangeIsReproducedWithFiveRings) {
    const StrokeSet ref_set = load_pattern("orientation_gradient.svg");
    PatternDesc desc{.rings = 5, .seed = 1};
    const PatternFrame ref_frame = bounding_frame(ref_set.strokes, true);
    const PatternAnalysis ref = analyze_pattern(ref_set.strokes, ref_frame, desc);
    ASSERT_EQ(ref.elements.size(), 30u);
    // A path as long as the reference, drawn elsewhere: the gradient must come out in order.
    const float length = frame_measure(ref_frame);
    double worst = 1.0, mean_step = 0.0;
    int runs = 0;
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        desc.seed = seed;
        const PatternFrame target = straight_path(100.0f, 100.0f + length, 300.0f);
        const PatternSynthesis s = synthesize_pattern(ref, target, desc);
        std::vector<double> position, angle;
        for (size_t e = 0; e < s.source.size(); ++e) {
            position.push_back(s.target.positions[e].x);
            angle.push_back(ref.local[size_t(s.source[e])].angle());
        }
        worst = std::min(worst, spearman(position, angle));
        std::vector<size_t> order(position.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return position[a] < position[b]; });
        for (size_t i = 1; i < order.size(); ++i) mean_step += std::abs(angle[order[i]] - angle[order[i - 1]]);
        runs += int(order.size()) - 1;
    }
    mean_step /= double(runs);
    // Reference: 140° over 29 steps, 4.8° per step, rank correlation 1.
    EXPECT_GT(worst, 0.9);
    EXPECT_LT(mean_step, 9.0 * kPi / 180.0);  // σ_par: neighbours stay parallel-ish
}

TEST(PatternSynthesis, VariationExchangesParametersAndBringsBackPositions) {
    const StrokeSet ref_set = load_pattern("hatch_sketchy.svg");
    const PatternFrame ref_frame = bounding_frame(ref_set.strokes, true);
    PatternDesc plain{.epsilon = 5.0f, .seed = 4};
    const PatternAnalysis ref = analyze_pattern(ref_set.strokes, ref_frame, plain);
    EXPECT_EQ(ref.elements.size(), 24u);  // each hatch drawn with 2–3 gestures is one element
    const PatternFrame target = straight_path(0.0f, 700.0f, 50.0f);
    PatternDesc varied = plain;
    varied.variation = 1.0f;
    const PatternSynthesis a = synthesize_pattern(ref, target, plain);
    const PatternSynthesis b = synthesize_pattern(ref, target, varied);
    ASSERT_EQ(a.source, b.source);  // same seed: same choices before the post-process
    // Without variation every centre lies on the path; with it the reference's offsets return.
    float offset_a = 0.0f, offset_b = 0.0f;
    for (const glm::vec2& c : a.centers) offset_a = std::max(offset_a, std::abs(c.y - 50.0f));
    for (const glm::vec2& c : b.centers) offset_b = std::max(offset_b, std::abs(c.y - 50.0f));
    EXPECT_LT(offset_a, 1e-3f);
    EXPECT_GT(offset_b, 0.3f);
    const PatternFidelity f = measure_fidelity(ref, b, target, plain.fit);
    EXPECT_LT(f.ks_length, f.critical);
    EXPECT_LT(f.ks_orientation, f.critical);
}

TEST(PatternSynthesis, SameSeedSameOutput) {
    const StrokeSet ref_set = load_pattern("flowers.svg");
    PatternDesc desc{.epsilon = 10.0f, .seed = 21};
    const PatternAnalysis ref = analyze_pattern(ref_set.strokes, bounding_frame(ref_set.strokes, false), desc);
    EXPECT_EQ(ref.elements.size() * 6, ref_set.strokes.size());  // one element per flower (six strokes)
    const PatternSynthesis a = synthesize_pattern(ref, square_region(200.0f), desc);
    const PatternSynthesis b = synthesize_pattern(ref, square_region(200.0f), desc);
    EXPECT_EQ(strokes_to_svg(a.strokes), strokes_to_svg(b.strokes));
    desc.seed = 22;
    EXPECT_NE(strokes_to_svg(synthesize_pattern(ref, square_region(200.0f), desc).strokes), strokes_to_svg(a.strokes));
}

}  // namespace
}  // namespace lw
