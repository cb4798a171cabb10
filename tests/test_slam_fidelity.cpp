// SLAM fidelity (slam_synth/slam_fidelity.h): the measures on planes whose answer is known,
// the exemplar as a fixed point of the synthesis, and every exemplar of scenes/exemplars
// synthesized as `linework slam` does (17 levels, Lmax 1024, 15 iterations, seed 1) against
// its own grain, elements and empty rows, and against the smooth variation of before.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image_io.h"
#include "slam_synth/seed_pyramid.h"
#include "slam_synth/slam_builder.h"
#include "slam_synth/slam_conditions.h"
#include "slam_synth/slam_fidelity.h"
#include "slam_synth/texture_synthesis.h"
#include "test_slam_support.h"
#include "test_support.h"

using namespace lw::synth;

namespace {

void disc(Plane& p, double cx, double cy, double r, float ink = 1.0f) {
    for (int y = 0; y < p.rows; ++y)
        for (int x = 0; x < p.cols; ++x)
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) p.at(y, x) = ink;
}

Plane exemplar(const std::string& name) {
    return exemplar_ink(lw::read_image_rgba8((lw::test::source_dir() / "scenes/exemplars" / ("slam-" + name + ".png")).string()));
}

}  // namespace

TEST(SlamFidelityMeasures, GrainOfASineIsItsSecondDifference) {
    // I(x) = c + A sin(2πx/P): I(x−1) − 2I(x) + I(x+1) = −4 sin²(π/P)·A sin(2πx/P), and the
    // mean of |sin(2πx/P)| over the P samples of a period is (2/P)·cot(π/P).
    constexpr int rows = 3, period = 32, cols = 8 * period;
    constexpr double amplitude = 0.4;
    Plane p(rows, cols);
    for (int r = 0; r < rows; ++r)
        for (int x = 0; x < cols; ++x) p.at(r, x) = float(0.5 + amplitude * std::sin(2 * std::numbers::pi * x / period));
    const double expected = 4 * std::pow(std::sin(std::numbers::pi / period), 2) * amplitude * (2.0 / period) /
                            std::tan(std::numbers::pi / period);
    EXPECT_NEAR(grain(p, true), expected, 1e-3 * expected);
    // Not periodic: the first and last columns have no neighbour and are left out (the
    // sine's values there add nothing of their own).
    EXPECT_NEAR(grain(p, false), expected, 0.02 * expected);
    EXPECT_EQ(grain(Plane(rows, cols, 0.7f), true), 0.0);
}

TEST(SlamFidelityMeasures, ElementsCountAreasAndHoles) {
    Plane p(16, 128);
    disc(p, 20, 8, 4);
    disc(p, 60, 8, 4);
    disc(p, 100, 8, 5);
    disc(p, 100, 8, 2, 0.0f);  // a hollow dot: paper enclosed by ink
    const ElementStatistics e = element_statistics(p, true);
    EXPECT_EQ(e.count, 3);
    EXPECT_EQ(e.holes, 1);
    EXPECT_NEAR(e.per_100_texels, 300.0 / 128, 1e-9);
    // Areas: the discs' texel counts, counted here independently.
    std::vector<double> areas(3, 0.0);
    for (int y = 0; y < p.rows; ++y)
        for (int x = 0; x < p.cols; ++x)
            if (p.at(y, x) > kElementInk) areas[size_t(x < 40 ? 0 : x < 80 ? 1 : 2)] += 1;
    const double mean = (areas[0] + areas[1] + areas[2]) / 3;
    double variance = 0;
    for (double a : areas) variance += (a - mean) * (a - mean) / 3;
    EXPECT_NEAR(e.mean_area, mean, 1e-9);
    EXPECT_NEAR(e.area_cv, std::sqrt(variance) / mean, 1e-9);

    // Across the wrap: one element when periodic, two cut ones (left out) when not.
    Plane wrap(16, 64);
    disc(wrap, 0, 8, 4);
    disc(wrap, 64, 8, 4);
    EXPECT_EQ(element_statistics(wrap, true).count, 1);
    EXPECT_EQ(element_statistics(wrap, false).count, 0);
    // A hollow dot across the wrap is one element with one hole.
    disc(wrap, 0, 8, 2, 0.0f);
    disc(wrap, 64, 8, 2, 0.0f);
    EXPECT_EQ(element_statistics(wrap, true).holes, 1);
    // Lines that go all the way round are no elements, and the paper between them no hole.
    Plane lines(16, 64);
    for (int x = 0; x < 64; ++x) lines.at(4, x) = lines.at(11, x) = 1.0f;
    EXPECT_EQ(element_statistics(lines, true).count, 0);
    EXPECT_EQ(element_statistics(lines, true).holes, 0);
    EXPECT_EQ(element_statistics(lines, false).holes, 0);
    // Paper touching the first or last row is not a hole, whatever it is surrounded by.
    Plane band(8, 32, 1.0f);
    for (int x = 10; x < 14; ++x) band.at(0, x) = 0.0f;
    EXPECT_EQ(element_statistics(band, true).holes, 0);
}

