// Scene files: every key checked, errors name the file and the key path.
#include "core/error.h"
#include "scene/scene_file.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

std::string error_of(const std::string& json) {
    try {
        (void)parse_scene_json(json, "scenes/x.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SceneFile, ReadsEveryKey) {
    const SceneDesc s = parse_scene_json(R"({
        "model": "models/spot.glb", "size": [640, 480], "shading": "flat",
        "color": [0.5, 0.25, 1], "background": [0, 0, 0],
        "camera": {"eye": [1, 2, 3], "target": [0, 0.5, 0], "up": [0, 0, 1], "fov": 30, "near": 0.1, "far": 50}})",
                                         "scenes/x.json");
    ASSERT_EQ(s.models.size(), 1u);
    EXPECT_EQ(s.models[0], std::filesystem::path("scenes/models/spot.glb"));
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 480);
    EXPECT_EQ(s.style.shading, Shading::Flat);
    EXPECT_EQ(s.style.color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(s.style.background, glm::vec3(0.0f));
    ASSERT_TRUE(s.camera.has_value());
    EXPECT_EQ(s.camera->eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.camera->up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(s.camera->fov_deg, 30.0f);
    EXPECT_FLOAT_EQ(s.camera->znear, 0.1f);
}

TEST(SceneFile, DefaultsWhenLeftOut) {
    const SceneDesc s = parse_scene_json(R"({"model": ["a.glb", "/abs/b.gltf"]})", "dir/x.json");
    ASSERT_EQ(s.models.size(), 2u);
    EXPECT_EQ(s.models[0], std::filesystem::path("dir/a.glb"));
    EXPECT_EQ(s.models[1], std::filesystem::path("/abs/b.gltf"));
    EXPECT_FALSE(s.camera.has_value());
    EXPECT_EQ(s.style.shading, Shading::Toon);
    EXPECT_TRUE(s.style.draw_surface);
}

// Colours as stroke files and SVG write them are colours in scene files too.
TEST(SceneFile, ColoursMayBeStrings) {
    const SceneDesc s = parse_scene_json(
        R"j({"model": "a.glb", "background": "#ff8800", "color": "rgb(0, 255, 0)",
            "lines": {"silhouette": {"color": "#00f"}}})j", "dir/x.json");
    EXPECT_NEAR(s.style.background.r, 1.0f, 1e-6f);
    EXPECT_NEAR(s.style.background.g, 136.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(s.style.background.b, 0.0f, 1e-6f);
    EXPECT_NEAR(s.style.color.g, 1.0f, 1e-6f);
    EXPECT_NEAR(s.style.color.r, 0.0f, 1e-6f);
    const glm::vec3 silhouette = s.lines.styles[size_t(LineType::Silhouette)].color;
    EXPECT_EQ(silhouette, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_NE(error_of(R"({"model": "a.glb", "background": 3})").find("background: expected [r, g, b] in [0, 1] or a colour string"),
              std::string::npos);
    // HTML's sixteen names, as SVG files use them (navy and teal were refused).
    EXPECT_EQ(parse_scene_json(R"({"model": "a.glb", "background": "navy"})", "x.json").style.background,
              glm::vec3(0.0f, 0.0f, 128.0f / 255.0f));
    EXPECT_EQ(parse_scene_json(R"({"model": "a.glb", "background": "Teal"})", "x.json").style.background,
              glm::vec3(0.0f, 128.0f / 255.0f, 128.0f / 255.0f));
    EXPECT_NE(error_of(R"({"model": "a.glb", "background": "navyblue"})").find("or a colour name (aqua, black, "),
              std::string::npos);
}

// "description" says what the image is for: kept as written, written back (a saved view keeps
// it), and a string or an error naming the key.
TEST(SceneFile, DescriptionIsKeptAndWrittenBack) {
    const SceneDesc s = parse_scene_json(R"({"model": "a.glb", "description": "the cow, for the README"})", "x.json");
    EXPECT_EQ(s.description, "the cow, for the README");
    const std::string written = scene_json(s, ViewCamera{.eye = {0, 0, 3}, .target = {0, 0, 0}}, ".");
    EXPECT_EQ(parse_scene_json(written, "y.json").description, "the cow, for the README") << written;
    EXPECT_EQ(error_of(R"({"model": "a.glb", "description": 3})").rfind("scenes/x.json: description: ", 0), 0u);
}

// "coherence": the parameterization's settings as scene keys (the command line's --param,
// --splat-radius, --inlier-px, --min-stroke-length, --length-scale), read, applied by the
// session's defaults and written back.
TEST(SceneFile, CoherenceKeysAreReadAppliedAndWrittenBack) {
    const SceneDesc s = parse_scene_json(R"({"model": "a.glb", "coherence": {"policy": "arclength", "splat_radius": 6,
        "inlier_distance": 2, "min_stroke_length": 12, "length_scale": 3}})", "x.json");
    ASSERT_TRUE(s.coherence.policy.has_value());
    EXPECT_EQ(*s.coherence.policy, ParamPolicy::Arclength);
    const SessionOptions options = default_session_options(s);
    EXPECT_EQ(options.coherence.policy, ParamPolicy::Arclength);
    EXPECT_FLOAT_EQ(options.coherence.splat_radius_px, 6.0f);
    EXPECT_FLOAT_EQ(options.coherence.ransac.inlier_px, 2.0f);
    EXPECT_FLOAT_EQ(options.coherence.min_stroke_length_px, 12.0f);
    // κ fills in for sets without their own: not an override of theirs, as --length-scale is.
    EXPECT_FLOAT_EQ(options.length_scale, 0.0f);
    EXPECT_EQ(s.coherence.length_scale.value_or(0.0f), 3.0f);

    const SceneDesc back = parse_scene_json(scene_json(s, ViewCamera{.eye = {0, 0, 3}, .target = {0, 0, 0}}, "."), "y.json");
    EXPECT_EQ(back.coherence.policy, s.coherence.policy);
    EXPECT_EQ(back.coherence.splat_radius_px, s.coherence.splat_radius_px);
    EXPECT_EQ(back.coherence.inlier_px, s.coherence.inlier_px);
    EXPECT_EQ(back.coherence.min_stroke_length_px, s.coherence.min_stroke_length_px);
    EXPECT_EQ(back.coherence.length_scale, s.coherence.length_scale);

    // Left out: the defaults, δ twice the sample spacing, and nothing written.
    const SceneDesc plain = parse_scene_json(R"({"model": "a.glb", "lines": {"sample_spacing": 3}})", "x.json");
    EXPECT_EQ(default_session_options(plain).coherence.policy, ParamPolicy::Coherent);
    EXPECT_FLOAT_EQ(default_session_options(plain).coherence.splat_radius_px, 6.0f);
    EXPECT_EQ(scene_json(plain, ViewCamera{.eye = {0, 0, 3}, .target = {0, 0, 0}}, ".").find("coherence"), std::string::npos);

    EXPECT_EQ(error_of(R"({"model": "a.glb", "coherence": {"policy": "tiled"}})").rfind("scenes/x.json: coherence.policy: ", 0), 0u);
    EXPECT_EQ(error_of(R"({"model": "a.glb", "coherence": {"splat_radius": 0}})").rfind("scenes/x.json: coherence.splat_radius: ", 0), 0u);
    EXPECT_EQ(error_of(R"({"model": "a.glb", "coherence": {"inlier": 2}})"),
              "scenes/x.json: coherence.inlier: unknown key (known here: inlier_distance, length_scale, min_stroke_length, "
              "policy, splat_radius)");
}

