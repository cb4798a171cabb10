// `linework render --svg`: the SVG drawn by a standard renderer (rsvg-convert, librsvg) shows
// what the PNG shows — widths, tapers, caps, fades and dashes as geometry — and hidden lines
// come in their own group. Ink is 1 − red/255 over white; the two images are compared by the
// IoU of their inked pixels (ink > ½).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/image.h"
#include "render/line_pass.h"
#include "io/image_io.h"
#include "lines/svg_export.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

struct SvgRender {
    ImageRGBA8 png, svg_drawn;
    std::string svg;
};

// Renders `input` with `flags` over white (lines only) at 320×240, and the SVG through rsvg.
SvgRender render_both(const fs::path& dir, const std::string& input, const std::string& flags) {
    SvgRender r;
    const auto run = test::run_linework("render " + input + " --lines-only --size 320x240 --device cpu -o " +
                                        test::quote(dir / "out") + " --svg " + test::quote(dir / "lines.svg") + " " + flags);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    const auto rsvg = test::run_command("rsvg-convert -w 320 -h 240 -b white " + test::quote(dir / "lines.svg") + " -o " +
                                        test::quote(dir / "svg.png") + " 2>&1");
    EXPECT_EQ(rsvg.exit_code, 0) << "rsvg-convert (librsvg2-bin, installed by tools/test.sh): " << rsvg.output;
    if (run.exit_code != 0 || rsvg.exit_code != 0) return r;  // empty images: the comparison fails too
    r.png = read_image_rgba8(dir / "out/frame_0000.png");
    r.svg_drawn = read_image_rgba8(dir / "svg.png");
    std::ifstream in(dir / "lines.svg");
    std::stringstream text;
    text << in.rdbuf();
    r.svg = text.str();
    return r;
}

struct InkComparison {
    double iou = 0.0;
    size_t png_ink = 0, svg_ink = 0;
};

InkComparison compare_ink(const ImageRGBA8& a, const ImageRGBA8& b) {
    InkComparison c;
    size_t both = 0;
    for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); i += 4) {
        const bool ia = a.pixels[i] < 128, ib = b.pixels[i] < 128;
        c.png_ink += ia;
        c.svg_ink += ib;
        both += ia && ib;
    }
    const size_t either = c.png_ink + c.svg_ink - both;
    c.iou = either ? double(both) / double(either) : 0.0;
    return c;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// The default lines (plain, fading suggestive contours), and the same with dashed and with
// faint hidden lines. Measured: IoU 0.989, 0.975 and 0.989 (the issue asks for 0.9).
TEST(SvgExport, StandardRendererDrawsThePng) {
    const fs::path dir = test::temp_dir();
    const std::string spot = test::quote(test::data_dir() / "models/spot/spot.glb");
    for (const std::string hidden : {"none", "dashed", "faint"}) {
        const SvgRender r = render_both(dir / hidden, spot, "--hidden " + hidden);
        const InkComparison c = compare_ink(r.png, r.svg_drawn);
        EXPECT_GE(c.iou, 0.95) << "hidden " << hidden << ": PNG " << c.png_ink << " inked pixels, SVG " << c.svg_ink;
        RecordProperty("iou_hidden_" + hidden, std::to_string(c.iou));
        EXPECT_GT(c.png_ink, 500u);
        // Widths are geometry: the drawing has no strokes; the centre lines are there, not drawn.
        EXPECT_EQ(count(r.svg, "stroke-width="), count(r.svg, "-centerlines\" display=\"none\""));
        EXPECT_EQ(count(r.svg, "-centerlines\""), 4u);
        EXPECT_GT(count(r.svg, "<path fill="), 4u);
        const size_t hidden_group = r.svg.find("-hidden\"");
        EXPECT_EQ(hidden_group != std::string::npos, hidden != "none") << hidden;
        // Faint hidden lines (too light for the ink threshold) at a quarter of the opacity.
        if (hidden == "faint") {
            EXPECT_NE(r.svg.find("fill-opacity=\"0.25", hidden_group), std::string::npos);
        }
    }
}

