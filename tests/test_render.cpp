// Headless renders on lavapipe: every shipped model renders, its silhouette matches the
// CPU coverage reference, and two golden images stay stable.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <cstdlib>
#include <filesystem>

#include "coherence/coherence.h"
#include "core/error.h"
#include "core/image.h"
#include "io/image_io.h"
#include "render/coverage_reference.h"
#include "render/frame_renderer.h"
#include "render/surface_pass.h"
#include "scene/scene.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

struct RenderedFrame {
    LoadedScene scene;
    CameraMatrices camera;
    FrameReadback frame;
};

// One sample per pixel: these tests check exact pixel sets (tests/test_antialiasing.cpp
// checks multisampling).
RenderedFrame render(Context& ctx, const fs::path& model, int width, int height, Shading shading = Shading::Toon) {
    SceneDesc desc = scene_for_model(model);
    desc.width = width;
    desc.height = height;
    desc.style.shading = shading;
    desc.style.samples = 1;
    RenderedFrame r{.scene = load_scene(desc)};
    r.camera = camera_matrices(r.scene.camera, float(width) / float(height), r.scene.bounds);
    FrameRenderer renderer(ctx, uint32_t(width), uint32_t(height));
    renderer.set_mesh(r.scene.mesh, false, 0.0f);
    desc.lines.enabled = false;
    r.frame = renderer.render(r.camera, r.scene.camera.eye, desc.style, desc.lines, {.color = true, .depth = true}).image;
    return r;
}

