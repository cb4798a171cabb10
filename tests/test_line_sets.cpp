// tests/test_line_sets.cpp — line sets and the scene session: each set keeps its own texture
// period, dashes follow the parameterization, `render` and the viewer's code path give the
// same frame, and a bad "line_sets" key is an error naming it.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "coherence/path_dump.h"
#include "core/error.h"
#include "scene/scene_file.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "render/line_sets.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A scene over the shared spot with the given "line_sets" JSON, 320×240, an orbit of
// `degrees` over `frames` frames.
fs::path spot_scene(const fs::path& dir, const std::string& line_sets, int frames, float degrees) {
    const fs::path scene = dir / "scene.json";
    write_file(scene, "{\"model\": \"" + (test::data_dir() / "models/spot/spot.glb").string() +
                          "\", \"size\": [320, 240], \"camera\": {\"orbit\": " + std::to_string(degrees) +
                          "}, \"animation\": {\"frames\": [0, " + std::to_string(frames - 1) +
                          "]}, \"line_sets\": " + line_sets + "}");
    return scene;
}

// `linework render SCENE --dump-paths` into `dir`; the dumps in frame order (none, and a
// failure, when the render fails).
std::vector<PathDump> render_dumps(const fs::path& scene, const fs::path& dir) {
    const test::CommandResult r = test::run_linework("render '" + scene.string() + "' -o '" + (dir / "out").string() +
                                                     "' --dump-paths '" + (dir / "dump").string() + "' --device cpu");
    std::vector<PathDump> dumps;
    if (r.exit_code != 0) {
        ADD_FAILURE() << r.output;
        return dumps;
    }
    for (int f = 0;; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.json", f);
        if (!fs::exists(dir / "dump" / name)) break;
        dumps.push_back(read_path_dump(dir / "dump" / name));
    }
    return dumps;
}

// Two sets with SLAMs of different lengths (512 and 1024 texels, same height and width, so
// κ is the same): each set's on-screen period stays in its own factor-of-2 band,
// (0.5, 1] · Lmax / κ. With one set of coherence parameters for all (the per-type loop that
// left the last SLAM's length for every type) one of them would sit an octave off.
TEST(LineSets, EachSetKeepsItsOwnTexturePeriod) {
    const fs::path dir = test::temp_dir();
    write_slam(dir / "short.exr", make_procedural_slam(SlamPattern::Dots, 9, 512, 16, 1));
    write_slam(dir / "long.exr", make_procedural_slam(SlamPattern::Dots, 9, 1024, 16, 2));
    const fs::path scene = spot_scene(
        dir,
        "[{\"name\": \"outline\", \"select\": {\"types\": [\"silhouette\"]}, "
        "\"style\": {\"width\": 4, \"slam\": \"" + (dir / "short.exr").string() + "\"}},"
        " {\"name\": \"inner\", \"select\": {\"types\": [\"suggestive\", \"crease\"]}, "
        "\"style\": {\"width\": 4, \"slam\": \"" + (dir / "long.exr").string() + "\"}}]",
        24, 72.0f);
    const std::vector<PathDump> dumps = render_dumps(scene, dir);
    ASSERT_EQ(dumps.size(), 24u);
    const float kappa = 16.0f / 4.0f;  // square texels: the SLAM's height over the width
    for (const auto& [set, length] : {std::pair{"outline", 512.0f}, std::pair{"inner", 1024.0f}}) {
        const StretchMeasure m = measure_stretch(paths_of_line_set(dumps, set));
        ASSERT_GT(m.samples, 500u) << set;
        const double period = length / kappa;
        EXPECT_GE(m.share_in_band, 0.99) << set;
        // Pixels per period lie in (0.5, 1]·Lmax/κ: at 1/√2 of it for an orbit, whose zoom
        // does not change the set's scale (a SLAM set starts mid-way between level changes);
        // the other set's band starts an octave away.
        EXPECT_GT(m.band_low, 0.5 * period) << set;
        EXPECT_LT(m.band_low, 0.75 * period) << set;
        EXPECT_GT(m.median_ds_du, 0.5 * period) << set;
        EXPECT_LE(m.median_ds_du, 1.0 * period + 1.0) << set;
    }
}

