// `linework slam` as a user meets it: the SLAM file and its metadata, the contact sheet,
// exit codes and one-line messages naming the file.
#include <filesystem>
#include <fstream>

#include "io/image_io.h"
#include "io/slam_io.h"
#include "slam_synth/slam_builder.h"
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

bool one_line_naming(const test::CommandResult& r, const fs::path& file) {
    return r.output.find("linework: error: " + file.string()) != std::string::npos &&
           std::count(r.output.begin(), r.output.end(), '\n') == 1;
}

// An 8-row exemplar of irregular dashes, black on white.
fs::path write_exemplar(const fs::path& dir) {
    ImageRGBA8 image{.width = 128, .height = 8, .pixels = std::vector<uint8_t>(128 * 8 * 4, 255)};
    for (int x = 0, k = 0; x < 128; ++k) {
        const int length = 6 + (k * 7) % 9;
        for (int i = x; i < std::min(128, x + length); ++i)
            for (int y = 2; y < 6; ++y) std::fill(image.at(i, y), image.at(i, y) + 3, uint8_t(0));
        x += length + 4 + (k * 5) % 6;
    }
    const fs::path path = dir / "dashes.png";
    write_png(path, image);
    return path;
}

class SlamCli : public ::testing::Test {};

TEST_F(SlamCli, WritesTheSlamAndTheContactSheet) {
    const fs::path dir = test::temp_dir(), exemplar = write_exemplar(dir);
    const fs::path out = dir / "dashes.exr", sheet = dir / "sheet.png";
    const auto r = run_linework("slam " + quote(exemplar) + " -o " + quote(out) + " --levels 5 --length 256 " +
                                "--iterations 4 --seed 3 --preview " + quote(sheet) + " --report");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* text : {"padded to 16 rows", "level  4  l = 1.0000", "self-similarity error", "cross-scale phase",
                             "RMS difference of adjacent levels", "fidelity to the exemplar", "largest grain over all levels",
                             "element sizes not imposed: the exemplar's", "are unlike",
                             "wrote"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
    const Slam slam = read_slam(out);
    EXPECT_EQ(slam.levels, 5);
    EXPECT_EQ(slam.length, 256);
    EXPECT_EQ(slam.height, 8);
    EXPECT_EQ(slam.exemplar, exemplar.string());
    EXPECT_EQ(slam.seed, 3u);
    EXPECT_EQ(slam_self_similarity_error(slam), 0.0f);  // level 1.0 is level 0.5 twice, exactly
    const ImageRGBA8 preview = read_image_rgba8(sheet);
    EXPECT_EQ(preview.width, 256);
    EXPECT_EQ(preview.height, 8 + 4 + 5 * (8 + 4));
}

// The report says when the exemplar's elements are alike and their sizes imposed.
TEST_F(SlamCli, TheReportSaysWhenElementSizesAreImposed) {
    const fs::path dir = test::temp_dir(), exemplar = dir / "same.png";
    ImageRGBA8 image{.width = 128, .height = 8, .pixels = std::vector<uint8_t>(128 * 8 * 4, 255)};
    for (int x = 2; x + 8 < 128; x += 14)  // identical 8 × 4 dashes
        for (int i = x; i < x + 8; ++i)
            for (int y = 2; y < 6; ++y) std::fill(image.at(i, y), image.at(i, y) + 3, uint8_t(0));
    write_png(exemplar, image);
    const auto r = run_linework("slam " + quote(exemplar) + " -o " + quote(dir / "same.exr") +
                                " --levels 3 --length 256 --iterations 2 --report");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("element sizes imposed: the exemplar's 9 elements are alike (32-32 texels)"), std::string::npos)
        << r.output;
}

TEST_F(SlamCli, BadInputIsOneLineNamingTheFile) {
    const fs::path dir = test::temp_dir();
    const fs::path missing = dir / "missing.png";
    auto r = run_linework("slam " + quote(missing) + " -o " + quote(dir / "x.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_line_naming(r, missing)) << r.output;

    const fs::path text = dir / "text.png";
    std::ofstream(text) << "not an image\n";
    r = run_linework("slam " + quote(text) + " -o " + quote(dir / "x.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_line_naming(r, text)) << r.output;

    const fs::path tall = dir / "tall.png";
    write_png(tall, ImageRGBA8{.width = 64, .height = 100, .pixels = std::vector<uint8_t>(64 * 100 * 4, 255)});
    r = run_linework("slam " + quote(tall) + " -o " + quote(dir / "x.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(one_line_naming(r, tall)) << r.output;
}

TEST_F(SlamCli, BadUsageExitsWithTwo) {
    const fs::path dir = test::temp_dir(), exemplar = write_exemplar(dir);
    auto r = run_linework("slam " + quote(exemplar) + " -o " + quote(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    r = run_linework("slam " + quote(exemplar) + " -o " + quote(dir / "x.exr") + " --length 100");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    r = run_linework("slam " + quote(exemplar) + " -o " + quote(dir / "x.exr") + " --levels 1");
    EXPECT_EQ(r.exit_code, 2) << r.output;
}

}  // namespace
}  // namespace lw