// Every model file shipped in tests/data/models (copies of ../shared/models).
std::vector<std::string> model_files() {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(test::data_dir() / "models")) {
        const auto ext = entry.path().extension();
        if (ext == ".glb" || ext == ".gltf") files.push_back(fs::relative(entry.path(), test::data_dir() / "models").string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

class RenderTest : public test::GpuTest {};

class ModelRender : public test::GpuTest, public ::testing::WithParamInterface<std::string> {};

// The rendered silhouette (pixels with depth < 1) must agree with the CPU rasterization of
// the same triangles: same area within 1 % of the image's silhouette and IoU ≥ 0.98.
TEST_P(ModelRender, SilhouetteMatchesCpuCoverage) {
    const int width = 320, height = 240;
    const RenderedFrame r = render(ctx(), test::data_dir() / "models" / GetParam(), width, height);
    const auto reference = coverage_reference(r.scene.mesh, r.camera, width, height);

    size_t gpu = 0, cpu = 0, both = 0, non_background = 0;
    for (size_t i = 0; i < reference.size(); ++i) {
        const bool g = r.frame.depth[i] < 1.0f;
        gpu += g;
        cpu += reference[i];
        both += g && reference[i];
        const uint8_t* px = &r.frame.color.pixels[4 * i];
        non_background += !(px[0] == 255 && px[1] == 255 && px[2] == 255);
    }
    const size_t either = gpu + cpu - both;
    const double coverage = double(gpu) / double(reference.size());
    EXPECT_GT(coverage, 0.01) << "the framed model should cover a real share of the image";
    EXPECT_LT(coverage, 0.95) << "the framed model should not fill the whole image";
    EXPECT_EQ(non_background, gpu) << "shaded pixels must be exactly the covered ones (image is not blank)";
    EXPECT_NEAR(double(gpu), double(cpu), 0.01 * double(cpu) + 4.0);
    EXPECT_GE(double(both) / double(either), 0.98) << "gpu " << gpu << " cpu " << cpu << " both " << both;
}

INSTANTIATE_TEST_SUITE_P(AllModels, ModelRender, ::testing::ValuesIn(model_files()),
                         [](const auto& param_info) {
                             std::string name = param_info.param;
                             for (auto& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

TEST_F(RenderTest, DepthIsOrderedFrontToBack) {
    // A sphere-like model seen from outside: the centre pixel is nearer than the rim pixels.
    const RenderedFrame r = render(ctx(), test::data_dir() / "models/spot/spot.glb", 200, 200);
    float min_depth = 1.0f, max_covered = 0.0f;
    for (float d : r.frame.depth)
        if (d < 1.0f) {
            min_depth = std::min(min_depth, d);
            max_covered = std::max(max_covered, d);
            EXPECT_GE(d, 0.0f);
        }
    EXPECT_LT(min_depth, max_covered) << "depth should vary over the surface";
}

TEST_F(RenderTest, ShadingModesDiffer) {
    const fs::path model = test::data_dir() / "models/Suzanne/Monkey.glb";
    const auto toon = render(ctx(), model, 160, 120, Shading::Toon).frame.color;
    const auto flat = render(ctx(), model, 160, 120, Shading::Flat).frame.color;
    const auto unlit = render(ctx(), model, 160, 120, Shading::Unlit).frame.color;
    EXPECT_GT(compare_images(toon, flat).max_abs_error, 20);
    // Unlit is one flat colour: at most two distinct values per channel (surface, background).
    std::set<uint8_t> reds;
    for (size_t i = 0; i < unlit.pixels.size(); i += 4) reds.insert(unlit.pixels[i]);
    EXPECT_LE(reds.size(), 2u);
    // Toon has three bands of the base colour plus the background; only the one-pixel ramps
    // between bands (their antialiasing) hold other values.
    std::map<uint8_t, size_t> toon_reds;
    for (size_t i = 0; i < toon.pixels.size(); i += 4) ++toon_reds[toon.pixels[i]];
    std::vector<size_t> counts;
    for (const auto& [red, count] : toon_reds) counts.push_back(count);
    std::sort(counts.rbegin(), counts.rend());
    ASSERT_GE(counts.size(), 4u);
    const size_t on_bands = counts[0] + counts[1] + counts[2] + counts[3];
    EXPECT_GE(double(on_bands), 0.9 * double(toon.pixels.size() / 4)) << "bands and background";  // measured 0.96 (160×120)
    EXPECT_GT(toon_reds.size(), 4u) << "band edges ramp";
}

// On CPU devices the frame extracts lines on the host (ComputeSite); the device path — the
// extraction in the surface pass's submission, its readback — must give the same frame.
TEST_F(RenderTest, DeviceAndHostExtractionGiveTheSameFrame) {
    Context device_ctx({.device = {DeviceChoice::Kind::Cpu}, .validation = true, .compute_site = ComputeSite::Device});
    ASSERT_EQ(ctx().preferred_compute_site(), ComputeSite::Host);  // lavapipe
    SceneDesc desc = scene_for_model(test::data_dir() / "models/spot/spot.glb");
    const LoadedScene scene = load_scene(desc);
    const CameraMatrices camera = camera_matrices(scene.camera, 4.0f / 3.0f, scene.bounds);
    const CoherenceParams coherence;
    std::vector<Frame> frames;
    for (Context* c : {&ctx(), &device_ctx}) {
        FrameRenderer renderer(*c, 320, 240);
        renderer.set_mesh(scene.mesh, true, desc.lines.params.crease_angle_deg);
        (void)renderer.render(camera, scene.camera.eye, desc.style, desc.lines, {}, &coherence);
        frames.push_back(renderer.render(camera, scene.camera.eye, desc.style, desc.lines, {}, &coherence));
    }
    EXPECT_GT(frames[0].timings.extract_ms, 0.0);
    EXPECT_EQ(frames[1].timings.extract_ms, 0.0);
    ASSERT_GT(frames[0].segments.size(), 100u);
    EXPECT_EQ(frames[0].segments.size(), frames[1].segments.size());
    EXPECT_EQ(frames[0].paths.size(), frames[1].paths.size());
    const ImageDiff diff = compare_images(frames[0].image.color, frames[1].image.color);
    EXPECT_GE(diff.psnr_db, 40.0) << "max error " << diff.max_abs_error;
    const auto messages = device_ctx.validation_messages();
    EXPECT_TRUE(messages.empty()) << messages.front();
}

// The viewer renders into its swapchain's format (B8G8R8A8) to copy rather than blit; the
// frame must be the same, and the colour read back RGBA all the same.
TEST_F(RenderTest, BgraTargetGivesTheSameFrame) {
    SceneDesc desc = scene_for_model(test::data_dir() / "models/spot/spot.glb");
    const LoadedScene scene = load_scene(desc);
    const CameraMatrices camera = camera_matrices(scene.camera, 4.0f / 3.0f, scene.bounds);
    std::vector<ImageRGBA8> images;
    for (VkFormat format : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM}) {
        FrameRenderer renderer(ctx(), 320, 240, format);
        renderer.set_mesh(scene.mesh, true, desc.lines.params.crease_angle_deg);
        images.push_back(renderer.render(camera, scene.camera.eye, desc.style, desc.lines).image.color);
    }
    const ImageDiff diff = compare_images(images[0], images[1]);
    EXPECT_EQ(diff.max_abs_error, 0) << diff.psnr_db;
}

// Golden images: regenerate with
//   LINEWORK_UPDATE_GOLDENS=1 ctest --test-dir build -R Golden
// Tolerance: PSNR ≥ 40 dB and at most 0.5 % of pixels off by more than 16 levels — room for
// LLVM code generation on another CPU, none for a changed camera, shading, mesh or line.
struct GoldenCase {
    std::string model;
    std::string golden;
    bool lines;
    bool surface;
};

class Golden : public test::GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(Golden, RenderMatchesGolden) {
    const GoldenCase& c = GetParam();
    SceneDesc desc = scene_for_model(test::data_dir() / "models" / c.model);
    desc.width = 320;
    desc.height = 240;
    desc.style.draw_surface = c.surface;
    desc.lines.enabled = c.lines;
    const LoadedScene scene = load_scene(desc);
    const CameraMatrices camera = camera_matrices(scene.camera, 320.0f / 240.0f, scene.bounds);
    FrameRenderer renderer(ctx(), 320, 240);
    renderer.set_mesh(scene.mesh, c.lines, desc.lines.params.crease_angle_deg);
    const ImageRGBA8 image = renderer.render(camera, scene.camera.eye, desc.style, desc.lines).image.color;

    const fs::path golden = test::source_dir() / "tests/golden" / c.golden;
    if (const char* update = std::getenv("LINEWORK_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        write_png(golden, image);
        GTEST_SKIP() << "updated " << golden;
    }
    const ImageRGBA8 expected = read_image_rgba8(golden);
    const ImageDiff d = compare_images(image, expected, 16);
    EXPECT_GE(d.psnr_db, 40.0);
    EXPECT_LE(d.differing_fraction, 0.005);
    if (d.psnr_db < 40.0 || d.differing_fraction > 0.005) {
        const fs::path out = test::temp_dir();
        write_png(out / "actual.png", image);
        write_png(out / "diff.png", d.diff);
        ADD_FAILURE() << "actual and diff written to " << out;
    }
}

INSTANTIATE_TEST_SUITE_P(Models, Golden,
                         ::testing::Values(GoldenCase{"spot/spot.glb", "spot_toon_lines.png", true, true},
                                           GoldenCase{"LeePerrySmith/LeePerrySmith.glb", "lee_lines_only.png", true, false},
                                           GoldenCase{"Suzanne/Monkey.glb", "suzanne_toon.png", false, true}),
                         [](const auto& param_info) { return fs::path(param_info.param.golden).stem().string(); });

// The README's first render shows what Linework is for (issue 17 item 7): SLAM strokes on
// the silhouettes and suggestive contours, suggestive contours actually drawn, antialiased
// (the default samples), a camera that moves so that coherence has something to hold.
using test::GpuTest;

TEST_F(GpuTest, DefaultSceneShowsSlamStrokesAndSuggestiveContours) {
    SceneDesc desc = load_scene_file(test::source_dir() / "scenes/default.json");
    EXPECT_FALSE(desc.description.empty());
    EXPECT_FALSE(desc.lines.styles[size_t(LineType::Silhouette)].slam.empty());
    EXPECT_FALSE(desc.lines.styles[size_t(LineType::Suggestive)].slam.empty());
    EXPECT_EQ(surface_samples(desc.style), 4u);
    EXPECT_EQ(desc.camera_path.kind, CameraPath::Kind::Orbit);
    desc.width = 320, desc.height = 240;
    SceneSession session(ctx(), desc);
    const Frame frame = session.frame({});
    std::map<std::string, size_t> paths;
    for (const LineSetFrame& set : frame.sets) paths[set.name] = set.paths.size();
    EXPECT_GE(paths["silhouette"], 5u);
    EXPECT_GE(paths["suggestive"], 10u) << "a face: eyelids, nose, mouth, cheeks";
    size_t partial = 0;  // antialiased stroke edges: neither paper nor full ink
    for (size_t i = 0; i < frame.image.color.pixels.size(); i += 4)
        if (frame.image.color.pixels[i] > 40 && frame.image.color.pixels[i] < 200) ++partial;
    EXPECT_GT(partial, 500u);
}

// Frames in flight (begin the next, then finish the last: what the viewer does on a GPU)
// give the frames drawn one at a time, bit for bit: a skinned model posed anew between a
// frame's begin and its finish (its votes carry samples from its own pose), SLAM strokes
// parameterized from frame to frame, the camera turning.
TEST_F(GpuTest, FramesInFlightEqualFramesDrawnOneAtATime) {
    SceneDesc desc = parse_scene_json(R"({"model": "Fox/Fox.glb", "size": [160, 120], "samples": 1,
        "animation": {"clip": 1}, "lines": {"silhouette": {"slam": "../../../scenes/slams/dots.exr"}},
        "camera": {"orbit": 30}})",
                                      test::data_dir() / "models/fox.json");
    const auto request = [](int f) {
        return FrameRequest{.when = {.progress = float(f) / 5.0f, .seconds = float(f) / 24.0f}};
    };
    std::vector<Frame> one_by_one, overlapped;
    {
        SceneSession session(ctx(), desc);
        for (int f = 0; f < 6; ++f) one_by_one.push_back(session.frame(request(f)));
    }
    {
        SceneSession session(ctx(), desc);
        session.begin_frame(request(0));
        for (int f = 1; f < 6; ++f) {
            session.begin_frame(request(f));
            EXPECT_EQ(session.frames_in_flight(), 2u);
            overlapped.push_back(session.finish_frame());
        }
        overlapped.push_back(session.finish_frame());
        EXPECT_THROW((void)session.finish_frame(), Error);
    }
    size_t strokes = 0;
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ(overlapped[size_t(f)].image.color.pixels, one_by_one[size_t(f)].image.color.pixels) << "frame " << f;
        ASSERT_EQ(overlapped[size_t(f)].sets.size(), one_by_one[size_t(f)].sets.size());
        for (size_t s = 0; s < one_by_one[size_t(f)].sets.size(); ++s) {
            const auto& a = overlapped[size_t(f)].sets[s].params;
            const auto& b = one_by_one[size_t(f)].sets[s].params;
            ASSERT_EQ(a.size(), b.size()) << "frame " << f;
            for (size_t p = 0; p < a.size(); ++p) {
                EXPECT_EQ(a[p].rho, b[p].rho) << "frame " << f << " path " << p;
                EXPECT_EQ(a[p].phi, b[p].phi) << "frame " << f << " path " << p;
                strokes += a[p].fitted;
            }
        }
    }
    EXPECT_GT(strokes, 10u) << "paths fitted from the frame before";
}

}  // namespace
}  // namespace lw
