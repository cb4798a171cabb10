// Stroke files: JSON and the SVG subset, in and out, and their one-line errors.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

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
        {R"(<svg><text x="0" y="0">words</text></svg>)", "<text>: unsupported element"},
        {R"svg(<svg><path d="M 0 0 L 1 1" transform="spin(3)"/></svg>)svg", "transform: unknown \"spin\""},
        {R"svg(<svg><path d="M 0 0 L 1 1" transform="rotate(3, 4)"/></svg>)svg", "rotate takes 1 or 3 numbers"},
        {R"(<svg><path d="M 0 0 L 1 1"></svg>)", "XML: "},
        {R"(<svg><polyline points="0 0 1 1" stroke-width="2em"/></svg>)", "unit \"em\""},
        {R"(<svg><use href="#nowhere"/></svg>)", "no element with id \"nowhere\""},
        {R"(<svg><g id="a"><use href="#a"/></g></svg>)", "nest deeper than 32"},
        {R"(<svg><circle cx="1" cy="1"/></svg>)", "missing the r attribute"},
        {R"(<svg><style>.st0{stroke:#f00}</style><line x2="1" class="st0"/></svg>)", "<style> sheets are not read"},
        {R"(<svg><svg viewBox="0 0 1 1"><line x2="1"/></svg></svg>)", "nested viewports"},
        {R"(<svg><path d="M 0 0 A 1 1 0 0 1 2 2"/></svg>)", "unsupported command 'A'"},
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
    std::string deep = "<svg>";
    for (int i = 0; i < 300; ++i) deep += "<g>";
    deep += "<line x2=\"1\"/>";
    for (int i = 0; i < 300; ++i) deep += "</g>";
    EXPECT_THROW((void)parse_strokes_svg(deep + "</svg>", "deep.svg"), Error);  // nesting past 256 levels
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

// ---- SVG as Inkscape writes it: the nested, transformed file and its flattened twin ----

// An affine map as the 2×3 numbers of SVG's matrix(a b c d e f): x' = a x + c y + e, y' = b x + d y + f.
struct Affine {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    Affine operator*(const Affine& o) const {  // this after o
        return {a * o.a + c * o.b, b * o.a + d * o.b, a * o.c + c * o.d, b * o.c + d * o.d, a * o.e + c * o.f + e,
                b * o.e + d * o.f + f};
    }
    glm::vec2 operator()(glm::vec2 p) const { return {float(a * p.x + c * p.y + e), float(b * p.x + d * p.y + f)}; }
    double mean_scale() const { return std::sqrt(std::abs(a * d - b * c)); }
};
Affine translate(double x, double y) { return {1, 0, 0, 1, x, y}; }
Affine rotate(double degrees) {
    const double r = degrees * 3.14159265358979 / 180.0;
    return {std::cos(r), std::sin(r), -std::sin(r), std::cos(r), 0, 0};
}
Affine scale(double s) { return {s, 0, 0, s, 0, 0}; }
Affine skew_y(double degrees) { return {1, std::tan(degrees * 3.14159265358979 / 180.0), 0, 1, 0, 0}; }

// What Inkscape saves: an XML declaration, a comment, namespaces and editor elements, a
// layer group with a transform and a style, a nested group, <use> of a <defs> path, a rect, a
// skewed circle, a hidden layer and a line with a width in millimetres.
constexpr const char* kInkscapeFile = R"svg(<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<!-- Created with Inkscape (http://www.inkscape.org/) -->
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
     width="100mm" height="50mm" viewBox="0 0 200 100" version="1.1">
  <sodipodi:namedview id="namedview1" pagecolor="#ffffff" inkscape:zoom="1.2"/>
  <defs id="defs1"><path id="tick" d="m 0,0 h 4" style="stroke:#ff0000"/></defs>
  <g inkscape:label="Layer 1" inkscape:groupmode="layer" id="layer1"
     transform="translate(10,20)" style="fill:none;stroke:#000000;stroke-width:2">
    <g transform="rotate(30) scale(2)">
      <path d="M 0,0 L 10,0 L 10,5" id="path1"/>
      <use xlink:href="#tick" x="3" y="1"/>
      <rect x="1" y="1" width="4" height="3" style="stroke-width:0.5"/>
    </g>
    <g transform="matrix(1,0,0.5,1,5,5) skewY(10)"><circle cx="0" cy="0" r="3"/></g>
  </g>
  <g inkscape:label="Hidden" inkscape:groupmode="layer" style="display:none"><path d="M 0 0 L 50 50"/></g>
  <line x1="0" y1="90" x2="20" y2="90" stroke="blue" stroke-width="1mm"/>
</svg>
)svg";

std::string points_of(const std::vector<glm::vec2>& points) {
    std::ostringstream out;
    out.precision(9);
    for (const glm::vec2& p : points) out << p.x << ',' << p.y << ' ';
    return out.str();
}

TEST(VectorIo, NestedTransformedGroupsGiveTheStrokesOfTheirFlattenedTwin) {
    const Affine layer = translate(10, 20), inner = layer * rotate(30) * scale(2);
    const Affine skewed = layer * Affine{1, 0, 0.5, 1, 5, 5} * skew_y(10);
    const StrokeSet circle = parse_strokes_svg(R"(<svg><circle cx="0" cy="0" r="3"/></svg>)", "circle.svg");
    ASSERT_EQ(circle.strokes.size(), 1u);
    std::vector<glm::vec2> ring;
    for (const glm::vec2& p : circle.strokes[0].points) {
        EXPECT_NEAR(glm::length(p), 3.0f, 1e-5f);  // the circle itself lies on its radius
        ring.push_back(skewed(p));
    }
    const auto map = [](const Affine& t, std::vector<glm::vec2> points) {
        for (glm::vec2& p : points) p = t(p);
        return points;
    };
    // The twin: absolute coordinates and widths, no groups, no transforms.
    std::ostringstream twin;
    twin.precision(9);
    twin << "<svg viewBox=\"0 0 200 100\">\n"
         << "<polyline points=\"" << points_of(map(inner, {{0, 0}, {10, 0}, {10, 5}})) << "\" stroke=\"#000000\" stroke-width=\""
         << 2 * inner.mean_scale() << "\"/>\n"
         << "<polyline points=\"" << points_of(map(inner * translate(3, 1), {{0, 0}, {4, 0}}))
         << "\" stroke=\"#ff0000\" stroke-width=\"" << 2 * inner.mean_scale() << "\"/>\n"
         << "<polygon points=\"" << points_of(map(inner, {{1, 1}, {5, 1}, {5, 4}, {1, 4}})) << "\" stroke=\"#000000\" stroke-width=\""
         << 0.5 * inner.mean_scale() << "\"/>\n"
         << "<polygon points=\"" << points_of(ring) << "\" stroke=\"#000000\" stroke-width=\"" << 2 * skewed.mean_scale()
         << "\"/>\n"
         << "<line x1=\"0\" y1=\"90\" x2=\"20\" y2=\"90\" stroke=\"blue\" stroke-width=\"" << 96.0 / 25.4 << "\"/>\n"
         << "</svg>\n";
    const StrokeSet drawn = parse_strokes_svg(kInkscapeFile, "inkscape.svg");
    const StrokeSet flat = parse_strokes_svg(twin.str(), "twin.svg");
    EXPECT_EQ(drawn.size, glm::vec2(200, 100)) << "the viewBox, not the page size in mm";
    ASSERT_EQ(drawn.strokes.size(), flat.strokes.size()) << "the hidden layer draws nothing";
    // The skewed circle (stroke 3) is flattened after the skew's stretch, to finer chords than
    // the plain circle of the twin: its points, mapped back, lie on r = 3.
    const double det = skewed.a * skewed.d - skewed.b * skewed.c;
    const Affine back{skewed.d / det, -skewed.b / det, -skewed.c / det, skewed.a / det,
                      (skewed.c * skewed.f - skewed.d * skewed.e) / det, (skewed.b * skewed.e - skewed.a * skewed.f) / det};
    ASSERT_GE(drawn.strokes.size(), 4u);
    EXPECT_GT(drawn.strokes[3].points.size(), circle.strokes[0].points.size());
    for (const glm::vec2& p : drawn.strokes[3].points) EXPECT_NEAR(glm::length(back(p)), 3.0f, 1e-4f);
    for (size_t i = 0; i < flat.strokes.size(); ++i) {
        const Stroke &a = drawn.strokes[i], &b = flat.strokes[i];
        if (i == 3) {
            EXPECT_TRUE(a.closed);
            EXPECT_NEAR(a.widths[0], b.widths[0], 1e-5f);
            continue;
        }
        ASSERT_EQ(a.points.size(), b.points.size()) << i;
        for (size_t k = 0; k < a.points.size(); ++k) EXPECT_LT(glm::length(a.points[k] - b.points[k]), 1e-4f) << i << " " << k;
        for (size_t k = 0; k < a.widths.size(); ++k) EXPECT_NEAR(a.widths[k], b.widths[k], 1e-5f) << i;
        EXPECT_EQ(a.color, b.color) << i;
        EXPECT_EQ(a.closed, b.closed) << i;
    }
}

// XML tools write SVG under a prefix bound to its namespace (xmlns:svg): the same drawing as
// without it. An element under a prefix of another namespace is still left out, and a prefix
// called svg bound elsewhere is not SVG.
TEST(VectorIo, PrefixedSvgElementsAreRead) {
    const StrokeSet plain = parse_strokes_svg(
        R"s(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 50 40"><g transform="translate(5,5)" stroke="red">
            <path d="M0 0 L10 0"/><circle cx="20" cy="20" r="4"/></g></svg>)s",
        "plain.svg");
    const StrokeSet prefixed = parse_strokes_svg(
        R"s(<svg:svg xmlns:svg="http://www.w3.org/2000/svg" xmlns:x="urn:other" viewBox="0 0 50 40">
            <svg:g transform="translate(5,5)" stroke="red"><svg:path d="M0 0 L10 0"/><x:path d="M0 0 L1 1"/>
            <svg:circle cx="20" cy="20" r="4"/></svg:g></svg:svg>)s",
        "prefixed.svg");
    EXPECT_EQ(prefixed.size, plain.size);
    ASSERT_EQ(prefixed.strokes.size(), 2u);
    ASSERT_EQ(plain.strokes.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(prefixed.strokes[i].points, plain.strokes[i].points) << i;
        EXPECT_EQ(prefixed.strokes[i].color, plain.strokes[i].color) << i;
    }
    try {
        (void)parse_strokes_svg(R"s(<svg:svg xmlns:svg="urn:not-svg"><svg:path d="M0 0 L1 1"/></svg:svg>)s", "other.svg");
        ADD_FAILURE() << "a root outside SVG's namespace was read";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "other.svg: no <svg> element");
    }
}

