// Occlusion levels (issue 16 item 5): three nested boxes, open at the back, seen from the
// front: the front rim of box k (0 outside) is behind k front faces, its back rim behind
// k + 1; line sets select levels with "qi"; --hidden-levels keeps the first hidden level.
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "lines/occlusion.h"
#include "render/frame_renderer.h"
#include "render/line_sets.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "test_support.h"

namespace lw {
namespace {

class OcclusionLevels : public test::GpuTest {};

constexpr float kHalf[3] = {1.0f, 0.6f, 0.3f};  // half sizes of the boxes, outermost first

// A cube [−h, h]³ without its back face (z = −h): 10 triangles wound outward, so its front
// rim (z = h) is creases and its back rim borders.
TriangleMesh open_box(float h) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
        m.positions.push_back(corner);
        m.normals.push_back(glm::normalize(corner));
    }
    m.indices = {4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    m.face_material.assign(10, -1);
    m.face_part.assign(10, 0u);
    m.part_count = 1;
    return m;
}

TriangleMesh nested_boxes() {
    TriangleMesh mesh = open_box(kHalf[0]);
    append_mesh(mesh, open_box(kHalf[1]));
    append_mesh(mesh, open_box(kHalf[2]));
    return mesh;
}

// The level expected of a sample on a rim (front rim of box k: k; back rim: k + 1), or −1
// for one on no rim (the edges along z) or at a rim's corner, where a run may change.
int expected_level(const glm::vec3& p) {
    for (int k = 0; k < 3; ++k) {
        const float h = kHalf[k];
        const bool on_square = std::abs(std::max(std::abs(p.x), std::abs(p.y)) - h) < 1e-4f;
        const bool corner = std::abs(std::abs(p.x) - h) < 0.02f && std::abs(std::abs(p.y) - h) < 0.02f;
        if (!on_square || corner) continue;
        if (std::abs(p.z - h) < 1e-4f) return k;
        if (std::abs(p.z + h) < 1e-4f) return k + 1;
    }
    return -1;
}

Frame render_levels(const Context& ctx, std::vector<LineSetDesc> sets, HiddenLines hidden = HiddenLines::None,
                    uint32_t hidden_levels = 0) {
    const TriangleMesh mesh = nested_boxes();
    const int width = 480, height = 480;
    // Off the axis but within the innermost box's x and y: every box's side faces are seen
    // from inside, so each back rim is seen through its own box's front face.
    const glm::vec3 eye(0.12f, 0.08f, 5.0f);
    const ViewCamera view{.eye = eye, .target = glm::vec3(0.0f), .fov_deg = 40.0f};
    const CameraMatrices camera = camera_matrices(view, 1.0f, compute_bounds(mesh.positions));
    FrameRenderer renderer(ctx, uint32_t(width), uint32_t(height));
    renderer.set_mesh(mesh, true, 45.0f);
    LinesDesc lines;
    lines.sets = std::move(sets);
    lines.hidden = hidden;
    lines.hidden_levels = hidden_levels;
    return renderer.render(camera, eye, SurfaceStyle{}, lines, FrameOutputs{.color = false, .depth = false});
}

LineSetDesc level_set(const char* name, LevelRange qi) {
    LineSetDesc set{.name = name};
    set.select.types = (1u << uint32_t(LineType::Crease)) | (1u << uint32_t(LineType::Border));
    set.select.qi = qi;
    return set;
}

TEST_F(OcclusionLevels, NestedOpenBoxesGiveTheirDepth) {
    const Frame frame = render_levels(ctx(), {level_set("all", {0, 1000})});
    std::map<int, size_t> checked;  // expected level → samples
    for (const ScreenPath& run : frame.screen_paths) {
        EXPECT_EQ(run.visible, run.qi == 0);
        for (const ScreenSample& s : run.samples) {
            const int want = expected_level(s.position);
            // A run's end sample is shared with the next run, whose level may differ.
            if (want < 0 || &s == &run.samples.front() || &s == &run.samples.back()) continue;
            EXPECT_EQ(int(run.qi), want) << "sample at " << s.position.x << "," << s.position.y << "," << s.position.z;
            ++checked[want];
        }
    }
    for (int level = 0; level <= 3; ++level) {
        RecordProperty("samples_at_level_" + std::to_string(level), int(checked[level]));
        EXPECT_GT(checked[level], 20u) << "level " << level << ": no rim seen at that level";
    }
}

// A set selecting [1, 1] keeps exactly the runs behind one surface; --hidden-levels 1 keeps
// the visible lines and the first hidden level.
TEST_F(OcclusionLevels, LineSetsAndHiddenLevelsSelectByLevel) {
    const Frame all = render_levels(ctx(), {level_set("all", {0, 1000})});
    std::vector<LineSetDesc> sets{level_set("first", {1, 1})};
    const FaceGroups* none = nullptr;
    const std::vector<ScreenPath> first = select_line_set(all.screen_paths, sets[0], none);
    ASSERT_FALSE(first.empty());
    for (const ScreenPath& run : first) EXPECT_EQ(run.qi, 1u);
    EXPECT_EQ(size_t(std::count_if(all.screen_paths.begin(), all.screen_paths.end(),
                                   [](const ScreenPath& r) { return r.qi == 1; })),
              first.size());

    // A set with its own sample spacing tests visibility again: with levels counted too.
    LineSetDesc spaced = level_set("deep", {2, 2});
    spaced.coherence.sample_spacing_px = 3.0f;
    const Frame own = render_levels(ctx(), {spaced});
    ASSERT_EQ(own.sets.size(), 1u);
    ASSERT_FALSE(own.sets[0].paths.empty()) << "level-2 runs at 3 px spacing";
    for (const ScreenPath& run : own.sets[0].paths) EXPECT_EQ(run.qi, 2u);

    // The shorthand (no line sets): --hidden dashed --hidden-levels 1.
    LinesDesc lines;
    lines.hidden = HiddenLines::Dashed;
    lines.hidden_levels = 1;
    const std::vector<LineSetDesc> shorthand = effective_line_sets(lines);
    for (const LineSetDesc& set : shorthand) {
        ASSERT_TRUE(set.select.qi.has_value());
        EXPECT_EQ(*set.select.qi, (LevelRange{0, 1}));
    }
    const Frame dashed = render_levels(ctx(), {}, HiddenLines::Dashed, 1);
    size_t deeper = 0;
    for (const ScreenPath& run : dashed.screen_paths) deeper += run.qi > 1;
    EXPECT_GT(deeper, 0u) << "the frame's runs carry all levels; the sets select";
}

// Rays from the eye to points inside the boxes (on no face: none left out as the point's
// own). Without an index nothing is counted.
TEST(OcclusionCounter, CountsEachSurfaceOnce) {
    const LineMesh lm = build_line_mesh(nested_boxes(), 45.0f);
    OcclusionCounter counter;
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {0, 0, -1}, 0, false), 0u);
    counter.set_mesh(lm);
    // Straight down the axis to the innermost box's open back: through three front faces
    // (each ray hits a front face on its diagonal edge, where two triangles meet: counted once).
    constexpr uint32_t kNoFace = ~0u;
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {0.0f, 0.0f, -0.29f}, kNoFace, false), 3u);
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {0.1f, 0.05f, 0.31f}, kNoFace, false), 2u);
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {0.1f, 0.05f, 2.0f}, kNoFace, false), 0u);
    // In through the outer box's front, out through its side (x = 1): two crossings.
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {1.5f, 0.0f, -2.0f}, kNoFace, false), 2u);
    EXPECT_EQ(counter.surfaces_in_front({0, 0, 5}, {0, 0, -1}, kNoFace, false), 3u);
}

