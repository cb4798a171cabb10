// `linework ribbon` and `linework ribbon-exemplar` as a user meets them: files written, the DP
// dump, exit codes and one-line messages naming the file.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/image_io.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;
using test::run_linework;

using test::quote;

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A small exemplar and curve in a fresh folder.
struct RibbonFiles {
    fs::path dir = test::temp_dir();
    fs::path exemplar = dir / "beads.png";
    fs::path curve = dir / "curve.json";
    RibbonFiles() {
        const auto r = run_linework("ribbon-exemplar beads -o " + quote(exemplar) + " --size 48x16 --seed 3");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        write_text(curve, R"({"points": [[10, 20], [30, 14], [50, 20], [70, 26]], "closed": false})");
    }
};

bool one_line_naming(const test::CommandResult& r, const fs::path& file) {
    return r.output.find("linework: error: " + file.string()) != std::string::npos &&
           std::count(r.output.begin(), r.output.end(), '\n') == 1;
}

TEST(RibbonCli, SynthesizesAndDumpsTheDp) {
    const RibbonFiles f;
    const fs::path out = f.dir / "out.png", dump = f.dir / "dp.json";
    const auto r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(f.curve) + " -o " + quote(out) +
                                " --piece 4 --stitch --seed 5 --device cpu --dump-dp " + quote(dump));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("device: llvmpipe"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("stitch: seam error"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("wrote " + out.string()), std::string::npos) << r.output;
    EXPECT_GT(fs::file_size(out), 200u);

    const auto d = nlohmann::json::parse(std::ifstream(dump));
    std::vector<std::string> keys;
    for (const auto& [key, value] : d.items()) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    EXPECT_EQ(keys, (std::vector<std::string>{"greedy_cost", "pieces", "positions", "random_cost", "row_ms",
                                              "seam_costs", "total_cost", "valid_counts"}));
    const size_t pieces = d["pieces"].get<size_t>();
    EXPECT_GE(pieces, 15u);
    ASSERT_EQ(d["positions"].size(), pieces);
    EXPECT_EQ(d["positions"][0].size(), 2u);
    EXPECT_EQ(d["valid_counts"].size(), pieces);
    EXPECT_EQ(d["seam_costs"].size(), pieces - 1);
    EXPECT_EQ(d["row_ms"].size(), pieces - 1);
    double sum = 0.0;
    for (const auto& c : d["seam_costs"]) sum += c.get<double>();
    EXPECT_NEAR(sum, d["total_cost"].get<double>(), 1e-3 * (1.0 + sum));
    EXPECT_LE(d["total_cost"].get<double>(), d["greedy_cost"].get<double>());
    EXPECT_LE(d["total_cost"].get<double>(), d["random_cost"].get<double>());
}

// On a CPU device `auto` runs the C++ DP and stitching; `--compute device` the Vulkan
// kernels; the two give the same pixels and the same DP.
TEST(RibbonCli, AutoTakesTheHostOnCpuDevicesWithTheKernelsResults) {
    const RibbonFiles f;
    std::string dumps[2];
    const char* sites[2] = {"auto", "device"};
    for (int i = 0; i < 2; ++i) {
        const fs::path out = f.dir / (std::string(sites[i]) + ".png"), dump = f.dir / (std::string(sites[i]) + ".json");
        const auto r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(f.curve) + " -o " + quote(out) +
                                    " --piece 4 --stitch --seed 5 --device cpu --compute " + sites[i] + " --dump-dp " +
                                    quote(dump));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find(i == 0 ? "dp (C++, on the host)" : "dp (Vulkan compute)"), std::string::npos)
            << r.output;
        auto d = nlohmann::json::parse(std::ifstream(dump));
        d.erase("row_ms");
        dumps[i] = d.dump();
    }
    EXPECT_EQ(dumps[0], dumps[1]);
    EXPECT_TRUE(read_image_rgba8(f.dir / "auto.png").pixels == read_image_rgba8(f.dir / "device.png").pixels);
}

