// Vector-art layers: fills, 2D transforms and their keyframes, clipping, scene keys, and the
// SLAM paper's zoom (Fig. 5) measured from dumps.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "coherence/path_dump.h"
#include "core/image.h"
#include "core/log.h"
#include "io/image_io.h"
#include "scene/scene_file.h"
#include "session/scene_layers.h"
#include "test_support.h"
#include "vector/fill.h"
#include "vector/layer.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

float triangles_area(const std::vector<glm::vec2>& t) {
    float area = 0.0f;
    for (size_t i = 0; i + 2 < t.size(); i += 3) {
        const glm::vec2 a = t[i + 1] - t[i], b = t[i + 2] - t[i];
        area += 0.5f * std::abs(a.x * b.y - a.y * b.x);
    }
    return area;
}

std::vector<glm::vec2> square(glm::vec2 lo, float side) {
    return {lo, lo + glm::vec2(side, 0), lo + glm::vec2(side), lo + glm::vec2(0, side)};
}

TEST(VectorFill, EvenOddCutsHolesAndOverlaps) {
    // A 10×10 square with a 4×4 hole: 84.
    EXPECT_NEAR(triangles_area(triangulate_even_odd({square({0, 0}, 10), square({3, 3}, 4)})), 84.0f, 1e-3f);
    // Two 10×10 squares overlapping in 5×5: even-odd leaves 100 + 100 − 2·25.
    EXPECT_NEAR(triangles_area(triangulate_even_odd({square({0, 0}, 10), square({5, 5}, 10)})), 150.0f, 1e-3f);
    // A bow tie (its edges cross at (5, 5)): two triangles of 25.
    EXPECT_NEAR(triangles_area(triangulate_even_odd({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}})), 50.0f, 1e-3f);
    EXPECT_TRUE(triangulate_even_odd({{{0, 0}, {1, 1}}}).empty());
}

TEST(VectorLayer, CameraMatchesThePixelMapAndKeysZoomGeometrically) {
    const glm::vec2 size(320, 200);
    const LayerTransform t{.center = glm::vec2(40, -12), .scale = 3.5f, .rotate_deg = 30.0f};
    const CameraMatrices camera = layer_camera(t, size);
    for (const glm::vec2 p : {glm::vec2(0, 0), glm::vec2(40, -12), glm::vec2(-100, 73), glm::vec2(12.5f, 300)}) {
        const glm::vec2 a = layer_to_pixel(t, p, size);
        const glm::vec3 b = project_to_pixel(camera, glm::vec3(p, 0.0f), size.x, size.y);
        EXPECT_NEAR(a.x, b.x, 1e-3f);
        EXPECT_NEAR(a.y, b.y, 1e-3f);
        EXPECT_GT(b.z, 0.0f);
    }
    EXPECT_EQ(layer_to_pixel(t, glm::vec2(40, -12), size), 0.5f * size);  // the centre goes to the middle
    const std::vector<LayerKey> keys{{0.0f, {.center = glm::vec2(0, 0), .scale = 1.0f}},
                                     {2.0f, {.center = glm::vec2(10, 20), .scale = 16.0f, .rotate_deg = 90.0f}}};
    const LayerTransform mid = layer_transform_at(keys, 1.0f);
    EXPECT_NEAR(mid.scale, 4.0f, 1e-4f);  // √(1 · 16): a constant zoom rate
    EXPECT_NEAR(mid.rotate_deg, 45.0f, 1e-4f);
    EXPECT_NEAR(mid.center->x, 5.0f, 1e-4f);
    EXPECT_EQ(layer_transform_at(keys, -1.0f).scale, 1.0f);
    EXPECT_EQ(layer_transform_at(keys, 5.0f).scale, 16.0f);
}

TEST(VectorLayer, FramesSampleStrokesAndCutThemToTheImage) {
    StrokeSet drawing;
    drawing.strokes.push_back(make_stroke({{10, 50}, {150, 50}, {400, 50}}, 3.0f, glm::vec3(1, 0, 0)));
    drawing.strokes.push_back(make_stroke(square({20, 20}, 20), 2.0f, glm::vec3(0, 0, 1), true));
    VectorLayerDesc desc;
    const LayerFrame frame = layer_frame(drawing, {}, desc, LayerTransform{}, glm::vec2(200, 100), 2.0f);
    ASSERT_EQ(frame.paths.size(), 2u);
    // The line leaves the image at x = 200: kept up to the 16 px margin, sampled every 2 px.
    const ScreenPath& line = frame.paths[0];
    EXPECT_FALSE(line.closed);
    EXPECT_LE(line.samples.back().pixel.x, 216.0f);
    EXPECT_GE(line.samples.back().pixel.x, 214.0f);
    for (size_t k = 1; k < line.samples.size(); ++k)
        EXPECT_LE(glm::length(line.samples[k].pixel - line.samples[k - 1].pixel), 2.0f + 1e-4f);
    EXPECT_EQ(line.samples.front().width, 3.0f);
    EXPECT_EQ(frame.colors[line.source], glm::vec3(1, 0, 0));
    // The square stays a loop, with its corners among the samples.
    const ScreenPath& loop = frame.paths[1];
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(loop.samples.size(), 40u);
    EXPECT_EQ(frame.colors[loop.source], glm::vec3(0, 0, 1));
}

