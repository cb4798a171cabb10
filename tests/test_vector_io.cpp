// Stroke files: JSON and the SVG subset, in and out, and their one-line errors.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "test_support.h"
#include "vector/stroke_io.h"

namespace lw {
namespace {

TEST(VectorIo, ReadsTheSvgSubsetWithInheritedPaint) {
    const StrokeSet s = parse_strokes_svg(R"svg(<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="10 20 300 200">
  <title>t</title><!-- a comment with <path d="M 0 0"/> inside -->
  <defs><path d="M 0 0 L 1 1"/></defs>
  <g stroke="#ff0000" stroke-width="3">
    <polyline points="0,0 10,0 10,10"/>
    <path d="M 0 0 C 0 10 10 10 10 0 M 20 20 l 5 0 0 5 z" stroke="rgb(0, 0, 255)"/>
    <g style="stroke: #0f0; stroke-width: 0.5px"><line x1="1" y1="2" x2="3" y2="4"/></g>
  </g>
  <polygon points="0 0 5 0 5 5" stroke="black" data-widths="1 2 3"/>
</svg>)svg",
                                          "a.svg");
    EXPECT_EQ(s.origin, glm::vec2(10, 20));
    EXPECT_EQ(s.size, glm::vec2(300, 200));
    ASSERT_EQ(s.strokes.size(), 5u);  // polyline, two subpaths, line, polygon
    EXPECT_EQ(s.strokes[0].color, glm::vec3(1, 0, 0));
    EXPECT_FLOAT_EQ(s.strokes[0].widths[2], 3.0f);
    EXPECT_EQ(s.strokes[1].color, glm::vec3(0, 0, 1));
    EXPECT_GT(s.strokes[1].points.size(), 4u);  // the Bézier, flattened
    EXPECT_TRUE(s.strokes[2].closed);
    EXPECT_EQ(s.strokes[2].points.back(), glm::vec2(25, 25));
    EXPECT_EQ(s.strokes[3].color, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(s.strokes[3].widths[0], 0.5f);
    EXPECT_TRUE(s.strokes[4].closed);
    EXPECT_EQ(s.strokes[4].widths, std::vector<float>({1, 2, 3}));
}

TEST(VectorIo, SvgAndJsonRoundTripsKeepPointsWidthsAndColours) {
    StrokeSet set;
    set.strokes.push_back(make_stroke({{1.5f, 2.25f}, {30, 40}, {50, 10}}, 2.0f, {0.8f, 0.2f, 0.4f}));
    set.strokes.back().widths = {1.0f, 4.0f, 0.5f};
    set.strokes.push_back(make_stroke({{0, 0}, {10, 0}, {10, 10}}, 1.25f, {0, 0, 0}, true));
    set.strokes.push_back(make_stroke({{7, 7}}, 3.0f, {0, 0.5f, 0}));  // a dot
    const std::string svg = strokes_to_svg(set);
    EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n'), 7);  // svg, g, 3 strokes, /g, /svg
    EXPECT_NE(svg.find("<polyline"), std::string::npos);
    EXPECT_NE(svg.find("<path d=\"M0 0 L10 0 L10 10 Z\""), std::string::npos);
    for (const StrokeSet& back : {parse_strokes_svg(svg, "x.svg"), parse_strokes_json(strokes_to_json(set), "x.json")}) {
        ASSERT_EQ(back.strokes.size(), 3u);
        for (size_t i = 0; i < 2; ++i) {
            EXPECT_EQ(back.strokes[i].points, set.strokes[i].points);
            EXPECT_EQ(back.strokes[i].widths, set.strokes[i].widths);
            EXPECT_EQ(back.strokes[i].closed, set.strokes[i].closed);
            EXPECT_NEAR(glm::length(back.strokes[i].color - set.strokes[i].color), 0.0f, 1.0f / 255.0f);
        }
        EXPECT_EQ(back.strokes[2].points.front(), glm::vec2(7, 7));
        EXPECT_FLOAT_EQ(back.strokes[2].widths.front(), 3.0f);
    }
    const auto dir = test::temp_dir();
    save_strokes(dir / "s.json", set);
    save_strokes(dir / "s.svg", set);
    EXPECT_EQ(load_strokes(dir / "s.json").strokes.size(), 3u);
    EXPECT_EQ(load_strokes(dir / "s.svg").strokes[0].widths, set.strokes[0].widths);
}

TEST(VectorIo, BadFilesGiveOneMessageNamingTheFile) {
    const std::pair<const char*, const char*> svg_cases[] = {
        {R"(<svg><rect x="0" y="0" width="5" height="5"/></svg>)", "<rect>: unsupported element"},
        {R"svg(<svg><path d="M 0 0 L 1 1" transform="rotate(3)"/></svg>)svg", "transform"},
        {R"(<svg><path d="M 0 0 Q 1 1 2 2"/></svg>)", "unsupported command 'Q'"},
        {R"(<svg><polyline points="0 0 1"/></svg>)", "odd number"},
        {R"(<svg><polyline points="0 0 1 1" stroke="chartreuse"/></svg>)", "colour \"chartreuse\""},
        {R"(<svg><polyline points="0 0 1 1" stroke-width="-2"/></svg>)", "widths must be positive"},
        {R"(<svg><polyline points="0 0 1 1" data-widths="1 2 3"/></svg>)", "data-widths"},
        {R"(<svg><path/></svg>)", "missing the d attribute"},
        {R"(<g></g>)", "no <svg> element"},
    };
    for (const auto& [text, expected] : svg_cases) {
        try {
            (void)parse_strokes_svg(text, "dir/p.svg");
            ADD_FAILURE() << "accepted " << text;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.rfind("dir/p.svg: ", 0), 0u) << m;
            EXPECT_NE(m.find(expected), std::string::npos) << m;
            EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        }
    }
    const std::pair<const char*, const char*> json_cases[] = {
        {R"({"strokes": [{"points": [[0, 0]], "colour": [0, 0, 0]}]})", "strokes[0].colour: unknown key"},
        {R"({"strokes": [{"points": [[0, 0], [1]]}]})", "strokes[0].points[1]"},
        {R"({"strokes": [{"points": [[0, 0], [1, 1]], "widths": [1]}]})", "widths: expected one number per point"},
        {R"({"strokes": [{"points": [[0, 0]], "color": [2, 0, 0]}]})", "colour components"},
        {R"({"strokes": [{"points": []}]})", "at least one point"},
        {R"({"strokes": 3})", "strokes: missing or not an array"},
        {R"({"strokes": [], "sise": [1, 1]})", "sise: unknown key"},
        {R"({"strokes": )", "not valid JSON"},
    };
    for (const auto& [text, expected] : json_cases) {
        try {
            (void)parse_strokes_json(text, "dir/p.json");
            ADD_FAILURE() << "accepted " << text;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.rfind("dir/p.json: ", 0), 0u) << m;
            EXPECT_NE(m.find(expected), std::string::npos) << m;
        }
    }
    EXPECT_THROW((void)load_strokes("/nonexistent/strokes.svg"), Error);
    const auto dir = test::temp_dir();
    std::ofstream(dir / "empty.svg") << "<svg></svg>";
    try {
        (void)load_strokes(dir / "empty.svg");
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("empty.svg: no strokes"), std::string::npos) << e.what();
    }
}

TEST(VectorIo, EveryShippedReferencePatternReads) {
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "scenes" / "patterns")) {
        if (entry.path().extension() != ".svg") continue;
        const StrokeSet s = load_strokes(entry.path());
        EXPECT_GE(s.strokes.size(), 3u) << entry.path();
        EXPECT_GT(s.size.x, 0.0f) << entry.path();
        ++files;
    }
    EXPECT_GE(files, 9u);  // eight reference patterns at least, plus the hatching files
}

}  // namespace
}  // namespace lw