TEST(SlamFidelityMeasures, StrayInkCountsSpecksInTheExemplarsEmptyRows) {
    Plane ex(8, 64);
    for (int r = 2; r < 6; ++r)
        for (int x = 0; x < 64; ++x) ex.at(r, x) = 1.0f;
    ex.at(0, 5) = 0.5f * kEmptyRowInk;  // below the threshold: row 0 is still empty
    Plane level(8, 100);
    level.at(0, 3) = 0.5f;
    level.at(7, 40) = 0.2f;
    level.at(1, 41) = 0.5f * kStrayInk;  // too faint to count
    level.at(3, 10) = 1.0f;              // ink in an inky row is no stray
    const StrayInk s = stray_ink(ex, level);
    EXPECT_EQ(s.empty_rows, 4);
    EXPECT_NEAR(s.share, 2.0 / 400.0, 1e-12);
}

// The exemplar has the target statistics, so the last iteration (the one that keeps the
// high-pass residual: a whole iteration of the model) must leave it almost unchanged.
// Reconstructing the residual through H once (not H²) let the transition band through with
// a gain above 1: 3e-3 in mean on this exemplar, 0.07 at worst. (Earlier iterations drop
// the residual, so from the exemplar they do change it.)
TEST(SlamFidelitySynthesis, ExemplarIsAFixedPointOfTheLastIteration) {
    const Plane ink = exemplar("wedges");
    const SlamModel m = slam_model(ink.rows, "wedges");
    const int cols = ink.cols / m.unit * m.unit;
    const Plane padded = pad_exemplar(ink, m, cols);
    const PyramidGeometry g = make_pyramid_geometry(m.padded_rows, cols, m.scales, 4);
    const Plane out = synthesize_texture(analyze_texture(padded, g, 9), padded, g, {.iterations = 1});
    double sum = 0, worst = 0;
    for (size_t i = 0; i < out.size(); ++i) {
        const double d = std::abs(double(out.v[i]) - double(padded.v[i]));
        sum += d;
        worst = std::max(worst, d);
    }
    std::printf("  one iteration from the exemplar: mean |change| %.5f, largest %.4f\n", sum / double(out.size()), worst);
    EXPECT_LT(sum / double(out.size()), 1e-3);
    EXPECT_LT(worst, 0.03);
}