// Dashes are laid along the coherent parameter: over an orbit they slide no more than SLAM
// strokes on the same lines (the same tracker carries both), and in a still first frame a
// straight run's dashes have the given lengths (the dash set starts at the tiling scale).
TEST(LineSets, DashesFollowTheParameterization) {
    const fs::path dir = test::temp_dir();
    write_slam(dir / "slam.exr", make_procedural_slam(SlamPattern::Dots, 9, 256, 16, 1));
    const fs::path scene = spot_scene(
        dir,
        "[{\"name\": \"dashed\", \"select\": {\"types\": [\"silhouette\"]}, "
        "\"style\": {\"width\": 3, \"dashes\": [12, 6], \"cap\": \"butt\"}},"
        " {\"name\": \"slam\", \"select\": {\"types\": [\"silhouette\"]}, "
        "\"style\": {\"width\": 4, \"slam\": \"" + (dir / "slam.exr").string() + "\"}}]",
        24, 72.0f);
    const std::vector<PathDump> dumps = render_dumps(scene, dir);
    ASSERT_EQ(dumps.size(), 24u);
    const SlidingMeasure dashed = measure_sliding(paths_of_line_set(dumps, "dashed"));
    const SlidingMeasure slam = measure_sliding(paths_of_line_set(dumps, "slam"));
    ASSERT_GT(dashed.pairs, 1000u);
    // |Δt| in periods of each set's own texture length: compare in pixels along the path.
    const double dashed_px = dashed.median_dt * 1024.0;      // no SLAM: T counts 1024-px lengths (κ 1)
    const double slam_px = slam.median_dt * 256.0 / 4.0;      // Lmax / κ
    EXPECT_LE(dashed_px, 1.25 * slam_px + 0.05) << "dashed " << dashed_px << " px, SLAM " << slam_px << " px";
    // Frame 0: every dashed path starts at the tiling scale, T = s / 1024.
    const std::vector<PathDump> first = paths_of_line_set({dumps.front()}, "dashed");
    ASSERT_FALSE(first.front().paths.empty());
    for (const DumpPath& path : first.front().paths) EXPECT_NEAR(path.rho, 1.0f / 1024.0f, 1e-7f);
}

// A plain set is drawn from its own paths whatever the other sets are: a dashed set beside it
// (which the tracker parameterizes) leaves it as it is, frame after frame of an orbit. When
// every set was fitted as soon as one needed it, spot's outline came out in 8 pieces at frame
// 0 beside a dashed set and in 22 beside a plain one, and other counts every frame.
TEST(LineSets, APlainSetIsTheSameBesideADashedSet) {
    const fs::path dir = test::temp_dir();
    std::vector<std::string> outlines[2];
    for (int dashed = 0; dashed < 2; ++dashed) {
        const fs::path run = dir / (dashed ? "dashed" : "plain");
        fs::create_directories(run);
        const fs::path scene = spot_scene(
            run,
            std::string("[{\"name\": \"outline\", \"select\": {\"types\": [\"silhouette\", \"crease\", \"border\"]}},"
                        " {\"name\": \"inner\", \"select\": {\"types\": [\"suggestive\"]}, \"style\": ") +
                (dashed ? "{\"dashes\": [6, 4]}}]" : "{\"width\": 1.5}}]"),
            4, 20.0f);
        const test::CommandResult r = test::run_linework("render '" + scene.string() + "' -o '" + (run / "out").string() +
                                                         "' --svg '" + (run / "l.svg").string() + "' --device cpu");
        ASSERT_EQ(r.exit_code, 0) << r.output;
        for (int f = 0; f < 4; ++f) {
            char name[32];
            std::snprintf(name, sizeof name, "l_%04d.svg", f);
            std::ifstream in(run / name);
            const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const size_t from = svg.find("<g id=\"outline-centerlines\""), to = svg.find("</g>", from);
            ASSERT_NE(from, std::string::npos) << name;
            outlines[dashed].push_back(svg.substr(from, to - from));
        }
    }
    for (int f = 0; f < 4; ++f) {
        EXPECT_NE(outlines[0][size_t(f)].find("<polyline"), std::string::npos) << "frame " << f;
        EXPECT_TRUE(outlines[0][size_t(f)] == outlines[1][size_t(f)]) << "frame " << f;
    }
}

