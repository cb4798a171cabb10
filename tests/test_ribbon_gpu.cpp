// Ribbon patterns on the GPU (lavapipe, validation layer on): every kernel of §2 against the
// C++ reference, the prefix scan over many blocks, stitching, the avoidance map and drawing.
#include <algorithm>
#include <cmath>

#include "ribbon/dp_gpu.h"
#include "ribbon/dp_reference.h"
#include "ribbon/draw_reference.h"
#include "ribbon/exemplar_gen.h"
#include "ribbon/ribbon_draw.h"
#include "ribbon/synthesize.h"
#include "test_ribbon_support.h"

namespace lw {
namespace {

using test::GpuTest;

Curve2D wave_curve(int points, float step, float amplitude, float frequency) {
    Curve2D c;
    for (int i = 0; i <= points; ++i)
        c.points.push_back({12.0f + step * float(i), 50.0f + amplitude * std::sin(float(i) * frequency)});
    return c;
}

Curve2D circle_curve(glm::vec2 centre, float radius, int points) {
    Curve2D c{{}, true};
    for (int i = 0; i < points; ++i) {
        const float a = 2.0f * float(M_PI) * float(i) / float(points);
        c.points.push_back(centre + radius * glm::vec2(std::cos(a), std::sin(a)));
    }
    return c;
}

// A figure eight on a 160 × 100 canvas (it crosses itself) ending in a hairpin (it folds over).
Curve2D eight_with_hairpin() {
    Curve2D eight;
    for (int i = 0; i <= 100; ++i) {
        const float t = float(i) / 100.0f * 2.0f * float(M_PI);
        eight.points.push_back({80.0f + 55.0f * std::sin(t), 50.0f + 30.0f * std::sin(2.0f * t)});
    }
    eight.points.push_back({80.0f, 75.0f});
    eight.points.push_back({50.0f, 75.0f});
    return eight;
}

void expect_same_tables(const DpTables& cpu, const DpTables& gpu) {
    ASSERT_EQ(cpu.valid.size(), gpu.valid.size());
    for (size_t r = 0; r < cpu.valid.size(); ++r) {
        EXPECT_EQ(cpu.valid[r], gpu.valid[r]) << "valid positions of row " << r;
        EXPECT_EQ(cpu.back[r], gpu.back[r]) << "back pointers of row " << r;
    }
    EXPECT_EQ(cpu.last_costs, gpu.last_costs);
}

TEST_F(GpuTest, RibbonCostTablesAndPositionsEqualTheReference) {
    const Exemplar e = make_exemplar(generate_exemplar("zigzag", 64, 24, 5), "zigzag");
    const Ribbon r = build_ribbon(ArclengthCurve(wave_curve(30, 4.0f, 18.0f, 0.2f)), {.width = 30, .piece = 9, .scale = 24});
    const DpProblem p = build_problem(e, r);
    DpRunOptions keep;
    keep.keep_cost_tables = true;
    const DpTables cpu = run_dp_reference(p, keep);
    RibbonDpGpu gpu(ctx());
    const DpTables g = gpu.run(p, keep);
    expect_same_tables(cpu, g);
    ASSERT_EQ(g.cost_tables.size(), cpu.cost_tables.size());
    size_t compared = 0;
    for (size_t row = 1; row < cpu.cost_tables.size(); ++row) {
        ASSERT_EQ(g.cost_tables[row].size(), cpu.cost_tables[row].size()) << row;
        for (size_t k = 0; k < cpu.cost_tables[row].size(); ++k)
            if (g.cost_tables[row][k] != cpu.cost_tables[row][k]) {
                ADD_FAILURE() << "row " << row << " entry " << k << ": GPU " << g.cost_tables[row][k] << ", CPU "
                              << cpu.cost_tables[row][k];
                break;
            }
        compared += cpu.cost_tables[row].size();
    }
    EXPECT_GT(compared, 10000u);

    const RibbonSolution a = solve_ribbon(p, run_dp_reference, 4), b = solve_ribbon(p, gpu.runner(), 4);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.total_cost, b.total_cost);
    EXPECT_EQ(a.valid_counts, b.valid_counts);
    EXPECT_EQ(a.rules, b.rules);
    EXPECT_EQ(b.row_ms.size(), p.rows.size() - 1);
}

TEST_F(GpuTest, RibbonChunkedCostTableGivesTheSameResult) {
    const Exemplar e = make_exemplar(generate_exemplar("beads", 64, 24, 2), "beads");
    const Ribbon r = build_ribbon(ArclengthCurve(wave_curve(20, 4.0f, 10.0f, 0.3f)), {.width = 24, .piece = 8, .scale = 24});
    const DpProblem p = build_problem(e, r);
    RibbonDpGpu gpu(ctx());
    DpRunOptions small;
    small.max_table_bytes = 64 << 10;  // several chunks per row
    expect_same_tables(gpu.run(p), gpu.run(p, small));
}

TEST_F(GpuTest, RibbonRelaxedRowsOnGpuEqualReference) {
    // A hairpin tighter than the pieces can slice: some rows need a looser rule. Its radius is
    // 3 px under a 16 px ribbon (its legs, 6 px apart, overlap; no avoidance map here): copied
    // along their chords, pieces round a radius of 9 px with the strict rule.
    Curve2D hairpin;
    for (int i = 0; i <= 20; ++i) hairpin.points.push_back({10.0f + 3.0f * float(i), 20.0f});
    for (int k = 1; k < 12; ++k)
        hairpin.points.push_back({70.0f + 3.0f * std::sin(float(M_PI) * float(k) / 12.0f),
                                  23.0f - 3.0f * std::cos(float(M_PI) * float(k) / 12.0f)});
    for (int i = 0; i <= 20; ++i) hairpin.points.push_back({70.0f - 3.0f * float(i), 26.0f});
    const Exemplar e = make_exemplar(generate_exemplar("rope", 64, 24, 2), "rope");
    const DpProblem p = build_problem(e, build_ribbon(ArclengthCurve(hairpin), {.width = 16, .piece = 10, .scale = 24}));
    RibbonDpGpu gpu(ctx());
    const RibbonSolution a = solve_ribbon(p, run_dp_reference, 3), b = solve_ribbon(p, gpu.runner(), 3);
    EXPECT_TRUE(std::any_of(a.rules.begin(), a.rules.end(), [](ValidityRule r) { return r != ValidityRule::Band; }));
    EXPECT_EQ(a.rules, b.rules);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.total_cost, b.total_cost);
}