// Where the element-size step acts (the identical dots), erasing, cutting and trimming ink
// moves the rows' means; the row steps after it must still leave every row within 5 % of the
// exemplar's (as tests/test_slam_synth.cpp holds a synthetic exemplar to).
TEST(SlamFidelitySynthesis, RowsKeepTheirStatisticsWhereElementSizesAreImposed) {
    const Plane ink = exemplar("beads");
    const SlamModel m = slam_model(ink.rows, "beads");
    const int cols = ink.cols / m.unit * m.unit, length = 512;
    const TextureStatistics target =
        analyze_texture(pad_exemplar(ink, m, cols), make_pyramid_geometry(m.padded_rows, cols, m.scales, 4), 9);
    ASSERT_TRUE(target.elements.alike());
    const PyramidGeometry g = make_pyramid_geometry(m.padded_rows, length, m.scales, 4);
    // One iteration before the last, the plane already has elements the step would mend
    // (seed 2): a stand-in for what the last iteration's own pyramid pass leaves it.
    ElementChanges before_last;
    const auto look = [&](int iteration, const Plane& image) {
        if (iteration != 13) return;
        Plane copy = image;
        before_last = impose_element_sizes(copy, target.elements, float(target.pixel.min), target.neighborhood / 2);
    };
    const Plane result = synthesize_texture(target, seed_level(half_seed(m.padded_rows, length, 2), 1.0, length), g,
                                            {.iterations = 15, .on_iteration = look});
    EXPECT_GT(before_last.erased + before_last.split + before_last.trimmed, 0);
    lw::test::expect_rows_within_5_percent(result, target);
}

// Every SLAM exemplar, as `linework slam` makes it. Bounds: the grain of every level ≤ 1.5×
// the exemplar's; stray ink ≤ 0.2 % of the empty rows (the 1.5D rows keep them empty; the
// 1D model does not, StrayInkIsWhatTheRowsPrevent); RMSE(1)/RMSE(16) no worse than 1.05×
// what the synthesis gave before this change (seed 1; across seeds 1–4 the ratio varies by
// ±5 %, docs/research/slam-fidelity.md); for the identical dots, as many elements as the
// exemplar within 10 % and an area spread of at most 0.15 at level 1.0 and over the levels
// (0.124 and 0.115 measured; 0.159 and 0.195 before the element-size step); for the
// identical dots, the irregular dots and the dashes, no hollow element on any of the 17
// levels (the enclosed-paper step, enclosed_ink.h: 14, 10 and 19 over the levels without
// it).
struct ExemplarCase {
    const char* name;
    double ratio_before;  // RMSE(1)/RMSE(16) at 17 levels, seed 1, before (commit 00e9fc5)
    int holes_before = 0;  // level 1.0's holes before the enclosed-paper step (commit 5d7e61b)
};
// Printed by name (gtest's default prints the bytes, a pointer among them, into test names).
void PrintTo(const ExemplarCase& c, std::ostream* os) { *os << c.name; }
class SlamFidelityExemplar : public ::testing::TestWithParam<ExemplarCase> {};

// Sanitized or unoptimised builds run about ten times slower and check memory, not
// figures: there the 8- and 16-row exemplars (2 and 3 scales) stand for all; 32 rows are
// synthesized under sanitizers by StrayInkIsWhatTheRowsPrevent (beads here: 13 s more).
#if defined(__SANITIZE_ADDRESS__) || !defined(__OPTIMIZE__)
constexpr bool kSlowBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSlowBuild = true;
#else
constexpr bool kSlowBuild = false;
#endif
#else
constexpr bool kSlowBuild = false;
#endif