// One frame of a scene through the render command's path (RGBA target, the scene's camera at
// the frame's time) and through the viewer's (the swapchain's BGRA format, the camera given
// per frame, ribbons written back to the target) is the same image.
TEST(LineSets, RenderAndViewerPathsGiveTheSameFrame) {
    const fs::path dir = test::temp_dir();
    write_slam(dir / "slam.exr", make_procedural_slam(SlamPattern::Pencil, 9, 256, 16, 3));
    const fs::path scene = spot_scene(
        dir,
        "[{\"name\": \"outline\", \"select\": {\"types\": [\"silhouette\", \"border\"]}, "
        "\"style\": {\"width\": 5, \"slam\": \"" + (dir / "slam.exr").string() + "\", \"taper\": 8}},"
        " {\"name\": \"sugg\", \"select\": {\"types\": [\"suggestive\"]}, \"style\": {\"width\": 2, \"cap\": "
        "\"round\", \"dashes\": [6, 4], \"color\": [0.2, 0.2, 0.6]}},"
        " {\"name\": \"hidden\", \"select\": {\"visibility\": \"hidden\", \"types\": [\"silhouette\"]}, "
        "\"style\": {\"width\": 1, \"alpha\": 0.3}}]",
        1, 0.0f);
    const test::CommandResult r =
        test::run_linework("render '" + scene.string() + "' -o '" + (dir / "out").string() + "' --device cpu");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const ImageRGBA8 rendered = read_image_rgba8(dir / "out/frame_0000.png");

    Context ctx({.device = {DeviceChoice::Kind::Cpu}, .validation = true});
    {
        SceneSession session(ctx, load_scene_file(scene), {.color_format = VK_FORMAT_B8G8R8A8_UNORM});
        const Frame frame = session.frame({.camera = session.scene().camera, .outputs = {.color = true},
                                           .ribbons_to_target = true});
        const ImageDiff d = compare_images(frame.image.color, rendered);
        EXPECT_EQ(d.max_abs_error, 0) << d.psnr_db;
        ASSERT_EQ(frame.sets.size(), 3u);
        EXPECT_EQ(frame.sets[2].name, "hidden");
        for (const ScreenPath& p : frame.sets[2].paths) EXPECT_FALSE(p.visible);
    }
    EXPECT_TRUE(ctx.validation_messages().empty());
}

TEST(LineSets, ShorthandIsOneSetPerType) {
    LinesDesc lines;
    lines.params.creases = false;
    lines.styles[1].slam = "x.exr";
    const std::vector<LineSetDesc> sets = effective_line_sets(lines);
    ASSERT_EQ(sets.size(), size_t(kLineTypeCount));
    for (int t = 0; t < kLineTypeCount; ++t) {
        EXPECT_EQ(sets[size_t(t)].name, line_type_name(LineType(t)));
        EXPECT_EQ(sets[size_t(t)].select.types, 1u << t);
    }
    EXPECT_FALSE(sets[2].enabled);
    EXPECT_EQ(sets[1].style.slam, "x.exr");
    EXPECT_EQ(sets[1].style.cap, Cap::Butt);
    EXPECT_FALSE(extraction_params(lines, sets).creases);
}