TEST(RibbonCli, ClosedSvgCurveEndsWhereItStarts) {
    const RibbonFiles f;
    const fs::path svg = f.dir / "loop.svg", dump = f.dir / "dp.json";
    write_text(svg, R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M 20 40 C 20 10 80 10 80 40 C 80 70 20 70 20 40"/></svg>)");
    const auto r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(svg) + " --closed -o " +
                                quote(f.dir / "loop.png") + " --piece 6 --size 100x80 --device cpu --dump-dp " +
                                quote(dump));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("closed"), std::string::npos) << r.output;
    const auto d = nlohmann::json::parse(std::ifstream(dump));
    EXPECT_EQ(d["positions"].front(), d["positions"].back());
    EXPECT_EQ(d["seam_costs"].size(), d["pieces"].get<size_t>() - 1);
}

TEST(RibbonCli, BadInputNamesTheFile) {
    const RibbonFiles f;
    const fs::path out = f.dir / "out.png";
    const fs::path missing = f.dir / "missing.png";
    auto r = run_linework("ribbon " + quote(missing) + " --curve " + quote(f.curve) + " -o " + quote(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r, missing)) << r.output;

    const fs::path not_png = f.dir / "not.png";
    write_text(not_png, "hello");
    r = run_linework("ribbon " + quote(not_png) + " --curve " + quote(f.curve) + " -o " + quote(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r, not_png)) << r.output;

    const fs::path no_curve = f.dir / "none.json";
    r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(no_curve) + " -o " + quote(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r, no_curve)) << r.output;

    const fs::path bad_curve = f.dir / "bad.json";
    write_text(bad_curve, R"({"points": [[0, 0], [1, "x"]]})");
    r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(bad_curve) + " -o " + quote(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r, bad_curve)) << r.output;
    EXPECT_NE(r.output.find("points[1]"), std::string::npos) << r.output;

    const fs::path degenerate = f.dir / "dot.json";
    write_text(degenerate, R"({"points": [[5, 5], [5, 5]]})");
    r = run_linework("ribbon " + quote(f.exemplar) + " --curve " + quote(degenerate) + " -o " + quote(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r, degenerate)) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(RibbonCli, BadFlagsAreUsageErrors) {
    const RibbonFiles f;
    const std::string base = "ribbon " + quote(f.exemplar) + " --curve " + quote(f.curve) + " -o " + quote(f.dir / "o.png");
    for (const std::string flags : {" --piece -1", " --width 0", " --scale nan", " --size 0x5", " --size big",
                                    " --device fastest", " --frobnicate"}) {
        const auto r = run_linework(base + flags);
        EXPECT_EQ(r.exit_code, 2) << flags << ": " << r.output;
    }
    EXPECT_EQ(run_linework("ribbon --curve " + quote(f.curve) + " -o x.png").exit_code, 2);  // no exemplar
    EXPECT_EQ(run_linework("ribbon-exemplar velvet -o x.png").exit_code, 2);
}

// A --scale under the pattern's height cuts every piece, along a straight curve as along a
// bend: the warning names the scale and the least that holds the pattern, not the bends.
TEST(RibbonCli, AScaleUnderThePatternIsNamedAsTheCause) {
    const RibbonFiles f;
    const std::string base = "ribbon " + quote(f.exemplar) + " --curve " + quote(f.curve) + " -o " + quote(f.dir / "o.png");
    const auto small = run_linework(base + " --scale 4");
    EXPECT_EQ(small.exit_code, 0) << small.output;
    EXPECT_NE(small.output.find("--scale 4 is too small for the pattern's"), std::string::npos) << small.output;
    EXPECT_EQ(small.output.find("bends this tightly"), std::string::npos) << small.output;
    const auto fine = run_linework(base);
    EXPECT_EQ(fine.output.find("cannot hold the whole pattern"), std::string::npos) << fine.output;
}