TEST_F(GpuTest, RibbonClosedCurveOnGpuEqualsReference) {
    const Exemplar e = make_exemplar(generate_exemplar("chain", 64, 24, 1), "chain");
    const Ribbon r = build_ribbon(ArclengthCurve(circle_curve({60, 60}, 36, 96)), {.width = 24, .piece = 12, .scale = 24});
    const DpProblem p = build_problem(e, r);
    RibbonDpGpu gpu(ctx());
    const RibbonSolution a = solve_ribbon(p, run_dp_reference, 2), b = solve_ribbon(p, gpu.runner(), 2);
    ASSERT_EQ(b.positions.size(), r.pieces.size() + 1);
    EXPECT_EQ(b.positions.back(), b.positions.front());
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.total_cost, b.total_cost);
    EXPECT_EQ(b.total_cost, path_cost(p, b.positions));
}

TEST_F(GpuTest, RibbonScanCompactsManyBlocks) {
    // One piece over a 600 × 300 exemplar with s = 300: U = 600 · 600 = 360,000 positions,
    // 704 scan blocks — more than one pass of the block-sum scan (512 per pass).
    const Exemplar e = make_exemplar(generate_exemplar("beads", 600, 300, 9), "big beads");
    const Ribbon r = build_ribbon(ArclengthCurve(Curve2D{{{0, 200}, {3, 200}}, false}),
                                  {.width = 300, .piece = 3, .scale = 300});
    const DpProblem p = build_problem(e, r);
    ASSERT_EQ(p.rows.size(), 1u);
    ASSERT_GT(p.position_count(), 512u * 512u);
    RibbonDpGpu gpu(ctx());
    const DpTables g = gpu.run(p);
    const std::vector<uint32_t> cpu = compact_valid_positions(find_valid_positions(p, 0));
    EXPECT_GT(cpu.size(), 1000u);
    EXPECT_EQ(g.valid[0], cpu);
}