TEST(VectorLayer, SceneKeysAreCheckedByName) {
    const fs::path file = "/tmp/layers.json";
    const SceneDesc ok = parse_scene_json(
        R"({"layers": [{"strokes": "a.svg", "fill": [1, 0, 0], "slam": "s.exr",
                        "keyframes": [{"time": 0, "scale": 1}, {"time": 2, "center": [5, 6], "scale": 16}]}]})",
        file);
    EXPECT_TRUE(ok.models.empty());
    ASSERT_EQ(ok.layers.size(), 1u);
    EXPECT_EQ(ok.layers[0].strokes, "/tmp/a.svg");
    EXPECT_EQ(ok.layers[0].keys.size(), 2u);
    auto error_of = [&](const std::string& text) {
        try {
            (void)parse_scene_json(text, file);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error_of(R"({"layers": [{"fill": [1, 0, 0]}]})"),
              "/tmp/layers.json: layers[0].strokes: required (a stroke file, .json or .svg)");
    EXPECT_NE(error_of(R"({"layers": [{"strokes": "a.svg", "keyframes": [{"time": 1}, {"time": 0}]}]})")
                  .find("layers[0].keyframes[1].time: keyframes must be in increasing time"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"layers": [{"strokes": "a.svg", "wobble": 1}]})").find("layers[0]"), std::string::npos);
    EXPECT_NE(error_of(R"({"size": [10, 10]})").find("model: required"), std::string::npos);
    // A ribbon's size without a ribbon changed nothing, in silence; now refused, by key.
    EXPECT_EQ(error_of(R"({"layers": [{"strokes": "a.svg", "ribbon_scale": 24}]})"),
              "/tmp/layers.json: layers[0].ribbon_scale: sizes a ribbon's exemplar, and this layer has no \"ribbon\"");
    EXPECT_EQ(error_of(R"({"model": "m.glb", "line_sets": [{"name": "a", "style": {"ribbon_scale": 24}}]})"),
              "/tmp/layers.json: line_sets[0].style.ribbon_scale: sizes a ribbon's exemplar, and this set has no "
              "\"ribbon\"");
    EXPECT_EQ(error_of(R"({"model": "m.glb", "lines": {"crease": {"ribbon_scale": 24}}})"),
              "/tmp/layers.json: lines.crease.ribbon_scale: sizes a ribbon's exemplar, and this type has no \"ribbon\"");
    EXPECT_EQ(error_of(R"({"layers": [{"strokes": "a.svg", "ribbon": "r.png", "ribbon_scale": 24}]})"), "no error");
}

// "fill" on a drawing without a closed stroke fills nothing: said, naming the scene key and
// the file; a drawing with closed strokes is filled without a word.
TEST(VectorLayer, AFillWithNothingClosedIsSaid) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "open.json") << R"({"strokes": [{"points": [[0, 0], [10, 0], [10, 10]], "width": 2}]})";
    std::ofstream(dir / "loop.json")
        << R"({"strokes": [{"points": [[0, 0], [10, 0], [10, 10]], "width": 2, "closed": true}]})";
    for (const char* name : {"open.json", "loop.json"}) {
        const SceneDesc desc = parse_scene_json(
            R"({"layers": [{"strokes": ")" + (dir / name).string() + R"(", "fill": "red"}]})", dir / "scene.json");
        WarningCapture warnings;
        const SceneLayers layers = load_scene_layers(desc);
        if (std::string(name) == "loop.json") {
            EXPECT_TRUE(warnings.messages().empty());
            EXPECT_FALSE(layers.fills[0].empty());
        } else {
            ASSERT_EQ(warnings.messages().size(), 1u);
            EXPECT_EQ(warnings.messages()[0], (dir / "scene.json").string() + ": layers[0].fill: " +
                                                  (dir / "open.json").string() +
                                                  " has no closed stroke (an SVG path ending in Z, a polygon, a "
                                                  "closed JSON stroke): nothing is filled");
        }
    }
}

