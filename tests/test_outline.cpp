// The outline chaining option (stroke/outline.h) on drawings made by hand: a square of four
// runs whose ends stop short of each other and overshoot, a loose line, two drawings, and
// visible and hidden runs together.
#include <cmath>

#include "stroke/outline.h"
#include "test_support.h"

namespace lw {
namespace {

// A run from a to b, a sample every 2 px.
ScreenPath run(glm::vec2 a, glm::vec2 b, uint32_t qi = 0) {
    ScreenPath p{.type = LineType::Silhouette, .visible = qi == 0, .qi = qi};
    const int n = std::max(1, int(std::ceil(glm::distance(a, b) / 2.0f)));
    for (int i = 0; i <= n; ++i) {
        const float t = float(i) / float(n);
        p.samples.push_back(ScreenSample{.pixel = glm::mix(a, b, t), .s = t * glm::distance(a, b), .face = uint32_t(i)});
    }
    return p;
}

// The square [x0, x0 + 100]²: its sides as runs, the top and right ending 2 px short of the
// corner they meet (a run that stops a sample before the contour hiding it), the left one
// overshooting by 10 px (a contour that goes on past the junction).
std::vector<ScreenPath> square(float x0, uint32_t qi = 0) {
    return {run({x0, 0}, {x0 + 98, 0}, qi), run({x0 + 100, 2}, {x0 + 100, 100}, qi), run({x0 + 100, 100}, {x0, 100}, qi),
            run({x0, 110}, {x0, 0}, qi)};
}

void expect_square_outline(const ScreenPath& p, float x0) {
    EXPECT_TRUE(p.closed);
    ASSERT_GT(p.samples.size(), 100u);
    float widest = 0.0f, off = 0.0f;
    double area = 0.0;
    const size_t n = p.samples.size();
    for (size_t i = 0; i < n; ++i) {
        const glm::vec2 a = p.samples[i].pixel, b = p.samples[(i + 1) % n].pixel;
        widest = std::max(widest, glm::distance(a, b));
        area += double(a.x) * b.y - double(b.x) * a.y;
        // On one of the four sides (or the overshoot's end, which the boundary goes round).
        const float to_side = std::min({std::abs(a.x - x0), std::abs(a.x - x0 - 100), std::abs(a.y), std::abs(a.y - 100)});
        off = std::max(off, to_side);
    }
    EXPECT_LE(widest, 4.0f);
    EXPECT_LE(off, 1e-3f) << "every sample is snapped onto a run";
    EXPECT_NEAR(std::abs(area) / 2.0, 100.0 * 100.0, 300.0) << "it goes once round the square";
}

TEST(Outline, SquareOfRunsWithGapsAndOvershootIsOneClosedPath) {
    const std::vector<ScreenPath> out = trace_outlines(square(10));
    ASSERT_EQ(out.size(), 1u);
    expect_square_outline(out[0], 10);
}

TEST(Outline, LooseRunsStayAsTheyAre) {
    std::vector<ScreenPath> runs = square(10);
    runs.push_back(run({300, 50}, {400, 60}));  // bounds nothing
    const std::vector<ScreenPath> out = trace_outlines(runs);
    ASSERT_EQ(out.size(), 2u);
    size_t loose = 0, outlines = 0;
    for (const ScreenPath& p : out) {
        if (p.closed) {
            ++outlines;
            expect_square_outline(p, 10);
        } else {
            ++loose;
            EXPECT_EQ(p.samples.size(), runs.back().samples.size());
            EXPECT_EQ(p.samples.front().pixel, glm::vec2(300, 50));
        }
    }
    EXPECT_EQ(outlines, 1u);
    EXPECT_EQ(loose, 1u);
    EXPECT_TRUE(trace_outlines({}).empty());
}

TEST(Outline, EachDrawingAndEachLevelHasItsOwn) {
    std::vector<ScreenPath> runs = square(10);
    for (const ScreenPath& r : square(200)) runs.push_back(r);
    for (const ScreenPath& r : square(400, 1)) runs.push_back(r);  // hidden, behind one surface
    const std::vector<ScreenPath> out = trace_outlines(runs);
    ASSERT_EQ(out.size(), 3u);
    size_t hidden = 0;
    for (const ScreenPath& p : out) {
        const float x0 = p.samples.front().pixel.x < 150 ? 10.0f : p.samples.front().pixel.x < 350 ? 200.0f : 400.0f;
        expect_square_outline(p, x0);
        EXPECT_EQ(p.visible, p.qi == 0);
        hidden += p.qi == 1;
        if (p.qi == 1) {
            EXPECT_EQ(x0, 400.0f);
        }
    }
    EXPECT_EQ(hidden, 1u);
}

}  // namespace
}  // namespace lw