TEST(LineSets, BadKeysNameThemselves) {
    const std::pair<const char*, const char*> cases[] = {
        {R"([{"select": {}}])", "line_sets[0].name: required"},
        {R"([{"name": "a b"}])", "line_sets[0].name: letters, digits"},
        {R"([{"name": "a"}, {"name": "a"}])", "line_sets[1].name: \"a\" is used by an earlier set"},
        {R"([{"name": "a", "select": {"types": ["outline"]}}])", "line_sets[0].select.types: unknown line type \"outline\""},
        {R"([{"name": "a", "style": {"dashes": [0, 0]}}])", "line_sets[0].style.dashes: the pattern has no length"},
        {R"([{"name": "a", "style": {"cap": "pointy"}}])", "line_sets[0].style.cap: must be one of"},
        {R"([{"name": "a", "style": {"width_modifiers": [{"input": "along"}]}}])",
         "line_sets[0].style.width_modifiers[0].ramp: required"},
        {R"([{"name": "a", "style": {"geometry": [{"kind": "wobble"}]}}])", "line_sets[0].style.geometry[0].kind:"},
        {R"([{"name": "a", "coherence": {"policy": "x"}}])", "line_sets[0].coherence.policy: must be one of"},
        {R"([{"name": "a", "colour": 1}])", "line_sets[0].colour: unknown key"},
        // Settings that drew nothing, or changed nothing, in silence.
        {R"([{"name": "a", "style": {"width_modifiers": [{"input": "distance", "ramp": [[0, 1], [1, 0]]}]}}])",
         "line_sets[0].style.width_modifiers[0].range: required for distance: [near, far]"},
        {R"([{"name": "a", "style": {"color_modifiers": [{"input": "curvature", "ramp": [[0, [1, 0, 0]]]}]}}])",
         "line_sets[0].style.color_modifiers[0].range: required for curvature"},
        {R"([{"name": "a", "style": {"alpha_modifiers": [{"input": "along", "range": [0, 2], "ramp": [[0, 1]]}]}}])",
         "line_sets[0].style.alpha_modifiers[0].range: along runs from 0"},
        {R"([{"name": "a", "style": {"width_modifiers": [{"input": "along", "ramp": [[0, -1], [1, -1]]}]}}])",
         "line_sets[0].style.width_modifiers[0].ramp: widths are 0 or more, got -1"},
        {R"([{"name": "a", "style": {"alpha_modifiers": [{"input": "along", "blend": "replace", "ramp": [[0, 2]]}]}}])",
         "line_sets[0].style.alpha_modifiers[0].ramp: an alpha that replaces is in [0, 1], got 2"},
        {R"([{"name": "a", "style": {"alpha": 0}}])",
         "line_sets[0].style.alpha: 0 and no alpha_modifiers: the set would draw nothing"},
        {R"([{"name": "a", "select": {"visibility": "any"}, "style": {"ribbon": "chain.png"}}])",
         "line_sets[0].select: a ribbon set draws visible lines only"},
        {R"([{"name": "a", "select": {"qi": [1, 3]}, "style": {"ribbon": "chain.png"}}])",
         "line_sets[0].select: a ribbon set draws visible lines only"},
        {R"([{"name": "a", "style": {"color_modifiers": [{"input": "along", "influence": 0, "ramp": [[0, [1, 0, 0]]]}]}}])",
         "line_sets[0].style.color_modifiers[0].influence: 0: the modifier would change nothing"},
        {R"([{"name": "a", "style": {"geometry": [{"kind": "tip_remove", "length": 3, "wavelength": 40}]}}])",
         "line_sets[0].style.geometry[0].wavelength: is not a key of tip_remove (its keys: length)"},
        {R"([{"name": "a", "style": {"geometry": [{"kind": "simplify", "seed": 3}]}}])",
         "line_sets[0].style.geometry[0].seed: is not a key of simplify (its keys: tolerance)"},
    };
    // What is still taken: a fade-in from alpha 0, an alpha scaled up by multiply, and what
    // views saved before these rules wrote (a [0, 1] range on along, another geometry kind's
    // keys at their defaults).
    for (const char* json :
         {R"([{"name": "a", "style": {"alpha": 0, "alpha_modifiers": [{"input": "along", "blend": "add", "ramp": [[0, 0], [1, 1]]}]}}])",
          R"([{"name": "a", "style": {"alpha": 0.4, "alpha_modifiers": [{"input": "along", "ramp": [[0, 2.5]]}]}}])",
          R"([{"name": "a", "style": {"width_modifiers": [{"input": "along", "range": [0, 1], "ramp": [[0, 1]]}]}}])",
          R"([{"name": "a", "style": {"geometry": [{"kind": "tip_remove", "length": 3, "wavelength": 32, "amplitude": 2,
                                                    "phase": 0, "seed": 1, "tolerance": 1}]}}])"})
        EXPECT_NO_THROW((void)parse_scene_json(std::string("{\"model\": \"m.glb\", \"line_sets\": ") + json + "}", "s.json"))
            << json;
    for (const auto& [json, message] : cases) {
        try {
            (void)parse_scene_json(std::string("{\"model\": \"m.glb\", \"line_sets\": ") + json + "}", "s.json");
            ADD_FAILURE() << json << ": no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("s.json: ") + message), std::string::npos)
                << json << " gave: " << e.what();
        }
    }
}