// A set that selects hidden lines has its -hidden group in every frame, empty where the frame
// has none (a pipeline reading the groups meets the same ones frame after frame); a set that
// selects only visible lines (qi [0, 0] too) has none.
TEST(SvgExport, AHiddenGroupIsWrittenWheneverTheSetSelectsHiddenLines) {
    LineSelection visible, any, behind_one, level_zero;
    any.visibility = Visibility::Any;
    behind_one.qi = LevelRange{1, 1};
    level_zero.qi = LevelRange{0, 0};
    level_zero.visibility = Visibility::Any;  // replaced by qi
    EXPECT_FALSE(visible.selects_hidden());
    EXPECT_TRUE(any.selects_hidden());
    EXPECT_TRUE(behind_one.selects_hidden());
    EXPECT_FALSE(level_zero.selects_hidden());
    const std::string svg = lines_svg(64, 48, {SvgGroup{.id = "front"}, SvgGroup{.id = "behind", .hidden = true}});
    EXPECT_EQ(svg.find("front-hidden"), std::string::npos);
    EXPECT_NE(svg.find("<g id=\"behind-hidden\">\n    </g>"), std::string::npos) << svg;
}

// The dashes cut as geometry are the shader's: every dash triangle lies where fract(s / 8) ≤ ½
// (u, the arc length, at its centroid), and the gaps hold none.
TEST(SvgExport, GeometricDashesAreTheShadersDashes) {
    ScreenPath path;
    path.visible = false;
    for (int i = 0; i <= 40; ++i) {
        const float a = 0.05f * float(i);
        const glm::vec2 p(50.0f + 30.0f * std::cos(a), 40.0f + 30.0f * std::sin(a));
        const float s = path.samples.empty() ? 3.0f : path.samples.back().s + glm::length(p - path.samples.back().pixel);
        path.samples.push_back(ScreenSample{.pixel = p, .depth = 1.0f, .s = s, .position = {}, .face = 0, .bary = {}, .alpha = 1.0f});
    }
    const std::vector<StrokeVertex> triangles =
        line_triangles({path}, LineDrawStyle{.width = 2.0f, .hidden = HiddenLines::Dashed}, 0.0f, true);
    ASSERT_GT(triangles.size(), 30u);
    std::vector<bool> period_drawn(32, false);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const float u = (triangles[t].tex.x + triangles[t + 1].tex.x + triangles[t + 2].tex.x) / 3.0f;
        EXPECT_LE(u / kDashPeriodPx - std::floor(u / kDashPeriodPx), 0.5f + 1e-4f) << "u " << u;
        period_drawn[size_t(u / kDashPeriodPx) % 32] = true;
    }
    EXPECT_GE(std::count(period_drawn.begin(), period_drawn.end(), true), 7);  // 60 px of dashes: 7–8 periods
}

// Line sets with tapers, width ramps, round caps, dashes, noise and translucent hidden lines.
TEST(SvgExport, StyledLineSetsKeepTheirShapes) {
    const fs::path dir = test::temp_dir();
    const fs::path scene = dir / "styled.json";
    std::ofstream(scene) << R"({"model": ")" << (test::data_dir() / "models/spot/spot.glb").string() << R"(",
      "camera": {"eye": [2.9, 0.7, 1.1], "target": [0.0, 0.05, 0.0], "fov": 35},
      "line_sets": [
        {"name": "hidden", "select": {"types": ["silhouette", "crease"], "visibility": "hidden"},
         "style": {"width": 1.2, "alpha": 0.35, "color": [0.2, 0.3, 0.6], "dashes": [6, 5], "cap": "round"}},
        {"name": "outline", "select": {"types": ["silhouette", "border"]},
         "style": {"width": 6, "taper": 14,
                   "width_modifiers": [{"input": "distance", "range": [2.5, 4.5], "ramp": [[0, 1.2], [1, 0.6]]}]}},
        {"name": "suggestive", "select": {"types": ["suggestive"]},
         "style": {"width": 2.5, "color": [0.15, 0.1, 0.05], "cap": "round", "taper": 6,
                   "geometry": [{"kind": "noise", "wavelength": 18, "amplitude": 0.8, "seed": 3}]}},
        {"name": "creases", "select": {"types": ["crease"]},
         "style": {"width": 1.5, "color": [0.5, 0.2, 0.1], "cap": "round",
                   "width_modifiers": [{"input": "along", "ramp": [[0, 0.4], [0.5, 1.3], [1, 0.4]]}]}}]})";
    const SvgRender r = render_both(dir, test::quote(scene), "");
    const InkComparison c = compare_ink(r.png, r.svg_drawn);
    EXPECT_GE(c.iou, 0.95) << "PNG " << c.png_ink << " inked pixels, SVG " << c.svg_ink;
    RecordProperty("iou_styled", std::to_string(c.iou));
    EXPECT_NE(r.svg.find("<g id=\"hidden-hidden\">"), std::string::npos) << "a set of hidden lines draws them apart";
    EXPECT_NE(r.svg.find("<g id=\"hidden\" fill-rule=\"nonzero\" stroke=\"none\" opacity=\"0.350\">"), std::string::npos)
        << "its alpha as the group's opacity";
    // The centre lines carry each set's ends and joins: round caps where the set asks for
    // them, the default square caps and mitres (at the stroke builder's limit) elsewhere.
    EXPECT_NE(r.svg.find("<g id=\"creases-centerlines\" display=\"none\" fill=\"none\" stroke=\"#80331a\" "
                         "stroke-width=\"1.50\" stroke-linecap=\"round\" stroke-linejoin=\"miter\" "
                         "stroke-miterlimit=\"2.00\">"),
              std::string::npos);
    EXPECT_NE(r.svg.find("<g id=\"outline-centerlines\" display=\"none\" fill=\"none\" stroke=\"#000000\" "
                         "stroke-width=\"6.00\" stroke-linecap=\"square\" stroke-linejoin=\"miter\""),
              std::string::npos);
}