// Fig. 5 of the SLAM paper: a drawing zoomed 16× keeps its texture period on screen within
// one factor of 2 of the target Lmax/κ, because the level follows ρ and folds.
TEST(VectorLayerCli, ZoomKeepsTheTexturePeriod) {
    const fs::path dir = test::temp_dir();
    const fs::path scene = dir / "zoom.json";
    std::ofstream(scene) << R"({"size": [160, 120], "animation": {"fps": 24, "frames": [0, 23]},
        "layers": [{"strokes": ")" << (test::source_dir() / "scenes/drawings/spiral.svg").string()
                         << R"(", "slam": ")" << (test::source_dir() / "scenes/slams/dots.exr").string() << R"(",
        "fill": [0.9, 0.8, 0.2],
        "keyframes": [{"time": 0, "center": [320, 240], "scale": 0.25},
                      {"time": 0.9583, "center": [320, 240], "scale": 4}]}]})";
    const auto r = test::run_linework("render " + test::quote(scene) + " -o " + test::quote(dir / "out") +
                                      " --device cpu --dump-paths " + test::quote(dir / "dump"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::vector<PathDump> dumps;
    for (int f = 0; f < 24; ++f) {
        char name[32];
        std::snprintf(name, sizeof(name), "frame_%04d.json", f);
        dumps.push_back(read_path_dump(dir / "dump" / name));
        for (const auto& path : dumps.back().paths) EXPECT_EQ(path.type, "layer");
    }
    const StretchMeasure stretch = measure_stretch(dumps);
    // κ = SLAM height / median stroke width = 32 / 2: the period's target is 1024 / 16 = 64 px.
    EXPECT_GE(stretch.share_in_band, 0.99);
    EXPECT_GE(stretch.median_ds_du, 32.0);
    EXPECT_LE(stretch.median_ds_du, 64.0 * 1.01);
    RecordProperty("zoom_share_in_band", std::to_string(stretch.share_in_band));
    // The last frame: the fill (yellow) shows between strokes at the spiral's centre.
    const ImageRGBA8 last = read_image_rgba8(dir / "out/frame_0023.png");
    size_t yellow = 0;
    for (size_t i = 0; i < last.pixels.size(); i += 4)
        yellow += last.pixels[i] > 200 && last.pixels[i + 1] > 180 && last.pixels[i + 2] < 90;
    EXPECT_GT(yellow, 100u);
    // Lines off, the dumps still hold the layers' paths (nothing else is refused for them).
    const auto off = test::run_linework("render " + test::quote(scene) + " -o " + test::quote(dir / "off") +
                                        " --device cpu --frames 0:0 --no-lines --dump-paths " + test::quote(dir / "off_dump"));
    ASSERT_EQ(off.exit_code, 0) << off.output;
    EXPECT_FALSE(read_path_dump(dir / "off_dump/frame_0000.json").paths.empty());
}

// Layer strokes have round caps, as their SVG has: a one-point stroke and a stroke shorter
// than a pixel are dots of their width (not nothing, not a one-pixel tick), and a line's ends
// reach half its width past its end points.
TEST(VectorLayerCli, StipplesAreDotsAndEndsAreRound) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "dots.json") << R"({"size": [100, 100], "strokes": [
        {"points": [[20, 20]], "width": 6}, {"points": [[50, 50], [50.4, 50.2]], "width": 6},
        {"points": [[30, 80], [70, 80]], "width": 4}]})";
    std::ofstream(dir / "scene.json")
        << R"({"size": [100, 100], "background": [1, 1, 1], "layers": [{"strokes": "dots.json", "color": [0, 0, 0]}]})";
    const auto r = test::run_linework("render " + test::quote(dir / "scene.json") + " -o " + test::quote(dir / "out") +
                                      " --device cpu --validation");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const ImageRGBA8 image = read_image_rgba8(dir / "out/frame_0000.png");
    const auto ink = [&](int x, int y) { return image.pixels[4 * (size_t(y) * image.width + size_t(x))] < 128; };
    const auto ink_near = [&](int cx, int cy) {
        int n = 0;
        for (int y = cy - 6; y <= cy + 6; ++y)
            for (int x = cx - 6; x <= cx + 6; ++x) n += ink(x, y);
        return n;
    };
    // A disc of diameter 6 covers pi * 9 = 28.3 pixel centres, give or take its rim.
    for (const auto& [x, y] : {std::pair{20, 20}, std::pair{50, 50}}) {
        const int n = ink_near(x, y);
        EXPECT_GE(n, 20) << "dot at " << x << ", " << y;
        EXPECT_LE(n, 38) << "dot at " << x << ", " << y;
    }
    // The line (half width 2) with its caps: inked from x = 28 to 71 on its row, no further.
    EXPECT_TRUE(ink(28, 80) && ink(71, 80));
    EXPECT_FALSE(ink(26, 80) || ink(73, 80));
    // A tapering layer tapers ends, not dots: the dots keep their width.
    std::ofstream(dir / "taper.json")
        << R"({"size": [100, 100], "background": [1, 1, 1], "layers": [{"strokes": "dots.json", "color": [0, 0, 0], "taper": 8}]})";
    const auto t = test::run_linework("render " + test::quote(dir / "taper.json") + " -o " + test::quote(dir / "t") +
                                      " --device cpu --validation");
    ASSERT_EQ(t.exit_code, 0) << t.output;
    const ImageRGBA8 tapered = read_image_rgba8(dir / "t/frame_0000.png");
    for (const auto& [x, y] : {std::pair{20, 20}, std::pair{50, 50}}) {
        int n = 0;
        for (int v = y - 6; v <= y + 6; ++v)
            for (int u = x - 6; u <= x + 6; ++u) n += tapered.pixels[4 * (size_t(v) * tapered.width + size_t(u))] < 128;
        EXPECT_EQ(n, ink_near(x, y)) << "dot at " << x << ", " << y;
    }
    // Under a SLAM the dots are drawn solid, as without it: too short for the texture, they
    // were dropped as the tracker drops an extraction's fragments (spot_layers' flower centres).
    std::ofstream(dir / "slam.json") << R"({"size": [100, 100], "background": [1, 1, 1], "layers": [{"strokes": "dots.json",
        "color": [0, 0, 0], "slam": ")" + (test::source_dir() / "scenes/slams/dots.exr").string() + R"("}]})";
    const auto sl = test::run_linework("render " + test::quote(dir / "slam.json") + " -o " + test::quote(dir / "s") +
                                       " --device cpu --validation");
    ASSERT_EQ(sl.exit_code, 0) << sl.output;
    const ImageRGBA8 slam = read_image_rgba8(dir / "s/frame_0000.png");
    for (const auto& [x, y] : {std::pair{20, 20}, std::pair{50, 50}})
        for (int v = y - 6; v <= y + 6; ++v)
            for (int u = x - 6; u <= x + 6; ++u) {
                const size_t i = 4 * (size_t(v) * slam.width + size_t(u));
                ASSERT_EQ(slam.pixels[i], image.pixels[i]) << "dot at " << x << ", " << y << ": pixel " << u << ", " << v;
            }
}

