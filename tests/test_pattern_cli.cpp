// `linework pattern` and `linework hatch` as a user meets them: files written, summary lines,
// the --kl2 block lines, --help, exit codes and one-line messages naming the file.
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "test_support.h"
#include "vector/stroke_io.h"

namespace lw {
namespace {

namespace fs = std::filesystem;
using test::quote;
using test::run_linework;

fs::path pattern(const char* name) { return test::source_dir() / "scenes" / "patterns" / name; }

bool one_error_line_naming(const test::CommandResult& r, const fs::path& file) {
    return r.output.find("linework: error: " + file.string()) != std::string::npos &&
           std::count(r.output.begin(), r.output.end(), '\n') == 1;
}

TEST(PatternCli, FillsARegionAndFollowsAPath) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "region.json") << R"({"points": [[0, 0], [300, 0], [300, 200], [0, 200]], "closed": true})";
    std::ofstream(dir / "path.svg") << R"(<svg><path d="M 20 100 C 120 20 240 180 420 90"/></svg>)";
    const fs::path out2d = dir / "bars.svg", out1d = dir / "hatch.json";
    auto r = run_linework("pattern " + quote(pattern("crosses.svg")) + " --region " + quote(dir / "region.json") +
                          " -o " + quote(out2d) + " --scale 10 --seed 3");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("84 strokes -> 42 elements at scale ε = 10"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("wrote " + out2d.string()), std::string::npos) << r.output;
    const StrokeSet crosses = load_strokes(out2d);
    EXPECT_EQ(crosses.strokes.size() % 2, 0u);  // whole crosses
    EXPECT_GT(crosses.strokes.size(), 80u);  // 42 crosses in 54400 px² -> 46 in 60000

    r = run_linework("pattern " + quote(pattern("hatch_sketchy.svg")) + " --path " + quote(dir / "path.svg") + " -o " +
                     quote(out1d) + " --scale 5 --rings 4 --variation 0.5");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("4-ring neighbourhoods"), std::string::npos) << r.output;
    EXPECT_GT(load_strokes(out1d).strokes.size(), 40u);
}