// A translucent set is composited once in both: black at alpha 0.5, 6 px wide with round caps
// and joins, over white, is nowhere darker than 128 (± 2 for rounding) in the PNG or in the
// SVG as rsvg draws it, though its caps, joins and the places where a silhouette meets a
// crease overlap (drawn one over another they reached 0). With an alpha modifier that
// replaces the alpha by 0.8, both draw at 0.8 (51): the SVG group's opacity is its most
// opaque shape's, not the set's alpha. The two ink the same pixels.
TEST(SvgExport, ATranslucentSetIsDrawnOnceInBoth) {
    const fs::path dir = test::temp_dir();
    struct Case {
        const char* name;
        const char* style;
        int darkest;
    };
    for (const Case c : {Case{"half", R"("alpha": 0.5)", 128},
                         Case{"replaced", R"("alpha": 0.5, "alpha_modifiers": [{"input": "along", "blend": "replace",
                                              "ramp": [[0, 0.8], [1, 0.8]]}])", 51}}) {
        const fs::path scene = dir / (std::string(c.name) + ".json");
        std::ofstream(scene) << R"({"model": ")" << (test::data_dir() / "models/spot/spot.glb").string() << R"(",
          "camera": {"eye": [2.9, 0.7, 1.1], "target": [0.0, 0.05, 0.0], "fov": 35},
          "line_sets": [{"name": "outline", "select": {"types": ["silhouette", "crease", "border"]},
                         "style": {"width": 6, "cap": "round", "join": "round", )" << c.style << "}}]}";
        const SvgRender r = render_both(dir / c.name, test::quote(scene), "");
        auto darkest = [](const ImageRGBA8& image) {
            int lo = 255;
            size_t inked = 0;
            for (size_t i = 0; i < image.pixels.size(); i += 4) {
                lo = std::min(lo, int(image.pixels[i]));
                inked += image.pixels[i] < 192;
            }
            return std::pair{lo, inked};
        };
        const auto [png_lo, png_inked] = darkest(r.png);
        const auto [svg_lo, svg_inked] = darkest(r.svg_drawn);
        EXPECT_GT(png_inked, 1000u) << c.name;
        EXPECT_NEAR(png_lo, c.darkest, 2) << c.name;
        EXPECT_NEAR(svg_lo, c.darkest, 2) << c.name;
        EXPECT_NEAR(double(svg_inked), double(png_inked), 0.05 * double(png_inked)) << c.name;
    }
}

// Under --frames, one SVG per frame beside the given name: lines_0003.svg for frame 3.
TEST(SvgExport, OneFilePerFrame) {
    const fs::path dir = test::temp_dir();
    const auto run = test::run_linework("render " + test::quote(test::data_dir() / "models/spot/spot.glb") +
                                        " --size 160x120 --device cpu --frames 2:3 --orbit 10 -o " +
                                        test::quote(dir / "out") + " --svg " + test::quote(dir / "lines.svg"));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir / "lines_0002.svg"));
    EXPECT_TRUE(fs::exists(dir / "lines_0003.svg"));
    EXPECT_FALSE(fs::exists(dir / "lines.svg"));
}

}  // namespace
}  // namespace lw