TEST_P(SlamFidelityExemplar, ResemblesItsExemplar) {
    const ExemplarCase c = GetParam();
    const std::string name = c.name;
    if (kSlowBuild && name != "wedges" && name != "wobble")
        GTEST_SKIP() << "sanitized or unoptimised build: the 8- and 16-row exemplars only";
    const Plane ink = exemplar(c.name);
    const SlamSynthesis s = synthesize_slam(ink, {.exemplar_name = c.name});
    const SlamConditions conditions = measure_slam_conditions(s);
    const double ratio = conditions.rmse_adjacent / conditions.rmse_ends;
    const double exemplar_grain = grain(ink, false);
    const LevelFidelity top = level_fidelity(ink, s.levels.back());
    double worst_grain = 0.0;
    for (const Plane& level : s.levels) worst_grain = std::max(worst_grain, grain(level, true));
    const ElementStatistics own = element_statistics(ink, false);
    std::printf("  %s: grain %.4f (exemplar %.4f, %.2fx), ratio %.3f (before %.3f), elements %.2f/100 (exemplar %.2f), "
                "area cv %.3f, holes %d, stray %.4f %%\n",
                c.name, top.grain, exemplar_grain, top.grain / exemplar_grain, ratio, c.ratio_before,
                top.elements.per_100_texels, own.per_100_texels, top.elements.area_cv, top.elements.holes,
                100 * top.stray.share);
    EXPECT_LE(worst_grain, 1.5 * exemplar_grain);
    EXPECT_LE(top.stray.share, 0.002);
    EXPECT_LE(ratio, 1.05 * c.ratio_before);
    // Identical dots (the point: area CV at most 0.15; the authors' artmap has 0.16):
    // at level 1.0 and on the mean over the levels, which the element-size step holds
    // (0.159 and 0.195 without it on this seed; element_sizes.h).
    if (name == "beads") {
        EXPECT_NEAR(top.elements.per_100_texels, own.per_100_texels, 0.1 * own.per_100_texels);
        EXPECT_LE(top.elements.area_cv, 0.15);
        double sum = 0.0;
        for (const Plane& level : s.levels) sum += element_statistics(level, true).area_cv;
        EXPECT_LE(sum / double(s.levels.size()), 0.15);
    }
    // Exemplars of separate elements with no enclosed paper: no level has a hollow element.
    if (name == "beads" || name == "dots" || name == "dashes") {
        ASSERT_EQ(own.holes, 0);
        for (size_t i = 0; i < s.levels.size(); ++i)
            EXPECT_EQ(element_statistics(s.levels[i], true).holes, 0) << "level " << s.reports[i].level;
    }
    // Exemplars that enclose paper keep it: level 1.0's holes against those measured before
    // the enclosed-paper step (lattice 40, scribble 14, spatter 106; with it the same).
    if (c.holes_before > 0) {
        EXPECT_GE(top.elements.holes, 0.9 * c.holes_before);
    }
}

INSTANTIATE_TEST_SUITE_P(Exemplars, SlamFidelityExemplar,
                         ::testing::Values(ExemplarCase{"beads", 0.392}, ExemplarCase{"brush", 0.185},
                                           ExemplarCase{"dashes", 0.352}, ExemplarCase{"dots", 0.318},
                                           ExemplarCase{"lattice", 0.396, 40}, ExemplarCase{"pencil", 0.242},
                                           ExemplarCase{"scribble", 0.366, 14}, ExemplarCase{"spatter", 0.254, 106},
                                           ExemplarCase{"wedges", 0.201}, ExemplarCase{"wobble", 0.453}),
                         [](const ::testing::TestParamInfo<ExemplarCase>& p) { return std::string(p.param.name); });

// The list above is every exemplar there is: a new one must be added to it.
TEST(SlamFidelitySynthesis, EveryExemplarIsMeasured) {
    std::vector<std::string> listed, found;
    for (const char* name : {"beads", "brush", "dashes", "dots", "lattice", "pencil", "scribble", "spatter", "wedges", "wobble"})
        listed.push_back(name);
    for (const auto& entry : std::filesystem::directory_iterator(lw::test::source_dir() / "scenes/exemplars")) {
        const std::string stem = entry.path().stem().string();
        if (stem.rfind("slam-", 0) == 0 && entry.path().extension() == ".png") found.push_back(stem.substr(5));
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, listed);
}

// Stray ink measures something: the 1D model (every statistic per texture) puts ink in the
// rows the exemplar leaves empty, which the 1.5D rows keep empty.
TEST(SlamFidelitySynthesis, StrayInkIsWhatTheRowsPrevent) {
    const Plane ink = exemplar("beads");
    auto stray = [&](StatisticsScope scope) {
        const SlamSynthesis s = synthesize_slam(ink, {.levels = 2, .scope = scope, .exemplar_name = "beads"});
        return level_fidelity(ink, s.levels.back()).stray.share;
    };
    const double rows = stray(StatisticsScope::Rows), global = stray(StatisticsScope::Global);
    std::printf("  stray ink in the empty rows: %.4f %% (1.5D), %.2f %% (1D)\n", 100 * rows, 100 * global);
    EXPECT_LE(rows, 0.002);
    EXPECT_GT(global, 0.01);
}