TEST(RibbonCli, HelpExplains) {
    const auto r = run_linework("ribbon --help");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const char* word : {"--curve", "--closed", "--stitch", "--piece", "--width", "--scale", "--seed", "--size",
                             "--dump-dp", "--device", "alpha"})
        EXPECT_NE(r.output.find(word), std::string::npos) << word;
}

// Ribbons as a stroke style of the 3D renderer: a scene whose silhouettes are drawn with a
// ribbon exemplar shows the pattern's ink where the plain render has none, and draws no
// plain silhouette line.
TEST(RibbonCli, SceneLineStyleDrawsRibbonsAlongPaths) {
    const RibbonFiles files;
    const fs::path model = test::data_dir() / "models/spot/spot.glb";
    auto scene = [&](const std::string& silhouette) {
        return R"({"model": ")" + model.string() + R"(", "size": [160, 120], "shading": "unlit", "color": [1, 1, 1],
                 "lines": {"silhouette": )" + silhouette + R"(, "suggestive": {"enabled": false},
                           "crease": {"enabled": false}, "border": {"enabled": false}}})";
    };
    write_text(files.dir / "ribbon.json", scene(R"({"width": 10, "ribbon": ")" + files.exemplar.string() + R"("})"));
    write_text(files.dir / "none.json", scene(R"({"enabled": false})"));
    const auto r = run_linework("render " + quote(files.dir / "ribbon.json") + " -o " + quote(files.dir / "ribbon") +
                                " --device cpu");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("ribbons (silhouette): "), std::string::npos) << r.output;
    const auto r2 = run_linework("render " + quote(files.dir / "none.json") + " -o " + quote(files.dir / "none") +
                                 " --device cpu");
    ASSERT_EQ(r2.exit_code, 0) << r2.output;
    const ImageRGBA8 ribbon = read_image_rgba8(files.dir / "ribbon/frame_0000.png");
    const ImageRGBA8 none = read_image_rgba8(files.dir / "none/frame_0000.png");
    ASSERT_EQ(ribbon.pixels.size(), none.pixels.size());
    // The beads exemplar's ink is coloured; the unlit white cow on a white background has none.
    size_t coloured = 0, black = 0;
    for (size_t i = 0; i < ribbon.pixels.size(); i += 4) {
        const int r_ = ribbon.pixels[i], g = ribbon.pixels[i + 1], b = ribbon.pixels[i + 2];
        coloured += std::max({r_, g, b}) - std::min({r_, g, b}) > 40;
        black += r_ + g + b < 30;
    }
    EXPECT_GT(coloured, 100u);
    EXPECT_LT(black, coloured / 4) << "plain silhouette lines drawn under the ribbon";

    // A missing exemplar names the scene, the key and the file; a SLAM and a ribbon on one
    // type name the key.
    write_text(files.dir / "missing.json", scene(R"({"ribbon": ")" + (files.dir / "nope.png").string() + R"("})"));
    const auto missing = run_linework("render " + quote(files.dir / "missing.json") + " -o " + quote(files.dir / "m"));
    EXPECT_EQ(missing.exit_code, 1) << missing.output;
    EXPECT_NE(missing.output.find("linework: error: " + (files.dir / "missing.json").string() +
                                  ": lines.silhouette.ribbon: " + (files.dir / "nope.png").string() + ": no such file"),
              std::string::npos)
        << missing.output;
    write_text(files.dir / "both.json", scene(R"({"ribbon": "a.png", "slam": "b.exr"})"));
    const auto both = run_linework("render " + quote(files.dir / "both.json") + " -o " + quote(files.dir / "b"));
    EXPECT_EQ(both.exit_code, 1) << both.output;
    EXPECT_NE(both.output.find("lines.silhouette.ribbon"), std::string::npos) << both.output;
}

}  // namespace
}  // namespace lw