// A SLAM layer draws its strokes in file order, the solid short ones among the textured: a
// dot drawn after a line lies over it, as in the same layer without a SLAM.
TEST(VectorLayerCli, ASlamLayerDrawsItsStrokesInFileOrder) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "order.json") << R"({"size": [100, 100], "strokes": [
        {"points": [[10, 50], [90, 50]], "width": 8, "color": [0, 0, 0]},
        {"points": [[50, 50]], "width": 14, "color": [1, 0, 0]}]})";
    std::ofstream(dir / "scene.json") << R"({"size": [100, 100], "background": [1, 1, 1], "layers": [{"strokes": "order.json",
        "slam": ")" + (test::source_dir() / "scenes/slams/pencil.exr").string() + R"("}]})";
    const auto r = test::run_linework("render " + test::quote(dir / "scene.json") + " -o " + test::quote(dir / "out") +
                                      " --device cpu --validation");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const ImageRGBA8 image = read_image_rgba8(dir / "out/frame_0000.png");
    int red = 0, other = 0, line_ink = 0;
    for (int y = 45; y <= 55; ++y)
        for (int x = 45; x <= 55; ++x) {
            if ((x - 50) * (x - 50) + (y - 50) * (y - 50) > 16) continue;  // within 4 px of the dot's centre
            const uint8_t* p = &image.pixels[4 * (size_t(y) * image.width + size_t(x))];
            (p[0] > 200 && p[1] < 60 && p[2] < 60 ? red : other)++;
        }
    for (int x = 15; x <= 35; ++x) line_ink += image.pixels[4 * (size_t(50) * image.width + size_t(x))] < 200;
    EXPECT_GT(line_ink, 5) << "the pencil line inks its row";
    EXPECT_EQ(other, 0) << red << " red pixels: the line was drawn over the dot";
}

}  // namespace
}  // namespace lw