TEST_F(GpuTest, RibbonStitchOnGpuEqualsReferenceAndLowersSeamError) {
    const Exemplar e = make_exemplar(generate_exemplar("zigzag", 64, 24, 3), "zigzag");
    const Ribbon r = build_ribbon(ArclengthCurve(wave_curve(40, 4.0f, 22.0f, 0.15f)), {.width = 30, .piece = 8, .scale = 24});
    const DpProblem p = build_problem(e, r);
    RibbonDpGpu gpu(ctx());
    const RibbonSolution s = solve_ribbon(p, gpu.runner(), 1);
    const StitchResult cpu = stitch_reference(p, s.positions);
    const StitchResult g = RibbonStitcherGpu(ctx()).stitch(p, s.positions);
    EXPECT_EQ(g.remap, cpu.remap);
    EXPECT_EQ(g.error_before, cpu.error_before);
    EXPECT_EQ(g.error_after, cpu.error_after);
    EXPECT_EQ(g.error_before, s.seam_costs);
    EXPECT_LT(g.total_after(), g.total_before());
    const StitchResult batched = RibbonStitcherGpu(ctx()).stitch(p, s.positions, 4096);  // a few seams per dispatch
    EXPECT_EQ(batched.remap, cpu.remap);
    EXPECT_EQ(batched.error_after, cpu.error_after);
}

TEST_F(GpuTest, RibbonAvoidanceMapMatchesTheReference) {
    const Ribbon r = build_ribbon(ArclengthCurve(circle_curve({50, 50}, 14, 64)), {.width = 36, .piece = 6, .scale = 24});
    const RibbonRenderer renderer(ctx());
    const std::vector<uint8_t> gpu = renderer.coverage_counts(r, 100, 100);
    const std::vector<uint8_t> cpu = coverage_counts_reference(r, 100, 100);
    size_t differ = 0, covered = 0;
    for (size_t i = 0; i < cpu.size(); ++i) {
        differ += gpu[i] != cpu[i];
        covered += cpu[i] > 0;
    }
    EXPECT_GT(covered, 2000u);
    EXPECT_LT(differ, covered / 50) << "the rasterizers may differ only on pixel centres on an edge";
    EXPECT_GT(renderer.avoidance_map(r, 100, 100).count(), 200u);
}

TEST_F(GpuTest, RibbonNoOpaquePixelInForbiddenRegions) {
    // A figure eight (it crosses itself), a hairpin at its end (folds over) and a user's
    // forbidden disc; drawn with and without the stitching deformation.
    const Curve2D eight = eight_with_hairpin();
    const int W = 160, H = 100;
    ForbiddenMask user{W, H, std::vector<uint8_t>(size_t(W) * H, 0)};
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (glm::length(glm::vec2(x, y) - glm::vec2(135, 50)) < 7.0f) user.pixels[size_t(y) * W + size_t(x)] = 1;
    const Exemplar e = make_exemplar(generate_exemplar("chain", 64, 24, 4), "chain");
    RibbonSynthesisDesc desc;
    desc.params = {.width = 20, .piece = 6, .scale = 24};
    desc.width = W;
    desc.height = H;
    desc.stitch = true;
    desc.user_forbidden = &user;
    const RibbonSynthesis s = synthesize_ribbon(ctx(), e, ArclengthCurve(eight), desc);
    const ImageRGBA8 plain = RibbonRenderer(ctx()).draw(s.ribbon, e, s.solution.positions, nullptr, &s.forbidden, W, H);
    for (const ImageRGBA8* image : {&s.image, &plain}) {
        size_t forbidden = 0, ink = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const bool opaque = image->at(x, y)[3] >= 128;
                ink += opaque;
                if (!s.forbidden.at(x, y)) continue;
                ++forbidden;
                EXPECT_FALSE(opaque) << "opaque output pixel " << x << "," << y << " in a forbidden region"
                                     << (image == &plain ? "" : " (stitched)");
            }
        EXPECT_GT(forbidden, 300u);  // the crossing, the hairpin and the disc
        EXPECT_GT(ink, 1000u);
    }
}

// Pixels where two RGBA8 images differ by more than `levels` in some channel (core/image.h's
// compare_images, as a count).
size_t differing_pixels(const ImageRGBA8& a, const ImageRGBA8& b, int levels) {
    return size_t(std::llround(compare_images(a, b, levels).differing_fraction * double(a.width) * double(a.height)));
}

// Pixels either image draws.
size_t drawn_pixels(const ImageRGBA8& a, const ImageRGBA8& b) {
    size_t drawn = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) drawn += a.at(x, y)[3] > 0 || b.at(x, y)[3] > 0;
    return drawn;
}

