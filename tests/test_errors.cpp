// docs/ERRORS.md as a test: every row of its table is run and checked (exit code, message),
// so the document and the program cannot drift apart.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu/vk_check.h"
#include "io/image_io.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

struct Row {
    std::string input, failure, command, message;
    int exit_code = 0;
};

std::vector<Row> error_table() {
    std::ifstream in(test::source_dir() / "docs/ERRORS.md");
    std::vector<Row> rows;
    std::string line;
    // | input | failure | `linework …` | exit | `message` |
    const std::regex row(R"(^\| ([^|]+) \| ([^|]+) \| `linework([^`]*)` \| (\d) \| `([^`]*)` \|$)");
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, row)) rows.push_back({m[1], m[2], m[3], m[5], std::stoi(m[4])});
    }
    return rows;
}

std::string substitute(std::string text, const fs::path& tmp) {
    const std::pair<std::string, std::string> keys[] = {
        {"{tmp}", tmp.string()}, {"{data}", test::data_dir().string()}, {"{src}", test::source_dir().string()}};
    for (const auto& [key, value] : keys)
        for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The fixtures ERRORS.md lists.
void write_fixtures(const fs::path& tmp) {
    const fs::path data = test::data_dir();
    write(tmp / "empty.glb", "");
    {
        std::ifstream box(data / "models/BoxTextured/BoxTextured.glb", std::ios::binary);
        std::string head(100, '\0');
        box.read(head.data(), 100);
        write(tmp / "truncated.glb", head);
    }
    write(tmp / "text.png", "not an image\n");
    write(tmp / "text.exr", "not an exr\n");
    write(tmp / "badjson.json", "{\n");
    write(tmp / "overflow.json", R"({"model": "x.glb", "fov": 1e400})");
    const std::string spot = (data / "models/spot/spot.glb").string();
    write(tmp / "unknownkey.json", R"({"model": ")" + spot + R"(", "wobble": 1})");
    write(tmp / "samples8.json", R"({"model": ")" + spot + R"(", "samples": 8})");
    write(tmp / "badsize.json", R"({"model": ")" + spot + R"(", "size": [0, 10]})");
    write(tmp / "badsamples.json", R"({"model": ")" + spot + R"(", "samples": 2})");
    write(tmp / "setslam.json", R"({"model": ")" + spot + R"(", "line_sets": [{"name": "a", "style": {"slam": "nope.exr"}}]})");
    write(tmp / "layerfile.json", R"({"layers": [{"strokes": "nope.svg"}]})");
    write(tmp / "setlevels.json", R"({"model": ")" + spot +
                                      R"(", "lines": {"hidden_levels": 2}, "line_sets": [{"name": "a"}]})");
    write(tmp / "maxlength.json",
          R"({"model": ")" + spot + R"(", "line_sets": [{"name": "long", "style": {"chaining": {"max_length": 2e6}}}]})");
    write(tmp / "setsuffix.json", R"({"model": ")" + spot + R"(", "line_sets": [{"name": "rim-hidden"}]})");
    write(tmp / "sets.json", R"({"model": ")" + spot + R"(", "line_sets": [{"name": "rim"}]})");
    write(tmp / "camtypo.json", R"({"model": ")" + spot + R"(", "camera": {"eye": [0, 0, 3], "targt": [0, 0, 0]}})");
    write(tmp / "nooutline.json", R"({"layers": [{"strokes": ")" +
                                      (test::source_dir() / "scenes/patterns/flowers.svg").string() +
                                      R"(", "outline": false}]})");
    write(tmp / "minmax.json", R"({"model": ")" + spot +
                                   R"(", "line_sets": [{"name": "a", "style": {"chaining": {"min_length": 100, "max_length": 20}}}]})");
    write(tmp / "colorramp.json", R"({"model": ")" + spot +
                                      R"(", "line_sets": [{"name": "a", "style": {"color_modifiers": [{"input": "along", "ramp": [[1, [1, 0, 0]], [0, [0, 0, 1]]]}]}}]})");
    write(tmp / "sethidden.json",
          R"({"model": ")" + spot + R"(", "lines": {"hidden": "dashed"}, "line_sets": [{"name": "rim"}]})");
    fs::create_directories(tmp / "folder.json");
    write(tmp / "keyed.json", R"({"model": ")" + spot + R"(", "camera_path": {"keyframes": [{"time": 0, "eye": [0, 0, 5], "target": [0, 0, 0]}]}})");
    write(tmp / "nolines.json", R"({"model": ")" + spot + R"(", "lines": false})");
    write(tmp / "badcolor.json", R"({"model": ")" + spot + R"(", "background": "#ff88"})");
    write(tmp / "twice.json", R"({"model": [")" + spot + R"(", ")" + spot + R"("]})");
    const std::string fox = (data / "models/Fox/Fox.glb").string(), man = (data / "models/CesiumMan/CesiumMan.glb").string();
    write(tmp / "oneclip.json", R"({"model": [")" + fox + R"(", ")" + man + R"("], "animation": {"clip": "Walk"}})");
    fs::copy_file(test::source_dir() / "scenes/patterns/hatch_training.svg", tmp / "training.svg");
    write(tmp / "past.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    write(tmp / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    write(tmp / "words.obj", "hello world\n");
    write(tmp / "noheader.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n");
    write(tmp / "points.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n1 1 1\n");
    {
        std::ifstream quad(test::source_dir() / "tests/fuzz/corpus/mesh/quad_little.ply", std::ios::binary);
        std::string all((std::istreambuf_iterator<char>(quad)), std::istreambuf_iterator<char>());
        write(tmp / "short.ply", all.substr(0, all.find("end_header\n") + 11 + 40));  // half a vertex list
    }
    write(tmp / "text.ply", "not a ply\n");
    write(tmp / "strips.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 7\n");
    write(tmp / "model.stl", "solid x\nendsolid x\n");
    write(tmp / "nomodel.json", R"({"size": [10, 10]})");
    write(tmp / "missingmodel.json", R"({"model": "missing.glb"})");
    write(tmp / "layernostrokes.json", R"({"layers": [{"fill": [1, 0, 0]}]})");
    write(tmp / "layermissing.json", R"({"layers": [{"strokes": "nope.svg"}]})");
    write(tmp / "layertext.json", R"({"layers": [{"strokes": "text.svg"}]})");
    write(tmp / "slamtext.json", R"({"model": ")" + spot + R"(", "lines": {"silhouette": {"slam": "text.exr"}}})");
    write(tmp / "onepoint.json", R"({"points": [[1, 2]]})");
    write(tmp / "square.json", R"({"points": [[0, 0], [100, 0], [100, 100], [0, 100]], "closed": true})");
    write(tmp / "offpage.json", R"({"points": [[-500, -500], [-300, -500]]})");
    write(tmp / "doubled.json", R"({"points": [[50, 50], [300, 50]], "closed": true})");
    write(tmp / "afterz.svg", R"(<svg><path d="M0 0 L5 5 Z 3 4" stroke="black"/></svg>)");
    write(tmp / "unclosed.svg", "<svg><path d=\"M0 0 L5 5\">\n</svg>");
    write(tmp / "text.svg", "<svg><text x=\"1\" y=\"1\">words</text></svg>");
    write(tmp / "twocurves.svg", R"(<svg><path d="M0 0 L50 0"/><path d="M0 10 L50 10"/></svg>)");
    write(tmp / "strokeskey.json", R"({"strokes": [], "colour": 1})");
    const auto small = test::run_linework("ribbon-exemplar beads -o " + test::quote(tmp / "small.png") + " --size 16x16");
    ASSERT_EQ(small.exit_code, 0) << small.output;
    {
        // A PNG cut after its header: libpng's complaint comes in several lines.
        std::ifstream png(tmp / "small.png", std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>());
        write(tmp / "cut.png", bytes.substr(0, 60));
    }
    const auto tall = test::run_linework("ribbon-exemplar beads -o " + test::quote(tmp / "tall.png") + " --size 64x100");
    ASSERT_EQ(tall.exit_code, 0) << tall.output;
    {
        ImageRGBA8 blank;
        blank.width = 64;
        blank.height = 16;
        blank.pixels.assign(size_t(64 * 16 * 4), uint8_t(255));
        write_png(tmp / "blank.png", blank);
    }
    for (const auto& [folder, frames] : {std::pair{"dumps", 3}, std::pair{"shortdumps", 2}}) {
        fs::create_directories(tmp / folder);
        for (int f = 0; f < frames; ++f)
            write(tmp / folder / ("frame_000" + std::to_string(f) + ".json"),
                  R"({"frame": )" + std::to_string(f) + R"(, "width": 16, "height": 16, "paths": []})");
    }
    fs::create_directories(tmp / "baddump");
    write(tmp / "baddump/frame_0000.json", R"({"width": 16, "height": 16, "paths": []})");
    // Frames 0 and 2 (1 missing); frames 0-2 at another size; a file named for another frame.
    for (const auto& [folder, f, size] : {std::tuple{"gapdumps", 0, 16}, std::tuple{"gapdumps", 2, 16},
                                          std::tuple{"bigdumps", 0, 32}, std::tuple{"bigdumps", 1, 32},
                                          std::tuple{"bigdumps", 2, 32}, std::tuple{"misnamed", 1, 16}}) {
        fs::create_directories(tmp / folder);
        const int frame = std::string(folder) == "misnamed" ? 0 : f;
        write(tmp / folder / ("frame_000" + std::to_string(f) + ".json"),
              R"({"frame": )" + std::to_string(frame) + R"(, "width": )" + std::to_string(size) + R"(, "height": )" +
                  std::to_string(size) + R"(, "paths": []})");
    }
    fs::create_directories(tmp / "resume");
    fs::copy_file(tmp / "small.png", tmp / "resume/frame_0000.png");
}

TEST(ErrorTable, EveryRowGivesItsMessageAndExitCode) {
    const fs::path tmp = test::temp_dir();
    write_fixtures(tmp);
    const std::vector<Row> rows = error_table();
    ASSERT_GE(rows.size(), 30u) << "docs/ERRORS.md's table was not found or lost rows";
    const bool has_gpu = test::run_linework("devices").output.find("[gpu") != std::string::npos;
    for (const Row& row : rows) {
        if (has_gpu && row.command.find("--device gpu") != std::string::npos) continue;
        SCOPED_TRACE(row.input + " / " + row.failure);
        const auto r = test::run_linework(substitute(row.command, tmp));
        EXPECT_EQ(r.exit_code, row.exit_code) << r.output;
        EXPECT_NE(r.output.find(substitute(row.message, tmp)), std::string::npos) << r.output;
        // A bad command line is refused before any work: its error is the first thing printed.
        if (row.exit_code == 2) {
            EXPECT_EQ(r.output.rfind("linework: error: ", 0), 0u) << r.output;
        }
        if (row.exit_code == 1) {
            EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
            EXPECT_NE(r.output.find("linework: error: "), std::string::npos) << r.output;
        }
    }
}

TEST(VkCheck, FailuresNameTheCallAndTheResult) {
    const std::pair<VkResult, std::string> cases[] = {
        {VK_ERROR_DEVICE_LOST, "vkQueueSubmit failed: VK_ERROR_DEVICE_LOST"},
        {VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkQueueSubmit failed: VK_ERROR_OUT_OF_DEVICE_MEMORY"},
        {VK_ERROR_EXTENSION_NOT_PRESENT, "vkQueueSubmit failed: VK_ERROR_EXTENSION_NOT_PRESENT"}};
    for (const auto& [result, message] : cases) {
        try {
            vk_check(result, "vkQueueSubmit");
            ADD_FAILURE() << "no error for " << message;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
    EXPECT_NO_THROW(vk_check(VK_SUCCESS, "vkQueueSubmit"));
}

}  // namespace
}  // namespace lw