TEST(VectorIo, RectCornersEllipsesAndUnits) {
    const StrokeSet s = parse_strokes_svg(
        R"(<svg width="2in" height="1in"><rect x="0" y="0" width="10" height="6" rx="2"/>
           <ellipse cx="5" cy="5" rx="4" ry="2" stroke-width="3pt"/></svg>)",
        "shapes.svg");
    EXPECT_EQ(s.size, glm::vec2(192, 96));
    ASSERT_EQ(s.strokes.size(), 2u);
    // Rounded corners (ry takes rx): every point within the rect, the corners cut.
    for (const glm::vec2& p : s.strokes[0].points) {
        EXPECT_GE(p.x, -1e-5f);
        EXPECT_LE(p.x, 10.0f + 1e-5f);
        EXPECT_GE(p.y, -1e-5f);
        EXPECT_LE(p.y, 6.0f + 1e-5f);
        EXPECT_GT(glm::length(p - glm::vec2(0, 0)), 0.5f);
    }
    EXPECT_TRUE(s.strokes[0].closed);
    for (const glm::vec2& p : s.strokes[1].points) {
        const glm::vec2 q = (p - glm::vec2(5, 5)) / glm::vec2(4, 2);
        EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    }
    EXPECT_FLOAT_EQ(s.strokes[1].widths[0], 4.0f);  // 3 pt = 4 px
    // A <switch> draws its first child that asks for no extension (Illustrator's fallback).
    const StrokeSet sw = parse_strokes_svg(R"(<svg><switch><foreignObject requiredExtensions="x"/>
        <g><line x2="5"/></g><g><line x2="9"/></g></switch></svg>)", "switch.svg");
    ASSERT_EQ(sw.strokes.size(), 1u);
    EXPECT_EQ(sw.strokes[0].points.back(), glm::vec2(5, 0));
    // Curves are flattened to ~1 px chords after the transform, not before it.
    const StrokeSet big = parse_strokes_svg(R"svg(<svg><g transform="scale(20)"><circle r="1"/></g></svg>)svg", "big.svg");
    const auto& ring = big.strokes.at(0).points;
    float longest = 0.0f;
    for (size_t i = 0; i < ring.size(); ++i) longest = std::max(longest, glm::length(ring[(i + 1) % ring.size()] - ring[i]));
    EXPECT_LE(longest, 1.01f);
}

}  // namespace
}  // namespace lw