TEST(LineSets, SelectByMaterialAndModel) {
    // The milk truck has several materials; a set that selects one sees only its faces, one
    // that names a model or material the scene lacks is refused (it would select nothing).
    SceneDesc desc = scene_for_model(test::data_dir() / "models/CesiumMilkTruck/CesiumMilkTruck.glb");
    desc.width = 320;
    desc.height = 240;
    const LoadedScene probe = load_scene(desc);
    ASSERT_GE(probe.models[0].materials.size(), 2u);
    const std::string material = probe.models[0].materials[0].name;
    desc.lines.sets = {LineSetDesc{.name = "all"},
                       LineSetDesc{.name = "one", .select = {.materials = {material}}},
                       LineSetDesc{.name = "truck", .select = {.models = {"CesiumMilkTruck.glb"}}}};
    Context ctx({.device = {DeviceChoice::Kind::Cpu}, .validation = true});
    {
        SceneSession session(ctx, desc);
        const Frame frame = session.frame({.outputs = {.color = false}});
        ASSERT_EQ(frame.sets.size(), 3u);
        EXPECT_GT(frame.sets[0].paths.size(), frame.sets[1].paths.size());
        EXPECT_GT(frame.sets[1].paths.size(), 0u) << material;
        EXPECT_EQ(frame.sets[2].paths.size(), frame.sets[0].paths.size());
        for (const auto& [models, materials] : {std::pair{std::vector<std::string>{"other.glb"}, std::vector<std::string>{}},
                                                std::pair{std::vector<std::string>{}, std::vector<std::string>{"Nope"}}}) {
            LinesDesc lines = desc.lines;
            lines.sets[2].select = {.models = models, .materials = materials};
            try {
                session.set_lines(lines);
                ADD_FAILURE() << "a selection of nothing: no error";
            } catch (const Error& e) {
                const std::string key = models.empty() ? "materials: \"Nope\"" : "models: \"other.glb\"";
                EXPECT_NE(std::string(e.what()).find("line_sets[2].select." + key + " is none of the scene's"),
                          std::string::npos) << e.what();
            }
        }
        EXPECT_EQ(session.frame({.outputs = {.color = false}}).sets[2].paths.size(), frame.sets[2].paths.size());
    }
    EXPECT_TRUE(ctx.validation_messages().empty());
}