// A scale as large as the drawing makes the whole reference one element: there is nothing to
// arrange, and the command says so in one warning line naming the reference (the output, the
// reference copied once, is still written). The default scale gives no warning.
TEST(PatternCli, AScaleThatMakesOneElementIsSaid) {
    const fs::path dir = test::temp_dir();
    const std::string region = quote(test::source_dir() / "scenes/curves/circle.json");
    auto r = run_linework("pattern " + quote(pattern("flowers.svg")) + " --region " + region + " -o " +
                          quote(dir / "one.svg") + " --scale 1e30");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: " + pattern("flowers.svg").string() +
                            ": its 276 strokes are one element at scale ε = 1e+30: there is no arrangement to follow"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(load_strokes(dir / "one.svg").strokes.size(), 276u);
    r = run_linework("pattern " + quote(pattern("flowers.svg")) + " --region " + region + " -o " + quote(dir / "many.svg"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

TEST(PatternCli, HelpAndErrors) {
    const fs::path dir = test::temp_dir();
    auto r = run_linework("pattern --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--path", "--region", "--scale", "--rings", "--variation", "--seed", "--ref-path"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    const std::string ref = quote(pattern("stipples.svg"));
    // Usage errors: exit 2.
    EXPECT_EQ(run_linework("pattern " + ref + " -o " + quote(dir / "o.svg")).exit_code, 2);
    std::ofstream(dir / "p.json") << R"({"points": [[0, 0], [100, 0]]})";
    EXPECT_EQ(run_linework("pattern " + ref + " -o " + quote(dir / "o.svg") + " --path " + quote(dir / "p.json") +
                           " --region " + quote(dir / "p.json"))
                  .exit_code,
              2);
    EXPECT_EQ(run_linework("pattern " + ref + " -o x.svg --path " + quote(dir / "p.json") + " --variation 2").exit_code, 2);
    // Bad files: exit 1, one line naming the file.
    std::ofstream(dir / "bad.svg") << R"(<svg><text x="1" y="1">a text is no stroke</text></svg>)";
    r = run_linework("pattern " + quote(dir / "bad.svg") + " -o " + quote(dir / "o.svg") + " --path " + quote(dir / "p.json"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_error_line_naming(r, dir / "bad.svg")) << r.output;
    std::ofstream(dir / "flat.json") << R"({"points": [[0, 0], [100, 0], [50, 0]]})";
    r = run_linework("pattern " + ref + " -o " + quote(dir / "o.svg") + " --region " + quote(dir / "flat.json"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_error_line_naming(r, dir / "flat.json")) << r.output;
    r = run_linework("pattern " + ref + " -o " + quote(dir / "o.svg") + " --path " + quote(dir / "missing.json"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_error_line_naming(r, dir / "missing.json")) << r.output;
}

TEST(HatchCli, PrintsOneKl2LinePerBlockAndWritesTheStrokes) {
    const fs::path dir = test::temp_dir();
    const fs::path out = dir / "hatch.svg";
    const auto r = run_linework("hatch " + quote(pattern("hatch_training.svg")) + " -o " + quote(out) +
                                " --count 120 --kl2 --seed 2 2>/dev/null; exit $?");  // stdout only
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::regex line(R"(block (\d+) strokes (\d+)-(\d+) KL2 ([0-9.]+))");
    std::vector<std::string> lines;
    std::stringstream stream(r.output);
    for (std::string l; std::getline(stream, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), 3u) << r.output;  // 50 + 50 + 20, nothing else on stdout
    std::smatch m;
    ASSERT_TRUE(std::regex_match(lines[0], m, line)) << lines[0];
    EXPECT_EQ(m[2], "1");
    EXPECT_EQ(m[3], "50");
    ASSERT_TRUE(std::regex_match(lines[2], m, line)) << lines[2];
    EXPECT_EQ(m[1], "3");
    EXPECT_EQ(m[3], "120");
    const StrokeSet s = load_strokes(out);
    EXPECT_EQ(s.strokes.size(), 120u);
    std::ifstream in(out);
    const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t elements = size_t(std::count(svg.begin(), svg.end(), '\n')) - 4;
    EXPECT_EQ(elements, 120u);  // one <polyline> or <path> per stroke
}

TEST(HatchCli, AlongPathsHelpAndErrors) {
    const fs::path dir = test::temp_dir();
    auto r = run_linework("hatch " + quote(pattern("hatch_training.svg")) + " -o " + quote(dir / "a.svg") +
                          " --count 200 --along " + quote(pattern("hatch_paths.svg")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("along 3 path(s)"), std::string::npos) << r.output;
    EXPECT_GT(load_strokes(dir / "a.svg").strokes.size(), 90u);

    r = run_linework("hatch --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--count", "--window", "--along", "--seed", "--kl2", "--threshold"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    EXPECT_EQ(run_linework("hatch " + quote(pattern("hatch_training.svg")) + " -o x.svg").exit_code, 2);  // no --count
    r = run_linework("hatch " + quote(pattern("hatch_training.svg")) + " -o x.svg --count 5 --window 60");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--window: 60 must be smaller than the training size (41 strokes"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("give --window 40 or less"), std::string::npos) << r.output;
    // The default window, which the user did not give, is named as such.
    std::ofstream(dir / "four.json") << R"({"strokes": [{"points": [[0, 0], [1, 1]]}, {"points": [[2, 0], [3, 1]]},
        {"points": [[4, 0], [5, 1]]}, {"points": [[6, 0], [7, 1]]}]})";
    r = run_linework("hatch " + quote(dir / "four.json") + " -o x.svg --count 5");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--window: 6 (the default) must be smaller"), std::string::npos) << r.output;
    std::ofstream(dir / "two.json") << R"({"strokes": [{"points": [[0, 0], [1, 1]]}, {"points": [[2, 0], [3, 1]]}]})";
    r = run_linework("hatch " + quote(dir / "two.json") + " -o x.svg --count 5");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_error_line_naming(r, dir / "two.json")) << r.output;
    std::ofstream(dir / "paths.json") << R"({"strokes": [{"points": [[5, 5]]}]})";
    r = run_linework("hatch " + quote(pattern("hatch_training.svg")) + " -o x.svg --count 5 --along " +
                     quote(dir / "paths.json"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_error_line_naming(r, dir / "paths.json")) << r.output;
}

}  // namespace
}  // namespace lw