// The stitched drawing (shaders/ribbon_draw.frag) against its C++ reference
// (ribbon/draw_reference.h), on a curve that bends, crosses itself and folds over at a
// hairpin (forbidden pixels) and on a closed loop: the same pixels to within one level (float
// interpolation across a triangle against the exact affine map; a pixel centre on a shared
// edge could go to the other piece). Measured: 3 of 2,527 drawn pixels one level apart on the
// figure eight, none of 1,292 on the circle. Drawn without the deformation, the reference
// differs on 93 and 119 pixels by more than two levels, so the comparison sees it.
TEST_F(GpuTest, RibbonStitchedDrawingEqualsTheReference) {
    const Curve2D eight = eight_with_hairpin();
    const struct {
        const char* name;
        Curve2D curve;
        const char* exemplar;
    } cases[] = {{"figure eight with a hairpin", eight, "chain"}, {"circle", circle_curve({60, 50}, 30, 96), "zigzag"}};
    for (const auto& c : cases) {
        const Exemplar e = make_exemplar(generate_exemplar(c.exemplar, 64, 24, 4), c.exemplar);
        RibbonSynthesisDesc desc;
        desc.params = {.width = 20, .piece = 6, .scale = 24};
        desc.width = 160;
        desc.height = 100;
        desc.stitch = true;
        const RibbonSynthesis s = synthesize_ribbon(ctx(), e, ArclengthCurve(c.curve), desc);
        ASSERT_TRUE(s.stitch.has_value());
        const ImageRGBA8 cpu = draw_ribbon_reference(s.ribbon, e, s.solution.positions, &s.stitch->remap, &s.forbidden,
                                                     desc.width, desc.height);
        const size_t drawn = drawn_pixels(s.image, cpu), differ = differing_pixels(s.image, cpu, 1);
        const ImageRGBA8 plain =
            draw_ribbon_reference(s.ribbon, e, s.solution.positions, nullptr, &s.forbidden, desc.width, desc.height);
        const size_t unstitched = differing_pixels(s.image, plain, 2);
        std::printf("%s: %zu of %zu drawn pixels differ by more than one level, %zu by any (without the deformation: "
                    "%zu by more than two)\n",
                    c.name, differ, drawn, differing_pixels(s.image, cpu, 0), unstitched);
        EXPECT_GT(drawn, 1000u) << c.name;
        EXPECT_LE(differ, drawn / 500) << c.name;
        EXPECT_GE(unstitched, 50u) << c.name;
    }
}

TEST_F(GpuTest, RibbonDrawingCopiesTheExemplar) {
    // A straight ribbon at scale 1: each output pixel is the exemplar texel of its piece (its
    // colour is compared where it is not fully transparent).
    const Exemplar e = make_exemplar(generate_exemplar("rope", 64, 24, 1), "rope");
    const Ribbon r = build_ribbon(ArclengthCurve(Curve2D{{{4, 20}, {124, 20}}, false}), {.width = 24, .piece = 8, .scale = 24});
    const DpProblem p = build_problem(e, r);
    const RibbonSolution s = solve_ribbon(p, run_dp_reference, 1);
    const ImageRGBA8 image = RibbonRenderer(ctx()).draw(r, e, s.positions, nullptr, nullptr, 128, 40);
    ASSERT_EQ(r.pieces.size(), 15u);
    size_t checked = 0;
    for (size_t i = 0; i < r.pieces.size(); ++i)
        for (int dy = 0; dy < 24; ++dy)
            for (int dx = 0; dx < 8; ++dx) {
                const int x = 4 + 8 * int(i) + dx, y = 8 + dy;  // pixel centres inside piece i
                const uint32_t want = e.at(s.positions[i].x + 1 + dx, s.positions[i].y + dy);  // columns x+1 … x+w
                const uint8_t* got = image.at(x, y);
                // Pixel centres land on texel centres: the bilinear weights are 0 and 1, up to
                // interpolation rounding.
                for (int c = 0; c < 4; ++c)
                    ASSERT_NEAR(int(got[c]), int((want >> (8 * c)) & 0xffu), (want >> 24) ? 1 : 255)
                        << "pixel " << x << "," << y << " channel " << c;
                ++checked;
            }
    EXPECT_EQ(checked, r.pieces.size() * 24 * 8);
}

}  // namespace
}  // namespace lw