// Sets select models by file name: a name two models share (each download a scene.gltf)
// would select both, so it is refused with both paths.
TEST(LineSets, AModelNameTwoModelsShareIsRefused) {
    const fs::path dir = test::temp_dir();
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    fs::copy_file(test::data_dir() / "models/spot/spot.glb", dir / "a/m.glb", fs::copy_options::overwrite_existing);
    fs::copy_file(test::data_dir() / "models/Fox/Fox.glb", dir / "b/m.glb", fs::copy_options::overwrite_existing);
    SceneDesc desc = scene_for_model(dir / "a/m.glb");
    desc.models.push_back(dir / "b/m.glb");
    desc.width = 64;
    desc.height = 48;
    desc.lines.sets = {LineSetDesc{.name = "one", .select = {.models = {"m.glb"}}}};
    Context ctx({.device = {DeviceChoice::Kind::Cpu}, .validation = true});
    try {
        SceneSession session(ctx, desc);
        ADD_FAILURE() << "an ambiguous model name: no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("line_sets[0].select.models: \"m.glb\" names more than one of the scene's models ("),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find((dir / "a/m.glb").string()), std::string::npos) << message;
        EXPECT_NE(message.find((dir / "b/m.glb").string()), std::string::npos) << message;
    }
    EXPECT_TRUE(ctx.validation_messages().empty());
}

// Keys read but changing nothing are said on stderr, once, naming the file and the keys: the
// per-type styles under "lines" beside "line_sets", and a ribbon set's stroke keys. A scene
// written back (the viewer's F5, Python's configure), which carries them at their defaults,
// says nothing.
TEST(LineSets, KeysThatChangeNothingAreSaid) {
    const fs::path dir = test::temp_dir();
    testing::internal::CaptureStderr();
    const SceneDesc desc = parse_scene_json(R"({"model": "m.glb",
        "lines": {"silhouette": {"width": 5}, "suggestive": {"threshold": 0.05}, "crease": {"enabled": false}},
        "line_sets": [{"name": "r", "style": {"ribbon": "chain.png", "alpha": 0.5, "dashes": [4, 2], "taper_in": 3,
                                              "cap": "square"}},
                      {"name": "s", "style": {"width": 3}},
                      {"name": "f", "select": {"types": ["silhouette", "crease"]}, "style": {"fade": false}}]})",
                                            dir / "in.json");
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("in.json: lines.silhouette: width; lines.crease: enabled: beside \"line_sets\" a type's "
                        "switch and style under \"lines\" change nothing"),
              std::string::npos)
        << said;
    EXPECT_EQ(said.find("lines.suggestive"), std::string::npos) << "a threshold applies beside sets: " << said;
    // The keys as written ("cap" at its default is not named).
    EXPECT_NE(said.find("in.json: line_sets[0].style: alpha, taper_in, dashes: a ribbon set draws its exemplar"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("in.json: line_sets[2]: style.fade: none of the set's types fades"), std::string::npos) << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 3) << said;

    SceneDesc plain = desc;
    plain.lines.styles = LinesDesc{}.styles;
    plain.lines.sets[0].style.alpha = 1.0f;
    plain.lines.sets[0].style.dashes.clear();
    plain.lines.sets[0].style.taper_in_px = 0.0f;
    plain.lines.sets[2].style.fade = true;
    plain.lines.params = LinesDesc{}.params;
    testing::internal::CaptureStderr();
    (void)parse_scene_json(scene_json(plain, ViewCamera{}, dir), dir / "out.json");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "a written scene reads back in silence";
}

