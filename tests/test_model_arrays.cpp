// Meshes given as arrays (model_from_arrays, load_scene with models in memory) and a session's
// lines replaced whole (set_lines): what the Python module builds on, tested here so that the
// sanitizer build runs it too.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/error.h"
#include "core/image.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

const std::filesystem::path kSpot = test::source_dir() / "scenes/models/spot/spot.glb";

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(ModelArrays, BadArraysAreNamedErrors) {
    const std::vector<glm::vec3> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(error_of([&] { (void)model_from_arrays("m", tri, {0, 1, 9}); }),
              "m: faces: index 9 of triangle 0 is past the 3 vertices");
    EXPECT_EQ(error_of([&] { (void)model_from_arrays("m", tri, {0, 1}); }),
              "m: faces: expected at least one triangle (M×3 vertex indices)");
    std::vector<glm::vec3> nan = tri;
    nan[1].y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(error_of([&] { (void)model_from_arrays("m", nan, {0, 1, 2}); }), "m: vertices: vertex 1 is not finite");
    EXPECT_EQ(error_of([&] { (void)model_from_arrays("m", tri, {0, 1, 2}, {{0, 0, 1}}); }),
              "m: normals: 1 normals for 3 vertices");
}

TEST(ModelArrays, ArraysMergeAsTheFileDoes) {
    const LoadedScene file = load_scene(scene_for_model(kSpot));
    Model arrays = model_from_arrays("spot arrays", file.mesh.positions, file.mesh.indices, file.mesh.normals);
    const LoadedScene given = load_scene(scene_for_model(kSpot), {std::move(arrays)});
    EXPECT_EQ(given.mesh.positions, file.mesh.positions);
    EXPECT_EQ(given.mesh.indices, file.mesh.indices);
    // Normals are normalized once more on the way in (one ulp at most).
    ASSERT_EQ(given.mesh.normals.size(), file.mesh.normals.size());
    for (size_t i = 0; i < file.mesh.normals.size(); ++i)
        EXPECT_LT(glm::length(given.mesh.normals[i] - file.mesh.normals[i]), 1e-6f) << i;
    EXPECT_EQ(given.model_triangles, file.model_triangles);
    EXPECT_EQ(given.camera.eye, file.camera.eye);
    EXPECT_EQ(given.models.front().path, "spot arrays");
}

TEST(ModelArrays, ASceneForGivenModelsMustNotNameOne) {
    EXPECT_NO_THROW((void)parse_scene_json("{\"size\": [64, 48]}", "scene", true));
    EXPECT_EQ(error_of([] { (void)parse_scene_json("{\"model\": \"a.glb\"}", "scene", true); }),
              "scene: model: not allowed beside a mesh given as arrays");
    EXPECT_NE(error_of([] { (void)parse_scene_json("{\"size\": [64, 48]}", "scene"); }), "");
}

class SessionArrays : public test::GpuTest {};

TEST_F(SessionArrays, InMemoryModelsGiveTheFilesLines) {
    SceneDesc desc = scene_for_model(kSpot);
    desc.width = 200;
    desc.height = 150;
    const LoadedScene file = load_scene(desc);
    SceneSession from_file(ctx(), desc, default_session_options(desc));
    SceneSession from_arrays(ctx(), desc, default_session_options(desc),
                             {model_from_arrays("mesh", file.mesh.positions, file.mesh.indices)});
    EXPECT_EQ(from_arrays.desc().models.front(), "mesh");
    const Frame a = from_file.frame({.outputs = {.color = false}});
    const Frame b = from_arrays.frame({.outputs = {.color = false}});
    ASSERT_EQ(a.screen_paths.size(), b.screen_paths.size());
    ASSERT_GT(a.screen_paths.size(), 10u);
    for (size_t i = 0; i < a.screen_paths.size(); ++i) {
        ASSERT_EQ(a.screen_paths[i].samples.size(), b.screen_paths[i].samples.size()) << i;
        for (size_t j = 0; j < a.screen_paths[i].samples.size(); ++j)
            EXPECT_EQ(a.screen_paths[i].samples[j].pixel, b.screen_paths[i].samples[j].pixel);
    }
}

// The scene's "coherence.length_scale" is κ for the sets without their own, in the sets the
// session draws; the description keeps the key as written (a saved view writes it back).
TEST_F(SessionArrays, TheScenesKappaFillsInForSetsWithoutTheirOwn) {
    const SceneDesc desc = parse_scene_json(R"({"model": ")" + kSpot.string() + R"(", "coherence": {"length_scale": 3},
        "line_sets": [{"name": "own", "coherence": {"length_scale": 5}}, {"name": "base"}]})", "x.json");
    SceneSession session(ctx(), desc, default_session_options(desc));
    ASSERT_EQ(session.line_sets().size(), 2u);
    EXPECT_FLOAT_EQ(session.line_sets()[0].coherence.length_scale, 5.0f);
    EXPECT_FLOAT_EQ(session.line_sets()[1].coherence.length_scale, 3.0f);
    EXPECT_FLOAT_EQ(session.desc().lines.sets[1].coherence.length_scale, 0.0f);
    SessionOptions flag = default_session_options(desc);
    flag.length_scale = 2.0f;  // --length-scale overrides every set's
    SceneSession overridden(ctx(), desc, flag);
    EXPECT_FLOAT_EQ(overridden.line_sets()[0].coherence.length_scale, 2.0f);
    EXPECT_FLOAT_EQ(overridden.line_sets()[1].coherence.length_scale, 2.0f);
}

TEST_F(SessionArrays, SetLinesAppliesAndABadFileChangesNothing) {
    SceneDesc desc = scene_for_model(kSpot);
    desc.width = 160;
    desc.height = 120;
    SceneSession session(ctx(), desc, default_session_options(desc));
    const ImageRGBA8 before = session.frame({}).image.color;

    LinesDesc wide = session.desc().lines;
    wide.styles[size_t(LineType::Silhouette)].width = 5.0f;
    session.set_lines(wide);
    const ImageRGBA8 widened = session.frame({}).image.color;
    EXPECT_GT(compare_images(before, widened).differing_fraction, 0.005);

    LinesDesc bad = session.desc().lines;
    bad.styles[size_t(LineType::Silhouette)].width = 1.0f;
    bad.styles[size_t(LineType::Silhouette)].slam = (test::temp_dir() / "missing.exr").string();
    EXPECT_NE(error_of([&] { session.set_lines(bad); }).find("missing.exr"), std::string::npos);
    EXPECT_EQ(session.desc().lines.styles[size_t(LineType::Silhouette)].width, 5.0f);
    EXPECT_EQ(compare_images(session.frame({}).image.color, widened).max_abs_error, 0);

    // Creases off and a new crease angle rebuild the line mesh; back to the start, the same frame.
    LinesDesc creases = session.desc().lines;
    creases.params.crease_angle_deg = 20.0f;
    session.set_lines(creases);
    EXPECT_GT(compare_images(session.frame({}).image.color, widened).differing_fraction, 0.0);
    session.set_lines(desc.lines);
    EXPECT_EQ(compare_images(session.frame({}).image.color, before).max_abs_error, 0);
}

}  // namespace
}  // namespace lw
