// `linework ribbon` and `linework ribbon-exemplar` as a user meets them: files written, the DP
// dump, exit codes and one-line messages naming the file.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;
using test::run_linework;

// Shell-quoted path (built with += : GCC 12 warns falsely about "'" + std::string&&).
std::string quote(const fs::path& p) {
    std::string q = "'";
    q += p.string();
    q += "'";
    return q;
}

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

TEST(RibbonCli, HelpExplains) {
    const auto r = run_linework("ribbon --help");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const char* word : {"--curve", "--closed", "--stitch", "--piece", "--width", "--scale", "--seed", "--size",
                             "--dump-dp", "--device", "alpha"})
        EXPECT_NE(r.output.find(word), std::string::npos) << word;
}

}  // namespace
}  // namespace lw