// The viewer's "save view" writes the line sets back: reading the saved scene gives the same
// sets, every key (the viewer test renders such a file headlessly).
TEST(LineSets, SavedSceneReadsBackEveryKey) {
    const fs::path dir = test::temp_dir();
    const std::string sets = R"([{"name": "a", "enabled": false,
        "select": {"types": ["silhouette", "suggestive", "crease"], "visibility": "any", "models": ["m.glb"], "materials": ["Body"]},
        "style": {"color": [0.1, 0.2, 0.3], "alpha": 0.5, "width": 3, "cap": "round", "join": "round",
                  "taper_in": 4, "taper_out": 2, "fade": false, "dashes": [5, 2, 1],
                  "width_modifiers": [{"input": "along", "ramp": [[0, 0.5], [1, 2]], "blend": "replace"}],
                  "alpha_modifiers": [{"input": "distance", "range": [1, 9], "ramp": [[0, 1], [1, 0]]}],
                  "color_modifiers": [{"input": "curvature", "range": [0, 0.2], "ramp": [[0, [0, 0, 0]], [1, [1, 0, 0]]],
                                       "influence": 0.25}],
                  "geometry": [{"kind": "noise", "wavelength": 9, "amplitude": 1.5, "seed": 42},
                               {"kind": "tip_remove", "length": 3}],
                  "chaining": {"split_angle": 50, "min_length": 4, "max_length": 300, "outline": true}},
        "coherence": {"policy": "arclength", "length_scale": 2, "sample_spacing": 3}},
       {"name": "b", "style": {"slam": "s.exr"}}])";
    const SceneDesc desc = parse_scene_json("{\"model\": \"m.glb\", \"line_sets\": " + sets + "}", dir / "in.json");
    const SceneDesc back = parse_scene_json(scene_json(desc, ViewCamera{}, dir), dir / "out.json");
    ASSERT_EQ(back.lines.sets.size(), 2u);
    const LineSetDesc& a = back.lines.sets[0];
    const LineSetDesc& b = desc.lines.sets[0];
    EXPECT_EQ(a.name, "a");
    EXPECT_FALSE(a.enabled);
    EXPECT_EQ(a.select.types, b.select.types);
    EXPECT_EQ(a.select.visibility, Visibility::Any);
    EXPECT_EQ(a.select.models, b.select.models);
    EXPECT_EQ(a.select.materials, b.select.materials);
    EXPECT_EQ(a.style.color, b.style.color);
    EXPECT_EQ(a.style.alpha, 0.5f);
    EXPECT_EQ(a.style.cap, Cap::Round);
    EXPECT_EQ(a.style.join, Join::Round);
    EXPECT_EQ(a.style.taper_in_px, 4.0f);
    EXPECT_EQ(a.style.taper_out_px, 2.0f);
    EXPECT_FALSE(a.style.fade);
    EXPECT_EQ(a.style.dashes, b.style.dashes);
    EXPECT_TRUE(a.style.chaining.outline);
    ASSERT_EQ(a.style.width_modifiers.size(), 1u);
    EXPECT_EQ(a.style.width_modifiers[0].blend, ModifierBlend::Replace);
    EXPECT_EQ(a.style.width_modifiers[0].ramp.points, b.style.width_modifiers[0].ramp.points);
    ASSERT_EQ(a.style.alpha_modifiers.size(), 1u);
    EXPECT_EQ(a.style.alpha_modifiers[0].range_max, 9.0f);
    ASSERT_EQ(a.style.color_modifiers.size(), 1u);
    EXPECT_EQ(a.style.color_modifiers[0].influence, 0.25f);
    EXPECT_EQ(a.style.color_modifiers[0].ramp.points, b.style.color_modifiers[0].ramp.points);
    ASSERT_EQ(a.style.geometry.size(), 2u);
    EXPECT_EQ(a.style.geometry[0].kind, GeometryModifier::Kind::Noise);
    EXPECT_EQ(a.style.geometry[0].seed, 42u);
    EXPECT_EQ(a.style.geometry[1].kind, GeometryModifier::Kind::TipRemove);
    EXPECT_EQ(a.style.chaining.split_angle_deg, 50.0f);
    EXPECT_EQ(a.style.chaining.max_length_px, 300.0f);
    EXPECT_EQ(a.coherence.policy, ParamPolicy::Arclength);
    EXPECT_EQ(a.coherence.length_scale, 2.0f);
    EXPECT_EQ(a.coherence.sample_spacing_px, 3.0f);
    EXPECT_EQ(back.lines.sets[1].style.slam, desc.lines.sets[1].style.slam);
    EXPECT_EQ(back.lines.sets[1].style.cap, Cap::Butt);
    EXPECT_FALSE(back.lines.sets[1].coherence.policy.has_value());
}

}  // namespace
}  // namespace lw