// "qi" and "hidden_levels" read back from a saved scene; bad values name the key; the
// shorthand's hidden-line keys are refused beside line sets (which draw their own).
TEST(OcclusionLevelKeys, ReadBackAndRejectBadValues) {
    const auto fs_dir = test::temp_dir();
    const std::string set = R"("line_sets": [{"name": "first", "select": {"types": ["crease"], "qi": [1, 1]}}])";
    const SceneDesc desc = parse_scene_json(R"({"model": "m.glb", )" + set + "}", fs_dir / "in.json");
    ASSERT_TRUE(desc.lines.sets[0].select.qi.has_value());
    EXPECT_EQ(*desc.lines.sets[0].select.qi, (LevelRange{1, 1}));
    EXPECT_EQ(parse_scene_json(scene_json(desc, ViewCamera{}, fs_dir), fs_dir / "out.json").lines.sets[0].select.qi,
              desc.lines.sets[0].select.qi);
    const SceneDesc shorthand =
        parse_scene_json(R"({"model": "m.glb", "lines": {"hidden": "faint", "hidden_levels": 2}})", fs_dir / "s.json");
    EXPECT_EQ(shorthand.lines.hidden_levels, 2u);
    EXPECT_EQ(parse_scene_json(scene_json(shorthand, ViewCamera{}, fs_dir), fs_dir / "s2.json").lines.hidden_levels, 2u);
    try {
        (void)parse_scene_json(R"({"model": "m.glb", "lines": {"hidden": "faint", "hidden_levels": 2}, )" + set + "}",
                               fs_dir / "both.json");
        ADD_FAILURE() << "hidden lines of the shorthand beside line sets: no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("both.json: lines.hidden: styles the hidden lines"), std::string::npos)
            << e.what();
    }
    // The viewer can turn hidden lines off with levels still set, or set them beside line sets
    // (where they do nothing): the scenes it saves read back.
    SceneDesc off = shorthand;
    off.lines.hidden = HiddenLines::None;
    EXPECT_NO_THROW((void)parse_scene_json(scene_json(off, ViewCamera{}, fs_dir), fs_dir / "off.json"));
    SceneDesc beside = desc;
    beside.lines.hidden = HiddenLines::Dashed;
    beside.lines.hidden_levels = 1;
    EXPECT_NO_THROW((void)parse_scene_json(scene_json(beside, ViewCamera{}, fs_dir), fs_dir / "beside.json"));
    const auto error_of = [&](const std::string& select) {
        try {
            (void)parse_scene_json(R"({"model": "m.glb", "line_sets": [{"name": "a", "select": )" + select + "}]}",
                                   fs_dir / "bad.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error_of(R"({"qi": [2, 1]})").find("bad.json: line_sets[0].select.qi: expected [min, max]"), std::string::npos)
        << error_of(R"({"qi": [2, 1]})");
    EXPECT_NE(error_of(R"({"qi": [0.5, 1]})").find("select.qi"), std::string::npos);
    EXPECT_NE(error_of(R"({"qi": 1})").find("select.qi"), std::string::npos);
    EXPECT_NE(error_of(R"({"qi": [0, 1], "visibility": "any"})").find("not both"), std::string::npos);
    EXPECT_THROW((void)parse_scene_json(R"({"model": "m.glb", "lines": {"hidden_levels": 1.5}})", fs_dir / "c.json"), Error);
}

}  // namespace
}  // namespace lw
