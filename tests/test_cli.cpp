// The `linework` command as a user meets it: exit codes, messages, files written.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "io/image_io.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;
using test::quote;
using test::run_linework;

// Every invalid glTF file shipped in tests/data/invalid (copies of ../shared/invalid).
std::vector<std::string> invalid_files() {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(test::data_dir() / "invalid")) {
        const auto ext = entry.path().extension();
        if (ext == ".glb" || ext == ".gltf") files.push_back(fs::relative(entry.path(), test::data_dir() / "invalid").string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

class InvalidModel : public ::testing::TestWithParam<std::string> {};

TEST_P(InvalidModel, RenderFailsWithOneClearError) {
    const fs::path file = test::data_dir() / "invalid" / GetParam();
    const auto r = run_linework("render " + quote(file) + " -o " + quote(test::temp_dir()));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("linework: error: " + file.string() + ": "), std::string::npos)
        << "the message must name the file: " << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
}

INSTANTIATE_TEST_SUITE_P(SharedInvalid, InvalidModel, ::testing::ValuesIn(invalid_files()), [](const auto& param_info) {
    std::string name = param_info.param;
    for (auto& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
});

TEST(Cli, RendersTheDefaultScene) {
    const fs::path out = test::temp_dir();
    const auto r = run_linework("render " + quote(test::source_dir() / "scenes/default.json") + " -o " + quote(out) +
                                " --device cpu --size 200x150 --exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("device: llvmpipe"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("size: 200x150"), std::string::npos) << r.output;
    // The head scan's box (min and max of its positions, in glTF units).
    EXPECT_NE(r.output.find("bounds: min (-4.276, -3.973, -2.59), max (4.276, 3.973, 2.59), centre (0, 1.192e-07, "
                            "-9.537e-06), radius 6.386"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("progress: 24/24 frames"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("wrote " + (out / "frame_0000.png").string()), std::string::npos) << r.output;
    EXPECT_GT(fs::file_size(out / "frame_0000.png"), 500u);
    EXPECT_GT(fs::file_size(out / "frame_0000.exr"), 200u * 150u);  // 5 float channels, compressed
    EXPECT_TRUE(fs::exists(out / "frame_0023.png")) << "the default scene turns over 24 frames";
}

// --exr writes what compositing tools read: colour in linear light (premultiplied) and Z as
// eye depth (the largest float where nothing was drawn). It wrote the PNG's sRGB-encoded
// bytes as floats (a grey #808080 read 0.502, not 0.216) and the depth buffer's [0, 1] as Z.
TEST(Cli, TheExrIsLinearWithEyeDepth) {
    const fs::path out = test::temp_dir();
    const auto r = run_linework("render " + quote(test::source_dir() / "scenes/spot.json") + " -o " + quote(out) +
                                " --device cpu --size 96x72 --background '#808080' --exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Imf::InputFile in((out / "frame_0000.exr").string().c_str());
    std::vector<std::string> names;
    for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) names.push_back(c.name());
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R", "Z"}));  // as EXR stores them, by name
    const Imath::Box2i window = in.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    ASSERT_EQ(width, 96);
    ASSERT_EQ(height, 72);
    std::vector<float> pixels(size_t(width) * height * 5);
    Imf::FrameBuffer frame;
    const char* order[5] = {"R", "G", "B", "A", "Z"};
    for (size_t c = 0; c < 5; ++c)
        frame.insert(order[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), sizeof(float) * 5,
                                          sizeof(float) * 5 * size_t(width)));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    const auto at = [&](int x, int y, int c) { return pixels[(size_t(y) * width + x) * 5 + c]; };
    // The corner is background: sRGB 128/255 in linear light, opaque, nothing there.
    EXPECT_NEAR(at(0, 0, 0), 0.2158f, 1e-3f);
    EXPECT_EQ(at(0, 0, 3), 1.0f);
    EXPECT_EQ(at(0, 0, 4), std::numeric_limits<float>::max());
    // The centre is the cow, seen from spot.json's eye about 3.5 units from its middle.
    const float z = at(48, 36, 4);
    EXPECT_GT(z, 2.5f);
    EXPECT_LT(z, 4.0f);
}

// The scene key coherence.policy draws what --param draws, and the flag overrides the key.
TEST(Cli, CoherencePolicyKeyDrawsAsTheFlag) {
    const fs::path dir = test::temp_dir();
    const std::string model = (test::data_dir() / "models/spot/spot.glb").string();
    const std::string common = R"("model": ")" + model + R"(", "size": [160, 120], "samples": 1,
        "camera": {"eye": [2.6, 0.9, -2.4], "target": [0, 0.05, 0], "fov": 35, "orbit": 40},
        "lines": {"silhouette": {"slam": ")" + (test::source_dir() / "scenes/slams/dots.exr").string() + R"("}})";
    std::ofstream(dir / "key.json") << "{" + common + R"(, "coherence": {"policy": "arclength"}})";
    std::ofstream(dir / "plain.json") << "{" + common + "}";
    const auto render = [&](const std::string& scene, const std::string& flags, const std::string& out) {
        const auto r = run_linework("render " + quote(dir / scene) + " -o " + quote(dir / out) + " --frames 0:2 --device cpu" + flags);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return read_image_rgba8(dir / out / "frame_0002.png").pixels;
    };
    const auto by_key = render("key.json", "", "key");
    EXPECT_EQ(by_key, render("plain.json", " --param arclength", "flag"));
    EXPECT_NE(by_key, render("plain.json", "", "coherent"));
    EXPECT_EQ(render("key.json", " --param coherent", "overridden"), render("plain.json", "", "coherent2"));
}

TEST(Cli, ExplicitCameraChangesTheImage) {
    const fs::path out = test::temp_dir();
    const fs::path model = test::data_dir() / "models/spot/spot.glb";
    auto a = run_linework("render " + quote(model) + " -o " + quote(out / "a") + " --device cpu --size 96x96");
    auto b = run_linework("render " + quote(model) + " -o " + quote(out / "b") +
                          " --device cpu --size 96x96 --eye 3,0,0 --target 0,0,0 --fov 30");
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    auto d = run_linework("diff " + quote(out / "a/frame_0000.png") + " " + quote(out / "b/frame_0000.png"));
    EXPECT_EQ(d.exit_code, 1) << d.output;
    // A mismatch names the thresholds passed: here PSNR and the share of differing pixels.
    EXPECT_NE(d.output.find("MISMATCH: psnr "), std::string::npos) << d.output;
    EXPECT_NE(d.output.find("dB < --min-psnr 40; differing pixels "), std::string::npos) << d.output;
    EXPECT_NE(d.output.find("> --max-differing 0.005 (0.5 %)"), std::string::npos) << d.output;
}

TEST(Cli, UsageErrorsExitWithTwo) {
    const std::string model = quote(test::data_dir() / "models/spot/spot.glb");
    const std::string out = quote(test::temp_dir());
    for (const std::string& args : {std::string(""), std::string("render"), "render " + model, "render " + model + " -o " + out + " --device fast",
                                    "render " + model + " -o " + out + " --size 0x10",
                                    "render " + model + " -o " + out + " --size big",
                                    "render " + model + " -o " + out + " --eye 1,2",
                                    "render " + model + " -o " + out + " --shading glossy", std::string("frobnicate")}) {
        const auto r = run_linework(args);
        EXPECT_EQ(r.exit_code, 2) << "linework " << args << "\n" << r.output;
    }
}

// Arguments CLI11 did not expect are named in the order given, one with a space whole (CLI11
// listed them backwards, and splitting its message cut such an argument in two).
TEST(Cli, UnexpectedArgumentsAreNamedAsGiven) {
    const std::string model = quote(test::data_dir() / "models/spot/spot.glb");
    const std::string out = quote(test::temp_dir());
    auto r = run_linework("render " + model + " -o " + out + " --sizee 320x240");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("unexpected arguments (an unknown option, or a value too many): --sizee 320x240"),
              std::string::npos)
        << r.output;
    r = run_linework("render " + model + " -o " + out + " 'my file.png'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("unexpected argument (an unknown option, or a value too many): 'my file.png'"),
              std::string::npos)
        << r.output;
}

// A value that is not a number, or not one of a set, says what was expected (CLI11 said
// "Could not convert: --fov = abc", "--samples: abc", "Value abc not in range 0 to 6").
TEST(Cli, AValueOfTheWrongKindSaysWhatWasExpected) {
    const std::string model = quote(test::data_dir() / "models/spot/spot.glb");
    const std::string out = quote(test::temp_dir());
    for (const auto& [args, message] :
         {std::pair{"render " + model + " -o " + out + " --fov abc", std::string("--fov: expected a number, got \"abc\"")},
          std::pair{"render " + model + " -o " + out + " --samples abc", std::string("--samples: expected one of {1,4,8}, got \"abc\"")},
          std::pair{"render " + model + " -o " + out + " --samples 3", std::string("--samples: expected one of {1,4,8}, got \"3\"")},
          std::pair{"render " + model + " -o " + out + " --shading glossy",
                    std::string("--shading: expected one of {flat,toon,unlit,none}, got \"glossy\"")},
          std::pair{std::string("slam x.png -o y.exr --levels abc"), std::string("--levels: expected a number from 2 to 256, got \"abc\"")}}) {
        const auto r = run_linework(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("linework: error: " + message), std::string::npos) << args << "\n" << r.output;
    }
}

TEST(Cli, HelpExplainsRender) {
    const auto r = run_linework("render --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--device", "--size", "--eye", "--target", "--fov", "--exr", "--shading"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
}

TEST(Cli, MissingInputNamesTheFile) {
    const auto r = run_linework("render /nonexistent/scene.json -o " + quote(test::temp_dir()));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("/nonexistent/scene.json: no such file"), std::string::npos) << r.output;
}

TEST(Cli, BadSceneKeyIsNamed) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "bad.json") << R"({"model": "m.glb", "camera": {"eye": [0,0,3], "target": [0,0,0], "fovv": 30}})";
    const auto r = run_linework("render " + quote(dir / "bad.json") + " -o " + quote(dir / "out"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("bad.json: camera.fovv: unknown key"), std::string::npos) << r.output;
}

// A model with clips rendered over several frames from the command line draws its rest pose
// in each (only a scene's "animation" plays clips): a warning says so, naming the clips. One
// frame, or a model without clips, says nothing.
TEST(Cli, FramesOfAModelWithClipsSayTheClipsAreNotPlayed) {
    const fs::path dir = test::temp_dir();
    const std::string fox = quote(test::data_dir() / "models/Fox/Fox.glb");
    auto r = run_linework("render " + fox + " --size 64x48 --device cpu --frames 0:1 -o " + quote(dir / "a"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: " + (test::data_dir() / "models/Fox/Fox.glb").string() +
                            ": its animation clips are not played (clips: 0 \"Survey\", 1 \"Walk\", 2 \"Run\"): every "
                            "frame draws the rest pose; a scene file's \"animation\" key plays them"),
              std::string::npos)
        << r.output;
    for (const std::string& other : {fox + " --frames 0:0", quote(test::data_dir() / "models/spot/spot.glb") + " --frames 0:1"}) {
        r = run_linework("render " + other + " --size 64x48 --device cpu -o " + quote(dir / "b"));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << other << ": " << r.output;
    }
}

// A transparent render composited over a colour is the render over that colour: the frame
// is premultiplied `over` nothing, the PNG straight alpha (within 2/255 for the rounding).
TEST(Cli, TransparentBackgroundCompositesToTheOpaqueRender) {
    const fs::path dir = test::temp_dir(), model = test::data_dir() / "models/spot/spot.glb";
    const std::string common = " --device cpu --size 160x120 --validation";
    const auto t = run_linework("render " + quote(model) + " -o " + quote(dir / "t") + common + " --background transparent");
    ASSERT_EQ(t.exit_code, 0) << t.output;
    const auto c = run_linework("render " + quote(model) + " -o " + quote(dir / "c") + common + " --background '#3380cc'");
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const ImageRGBA8 clear = read_image_rgba8(dir / "t/frame_0000.png"), over = read_image_rgba8(dir / "c/frame_0000.png");
    ASSERT_EQ(clear.pixels.size(), over.pixels.size());
    EXPECT_EQ(clear.pixels[3], 0) << "the corner is background";
    const int plate[3] = {0x33, 0x80, 0xcc};
    int worst = 0, inked = 0;
    for (size_t i = 0; i < clear.pixels.size(); i += 4) {
        const int a = clear.pixels[i + 3];
        inked += a > 0;
        for (size_t k = 0; k < 3; ++k) {
            const double composited = (clear.pixels[i + k] * a + plate[k] * (255 - a)) / 255.0;
            worst = std::max(worst, int(std::lround(std::abs(composited - over.pixels[i + k]))));
        }
    }
    EXPECT_GT(inked, 1000);
    EXPECT_LE(worst, 2);
}

TEST(Cli, DevicesSaysWhichOneAutoTakes) {
    const auto r = run_linework("devices");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("<- --device auto"), std::string::npos) << r.output;
    const size_t line = r.output.find("--device auto takes [");
    ASSERT_NE(line, std::string::npos) << r.output;
    // The index it names is the row marked.
    const int index = std::stoi(r.output.substr(line + std::string("--device auto takes [").size()));
    const size_t row = r.output.find("[" + std::to_string(index) + "] ");
    ASSERT_NE(row, std::string::npos);
    EXPECT_NE(r.output.substr(row, r.output.find('\n', row) - row).find("<- --device auto"), std::string::npos) << r.output;
}

TEST(Cli, GpuDeviceWithoutGpuFails) {
    const auto devices = run_linework("devices");
    ASSERT_EQ(devices.exit_code, 0) << devices.output;
    if (devices.output.find("gpu,") != std::string::npos) GTEST_SKIP() << "this machine has a GPU";
    const auto r = run_linework("render " + quote(test::data_dir() / "models/spot/spot.glb") + " -o " +
                                quote(test::temp_dir()) + " --device gpu");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("--device gpu: no GPU Vulkan device found"), std::string::npos) << r.output;
}

TEST(Cli, DiffReportsIdenticalImages) {
    const fs::path png = test::source_dir() / "tests/golden/suzanne_toon.png";
    const auto r = run_linework("diff " + quote(png) + " " + quote(png));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("max abs error: 0"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("psnr: inf dB"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace lw