TEST(SceneFile, ErrorsNameTheKey) {
    EXPECT_EQ(error_of(R"({"model": "a.glb", "sise": [1, 2]})").rfind("scenes/x.json: sise: unknown key", 0), 0u);
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"eye": [0,0,1], "target": [0,0,0], "fovv": 3}})")
                  .rfind("scenes/x.json: camera.fovv: unknown key", 0),
              0u);
    EXPECT_EQ(error_of(R"({"model": "a.glb", "size": [0, 10]})"),
              "scenes/x.json: size: width and height must be 1..16384");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "size": "big"})"), "scenes/x.json: size: expected [width, height] in pixels");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "shading": "glossy"})"),
              "scenes/x.json: shading: must be one of flat, none, toon, unlit, got \"glossy\"");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "color": [2, 0, 0]})"),
              "scenes/x.json: color: components must be between 0 and 1");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"eye": [0,0,1], "target": [0,0,1]}})"),
              "scenes/x.json: camera: eye and target coincide");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"eye": [0,0,1], "target": [0,0,0], "fov": 200}})"),
              "scenes/x.json: camera.fov: must be between 1 and 170, got 200");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"target": [0,0,0]}})"), "scenes/x.json: camera.eye: required");
    // A key twice in one object (JSON keeps one) is refused; the same key in two objects is not.
    EXPECT_EQ(error_of(R"({"model": "a.glb", "size": [64, 48], "model": "b.glb"})"),
              "scenes/x.json: \"model\" is given twice in one object (JSON would keep only one of them): give it once");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "lines": {"crease": {"width": 2, "width": 3}}})"),
              "scenes/x.json: lines.crease: \"width\" is given twice in one object (JSON would keep only one of them): "
              "give it once");
    EXPECT_NE(error_of(R"({"model": "a.glb", "line_sets": [{"name": "a"}, {"name": "b", "style": {"width": 1, "width": 2}}]})")
                  .find("scenes/x.json: line_sets[1].style: \"width\" is given twice"),
              std::string::npos);
    EXPECT_EQ(error_of(R"({"model": "a.glb", "lines": {"crease": {"width": 2}, "border": {"width": 2}}})"), "(no error)");
    // Neither eye nor target: the framing camera, with the fov given (as under an orbit).
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"fov": 35}})"), "(no error)");
    EXPECT_EQ(error_of(R"({"model": "a.glb", "camera": {"fov": 35, "up": [0, 0, 1]}})"),
              "scenes/x.json: camera.up: needs eye and target (without them the camera frames the model)");
    EXPECT_EQ(error_of(R"({"size": [10, 10]})").rfind("scenes/x.json: model: required", 0), 0u);
    EXPECT_EQ(error_of(R"({"model": "a.stl"})"), "scenes/x.json: model: \"a.stl\" is not a model file (.gltf, .glb, .obj or .ply)");
    EXPECT_EQ(error_of(R"([1, 2])"), "scenes/x.json: the scene must be a JSON object");
    EXPECT_EQ(error_of(R"({"model": "a.glb",)").rfind("scenes/x.json: invalid JSON: parse error", 0), 0u);
}

TEST(SceneFile, MissingFileIsNamed) {
    try {
        (void)load_scene_file("/no/such/scene.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "/no/such/scene.json: cannot open scene file (no such file)");
    }
}

TEST(SceneFile, ShippedScenesAreValid) {
    for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        const SceneDesc s = load_scene_file(entry.path());
        for (const auto& model : s.models) EXPECT_TRUE(std::filesystem::exists(model)) << model;
    }
}

}  // namespace
}  // namespace lw
