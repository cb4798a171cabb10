// Animation evaluation, skinning, welded-mesh updates, camera paths and their scene keys.
// CPU only: no Vulkan, so this file does not include test_support.h.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "geometry/welded_mesh.h"
#include "scene/animation.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "scene/scene_file.h"

namespace lw {
namespace {

std::filesystem::path models_dir() { return std::filesystem::path(LW_SOURCE_DIR) / "tests" / "data" / "models"; }

using Interpolation = AnimationSampler::Interpolation;

AnimationSampler make_sampler(Interpolation interpolation, std::vector<float> times, std::vector<float> values,
                              int components) {
    AnimationSampler s;
    s.interpolation = interpolation;
    s.times = std::move(times);
    s.values = std::move(values);
    s.components = components;
    return s;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// q and −q are the same rotation.
void expect_same_rotation(const glm::quat& a, const glm::quat& b) { EXPECT_NEAR(std::fabs(glm::dot(a, b)), 1.0f, 1e-5f); }

std::string error_of(const auto& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(AnimationSampling, LinearTranslationHalfwayAndClamped) {
    const AnimationSampler s = make_sampler(Interpolation::Linear, {1.0f, 3.0f}, {0, 0, 0, 2, 4, 6}, 3);
    expect_near(sample_vec3(s, 2.0f), {1, 2, 3}, 1e-6f);
    expect_near(sample_vec3(s, 1.5f), {0.5f, 1, 1.5f}, 1e-6f);
    // Before the first key the first value holds, after the last the last.
    EXPECT_EQ(sample_vec3(s, 0.0f), glm::vec3(0.0f));
    EXPECT_EQ(sample_vec3(s, -5.0f), glm::vec3(0.0f));
    EXPECT_EQ(sample_vec3(s, 3.0f), glm::vec3(2, 4, 6));
    EXPECT_EQ(sample_vec3(s, 100.0f), glm::vec3(2, 4, 6));
}

TEST(AnimationSampling, StepHoldsUntilTheNextKey) {
    const AnimationSampler s = make_sampler(Interpolation::Step, {0, 1, 2}, {1, 1, 1, 5, 5, 5, 9, 9, 9}, 3);
    EXPECT_EQ(sample_vec3(s, 0.99f), glm::vec3(1.0f));
    EXPECT_EQ(sample_vec3(s, 1.0f), glm::vec3(5.0f));
    EXPECT_EQ(sample_vec3(s, 1.5f), glm::vec3(5.0f));
    EXPECT_EQ(sample_vec3(s, 7.0f), glm::vec3(9.0f));
}

// glTF 2.0 Appendix C: p(t) = h00 v0 + h10 td b0 + h01 v1 + h11 td a1, per component.
TEST(AnimationSampling, CubicSplineMatchesTheHermiteFormula) {
    const glm::dvec3 a0(9, 9, 9), v0(1, 0, -1), b0(2, 0, 1);   // a0 unused between keys 0 and 1
    const glm::dvec3 a1(-1, 3, 0), v1(4, 2, 0), b1(7, 7, 7);   // b1 unused
    const double t0 = 1.0, t1 = 3.0, td = t1 - t0;
    std::vector<float> values;
    for (const glm::dvec3& v : {a0, v0, b0, a1, v1, b1})
        for (int c = 0; c < 3; ++c) values.push_back(static_cast<float>(v[c]));
    const AnimationSampler s =
        make_sampler(Interpolation::CubicSpline, {static_cast<float>(t0), static_cast<float>(t1)}, values, 3);
    for (double time : {1.25, 1.5, 2.0, 2.9}) {
        const double t = (time - t0) / td, t2 = t * t, t3 = t2 * t;
        const glm::dvec3 expected = (2 * t3 - 3 * t2 + 1) * v0 + td * (t3 - 2 * t2 + t) * b0 + (-2 * t3 + 3 * t2) * v1 +
                                    td * (t3 - t2) * a1;
        expect_near(sample_vec3(s, static_cast<float>(time)), glm::vec3(expected), 1e-5f);
    }
    // The keys' values, and the tangents as slopes per second (that is why they are scaled
    // by the key interval): leaving key 0 at b0, arriving at key 1 at a1.
    expect_near(sample_vec3(s, 1.0f), glm::vec3(v0), 0.0f);
    expect_near(sample_vec3(s, 3.0f), glm::vec3(v1), 0.0f);
    const float h = 1e-3f;
    expect_near((sample_vec3(s, 1.0f + h) - sample_vec3(s, 1.0f)) / h, glm::vec3(b0), 1e-2f);
    expect_near((sample_vec3(s, 3.0f) - sample_vec3(s, 3.0f - h)) / h, glm::vec3(a1), 1e-2f);
}

std::vector<float> xyzw(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

TEST(AnimationSampling, RotationSlerpsHalfwayAlongTheShortArc) {
    const glm::quat identity(1, 0, 0, 0);
    const glm::quat quarter = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    const glm::quat eighth = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0));
    std::vector<float> values = xyzw(identity);
    for (float v : xyzw(quarter)) values.push_back(v);
    const AnimationSampler s = make_sampler(Interpolation::Linear, {0, 2}, values, 4);
    expect_same_rotation(sample_rotation(s, 1.0f), eighth);
    EXPECT_NEAR(glm::length(sample_rotation(s, 0.7f)), 1.0f, 1e-6f);

    // −quarter is the same rotation: halfway is still 45°, not the long way round (−135°).
    values = xyzw(identity);
    for (float v : xyzw(-quarter)) values.push_back(v);
    const AnimationSampler flipped = make_sampler(Interpolation::Linear, {0, 2}, values, 4);
    expect_same_rotation(sample_rotation(flipped, 1.0f), eighth);
    expect_same_rotation(slerp_shortest(identity, -quarter, 0.5f), eighth);

    // Clamped, and STEP holds the first key.
    expect_same_rotation(sample_rotation(s, -1.0f), identity);
    expect_same_rotation(sample_rotation(s, 9.0f), quarter);
    const AnimationSampler step = make_sampler(Interpolation::Step, {0, 2}, s.values, 4);
    expect_same_rotation(sample_rotation(step, 1.9f), identity);
}

TEST(AnimationSampling, CubicSplineRotationsAreNormalizedAndComponentCountsChecked) {
    // Zero tangents: the spline eases from identity to the quarter turn through non-unit
    // quaternions, which must come out normalized.
    const glm::quat quarter = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    std::vector<float> values = {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0};
    const std::vector<float> second = {0, 0, 0, 0, quarter.x, quarter.y, quarter.z, quarter.w, 0, 0, 0, 0};
    values.insert(values.end(), second.begin(), second.end());
    const AnimationSampler s = make_sampler(Interpolation::CubicSpline, {0, 1}, values, 4);
    EXPECT_NEAR(glm::length(sample_rotation(s, 0.5f)), 1.0f, 1e-6f);
    expect_same_rotation(sample_rotation(s, 0.5f), glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1)));
    EXPECT_NE(error_of([&] { (void)sample_vec3(s, 0.5f); }).find("needs 3 components"), std::string::npos);
}

// A root that turns 90° about z, a child one unit along its x, and a matrix node.
Model hand_built_hierarchy() {
    Model model;
    model.path = "hand-built.gltf";
    model.nodes.resize(3);
    model.nodes[0].children = {1};
    model.nodes[1].parent = 0;
    model.nodes[1].translation = {1, 0, 0};
    model.nodes[2].has_matrix = true;
    model.nodes[2].matrix = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 7));
    model.roots = {0, 2};
    const glm::quat quarter = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    Animation turn;
    turn.name = "turn";
    turn.samplers.push_back(make_sampler(Interpolation::Linear, {0, 1}, {0, 0, 0, 1, quarter.x, quarter.y, quarter.z, quarter.w}, 4));
    turn.samplers.push_back(make_sampler(Interpolation::Linear, {0, 1}, {5, 5, 5, 5, 5, 5}, 3));
    turn.channels = {{0, AnimationChannel::Path::Rotation, 0},
                     {2, AnimationChannel::Path::Translation, 1},  // a matrix node: ignored
                     {1, AnimationChannel::Path::Weights, 1}};     // morph weights: ignored
    turn.duration = 1.0f;
    Animation slide;
    slide.name = "slide";
    slide.samplers.push_back(make_sampler(Interpolation::Linear, {0, 1}, {0, 2, 0, 0, 2, 0}, 3));
    slide.channels = {{1, AnimationChannel::Path::Translation, 0}};
    slide.duration = 1.0f;
    model.animations = {turn, slide};
    return model;
}

TEST(AnimationPose, WorldIsParentTimesChildAndMatrixNodesKeepTheirMatrix) {
    const Model model = hand_built_hierarchy();
    const Pose rest = evaluate_pose(model, {}, 0.5f);
    expect_near(glm::vec3(rest.world[1][3]), {1, 0, 0}, 1e-6f);

    const Pose turned = evaluate_pose(model, {0}, 1.0f);
    expect_near(glm::vec3(turned.world[1][3]), {0, 1, 0}, 1e-6f);  // the child swings round with its parent
    EXPECT_EQ(turned.world[2], model.nodes[2].matrix);
    EXPECT_EQ(turned.translation[1], glm::vec3(1, 0, 0));

    // Clips play together; the later one in the list wins where both drive a property.
    const Pose both = evaluate_pose(model, {0, 1}, 1.0f);
    expect_near(glm::vec3(both.world[1][3]), {-2, 0, 0}, 1e-6f);  // (0, 2, 0) turned 90° about z

    EXPECT_NE(error_of([&] { (void)evaluate_pose(model, {2}, 0.0f); }).find("no animation clip 2"), std::string::npos);
}

TEST(AnimationClips, FindByNameOrIndexWithClearErrors) {
    const Model fox = load_gltf(models_dir() / "Fox/Fox.glb");
    EXPECT_EQ(find_clip(fox, "Walk"), 1);
    EXPECT_EQ(find_clip(fox, 2), 2);
    EXPECT_EQ(select_clips(fox, {}), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(select_clips(fox, ClipChoice{ClipChoice::Kind::Name, "Run", -1}), (std::vector<int>{2}));
    EXPECT_NEAR(clip_duration(fox, 1), 0.7083f, 1e-3f);
    EXPECT_NEAR(clips_duration(fox, {0, 1, 2}), 3.4167f, 1e-3f);
    const std::string missing = error_of([&] { (void)find_clip(fox, "Jump"); });
    EXPECT_NE(missing.find("Fox.glb: no animation clip named \"Jump\""), std::string::npos) << missing;
    EXPECT_NE(missing.find("0 \"Survey\", 1 \"Walk\", 2 \"Run\""), std::string::npos) << missing;
    EXPECT_NE(error_of([&] { (void)find_clip(fox, 3); }).find("no animation clip 3"), std::string::npos);
}

// SimpleSkin: a strip of 10 vertices, x ∈ {0, 1}, y = 0 .. 2, skinned to joint 0 (node 1 at
// y = 1) and joint 1 (node 2, its child at the same place) with weights shading from joint 0
// at the bottom to joint 1 at the top. Both inverse bind matrices translate by (−0.5, −1, 0):
// the strip was bound centred on x = 0.5, so the skinned rest pose is the strip moved by
// −0.5 in x, not the file's positions. At t = 1 s node 2 has turned 90° about z.
TEST(Skinning, SimpleSkinFollowsItsJointsAsComputedByHand) {
    const Model model = load_gltf(models_dir() / "SimpleSkin/SimpleSkin.gltf");
    const Primitive& strip = model.meshes[0].primitives[0];
    const glm::mat4 inverse_bind = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, -1.0f, 0.0f));
    const glm::mat4 joint_world = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0));
    const glm::mat4 turned = joint_world * glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1));

    // Rest: both joint matrices are the same translation, so the shape is the bind shape.
    const TriangleMesh rest = flatten_posed(model, evaluate_pose(model, {}, 0.0f));
    ASSERT_EQ(rest.positions.size(), strip.positions.size());
    for (size_t v = 0; v < rest.positions.size(); ++v)
        expect_near(rest.positions[v], strip.positions[v] + glm::vec3(-0.5f, 0, 0), 1e-6f);

    const TriangleMesh posed = flatten_posed(model, evaluate_pose(model, {0}, 1.0f));
    ASSERT_EQ(posed.positions.size(), strip.positions.size());
    EXPECT_EQ(posed.indices, rest.indices);
    for (size_t v = 0; v < posed.positions.size(); ++v) {
        const glm::vec4 p(strip.positions[v], 1.0f);
        const glm::vec4 w = strip.weights[v];
        ASSERT_EQ(strip.joints[v], glm::u16vec4(0, 1, 0, 0));
        const glm::vec3 expected = glm::vec3(w.x * (joint_world * inverse_bind * p) + w.y * (turned * inverse_bind * p));
        expect_near(posed.positions[v], expected, 2e-4f);  // the file's quaternion is 0.707, not √½
    }
    // The top corners hang from joint 1 alone: (0.5, 1) from the joint turned by 90°.
    expect_near(posed.positions[9], {-1.0f, 1.5f, 0.0f}, 2e-4f);
    // The strip has no normals: they are recomputed from the posed triangles.
    for (const glm::vec3& n : posed.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

// One triangle on a node whose own transform must be ignored, skinned to two joints.
Model hand_built_skin(glm::vec4 weights) {
    Model model;
    model.path = "skin.gltf";
    model.nodes.resize(3);
    model.nodes[0].mesh = 0;
    model.nodes[0].skin = 0;
    model.nodes[0].translation = {100, 0, 0};  // ignored for skinned vertices (§3.7.3)
    model.nodes[1].translation = {0, 0, 2};
    model.nodes[2].translation = {0, 3, 0};
    model.roots = {0, 1, 2};
    Primitive triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    triangle.indices = {0, 1, 2};
    triangle.joints.assign(3, glm::u16vec4(0, 1, 0, 0));
    triangle.weights.assign(3, weights);
    model.meshes.push_back({"triangle", {triangle}});
    model.skins.push_back({"skin", {1, 2}, {glm::mat4(1.0f), glm::mat4(1.0f)}, -1});
    return model;
}

TEST(Skinning, WeightsAreRenormalizedAndAllZeroWeightsStayRigid) {
    const Model half = hand_built_skin({0.25f, 0.25f, 0, 0});  // sums to 0.5: treated as (0.5, 0.5)
    const TriangleMesh a = flatten_posed(half, rest_pose(half));
    expect_near(a.positions[1], {1, 1.5f, 1}, 1e-6f);
    expect_near(a.normals[0], {0, 0, 1}, 1e-6f);

    const Model zero = hand_built_skin({0, 0, 0, 0});  // no joint: the node's own transform
    const TriangleMesh b = flatten_posed(zero, rest_pose(zero));
    expect_near(b.positions[1], {101, 0, 0}, 1e-6f);

    // Plain flatten ignores skins entirely.
    expect_near(flatten(half, rest_pose(half).world).positions[1], {101, 0, 0}, 1e-6f);
}

TEST(Skinning, CesiumManAllClipsMoveTheMeshKeepingTopology) {
    const Model man = load_gltf(models_dir() / "CesiumMan/CesiumMan.glb");
    const std::vector<int> clips = select_clips(man, {});
    ASSERT_EQ(clips.size(), 19u);
    const TriangleMesh rigid = flatten(man, world_transforms(man));
    const TriangleMesh rest = flatten_posed(man, evaluate_pose(man, {}, 0.0f));
    const TriangleMesh walking = flatten_posed(man, evaluate_pose(man, clips, 0.5f));
    // Its rest joint matrices are not identities (a z-up armature under a y-up root), yet
    // the skinned rest pose is the mesh as drawn without skinning.
    ASSERT_EQ(rest.positions.size(), rigid.positions.size());
    for (size_t v = 0; v < rest.positions.size(); ++v) expect_near(rest.positions[v], rigid.positions[v], 1e-5f);

    EXPECT_EQ(walking.indices, rest.indices);
    EXPECT_EQ(walking.indices, rigid.indices);
    ASSERT_EQ(walking.positions.size(), rest.positions.size());
    const Bounds b0 = compute_bounds(rest.positions), b1 = compute_bounds(walking.positions);
    EXPECT_GT(glm::length(b1.min - b0.min) + glm::length(b1.max - b0.max), 0.05f);
    for (const glm::vec3& n : walking.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    // Looping by the caller: t and t + duration give the same pose.
    const float duration = clips_duration(man, clips);
    EXPECT_EQ(flatten_posed(man, evaluate_pose(man, clips, std::fmod(0.5f + duration, duration))).positions,
              walking.positions);
}

TEST(Skinning, FoxWalkDiffersBetweenTwoTimes) {
    const Model fox = load_gltf(models_dir() / "Fox/Fox.glb");
    const std::vector<int> walk = {find_clip(fox, "Walk")};
    const TriangleMesh a = flatten_posed(fox, evaluate_pose(fox, walk, 0.1f));
    const TriangleMesh b = flatten_posed(fox, evaluate_pose(fox, walk, 0.4f));
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(a.indices, b.indices);
    float moved = 0.0f;
    for (size_t v = 0; v < a.positions.size(); ++v) moved = std::max(moved, glm::length(a.positions[v] - b.positions[v]));
    EXPECT_GT(moved, 1.0f);  // the fox is ~170 units long; its legs swing by several units
    // Fox's rest joint matrices are identities: skinned rest = rigid rest.
    const TriangleMesh rest = flatten_posed(fox, rest_pose(fox)), rigid = flatten(fox, world_transforms(fox));
    for (size_t v = 0; v < rest.positions.size(); ++v) expect_near(rest.positions[v], rigid.positions[v], 1e-3f);
}

TEST(WeldUpdate, RoundTripAndMovedPositions) {
    const Model man = load_gltf(models_dir() / "CesiumMan/CesiumMan.glb");
    const TriangleMesh rest = flatten_posed(man, rest_pose(man));
    const WeldedMesh welded = weld(rest);
    ASSERT_LT(welded.positions.size(), rest.positions.size());  // seams were welded

    WeldedMesh same = welded;
    update_positions(same, rest);
    EXPECT_EQ(same.positions, welded.positions);

    const TriangleMesh moved = flatten_posed(man, evaluate_pose(man, select_clips(man, {}), 1.0f));
    WeldedMesh updated = welded;
    update_positions(updated, moved);
    EXPECT_EQ(updated.faces, welded.faces);
    EXPECT_NE(updated.positions, welded.positions);
    std::vector<char> seen(welded.positions.size(), 0);
    for (size_t v = 0; v < moved.positions.size(); ++v) {
        const uint32_t w = welded.welded_index[v];
        if (!seen[w]) {
            EXPECT_EQ(updated.positions[w], moved.positions[v]) << "vertex " << v;  // the first one
            seen[w] = 1;
        }
        // Vertices split at seams carry the same skin, so they stay together.
        expect_near(updated.positions[w], moved.positions[v], 1e-5f);
    }

    TriangleMesh shorter = moved;
    shorter.positions.pop_back();
    EXPECT_NE(error_of([&] { update_positions(updated, shorter); }).find("update_positions"), std::string::npos);
}

TEST(CameraPaths, OrbitTurnsTheEyeAboutTheTarget) {
    const ViewCamera base{.eye = {1, 3, 7}, .target = {1, 2, 3}, .fov_deg = 35.0f};
    CameraPath path;
    path.kind = CameraPath::Kind::Orbit;
    path.orbit.degrees = 180.0f;
    const FrameRange range{10, 58};
    const PathTime half = frame_time(34, range, 24.0f);
    EXPECT_FLOAT_EQ(half.progress, 0.5f);
    EXPECT_FLOAT_EQ(half.seconds, 34.0f / 24.0f);
    const ViewCamera c = camera_at(path, base, half);
    // (0, 1, 4) from the target, turned 90° about +y, is (4, 1, 0).
    expect_near(c.eye, {5, 3, 3}, 1e-5f);
    EXPECT_EQ(c.target, base.target);
    EXPECT_NEAR(glm::length(c.eye - c.target), glm::length(base.eye - base.target), 1e-5f);
    expect_near(c.up, {0, 1, 0}, 1e-6f);
    EXPECT_EQ(c.fov_deg, 35.0f);
    expect_near(camera_at(path, base, frame_time(10, range, 24.0f)).eye, base.eye, 1e-6f);
    expect_near(camera_at(path, base, frame_time(58, range, 24.0f)).eye, {1, 3, -1}, 1e-5f);
    EXPECT_EQ(camera_at(CameraPath{}, base, half).eye, base.eye);  // Fixed

    EXPECT_EQ(frame_time(5, {5, 5}, 24.0f).progress, 0.0f);
    EXPECT_NE(error_of([] { (void)frame_time(0, {0, 1}, 0.0f); }).find("fps"), std::string::npos);
    EXPECT_NE(error_of([] { (void)frame_time(0, {3, 1}, 24.0f); }).find("ends before"), std::string::npos);
}

TEST(CameraPaths, KeyframesInterpolateBySecondsAndHoldAtTheEnds) {
    CameraPath path;
    path.kind = CameraPath::Kind::Keyframes;
    path.keyframes = {{.time = 1.0f, .eye = {0, 0, 4}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fov_deg = 30.0f},
                      {.time = 3.0f, .eye = {4, 0, 0}, .target = {0, 2, 0}, .up = {1, 0, 0}, .fov_deg = 50.0f}};
    const ViewCamera base{.znear = 0.5f, .zfar = 20.0f};
    const ViewCamera mid = camera_at(path, base, {.progress = 0.9f, .seconds = 1.5f});
    expect_near(mid.eye, {1, 0, 3}, 1e-6f);
    expect_near(mid.target, {0, 0.5f, 0}, 1e-6f);
    expect_near(mid.up, glm::normalize(glm::vec3(0.25f, 0.75f, 0)), 1e-6f);
    EXPECT_FLOAT_EQ(mid.fov_deg, 35.0f);
    EXPECT_EQ(mid.znear, 0.5f);
    EXPECT_EQ(mid.zfar, 20.0f);
    EXPECT_EQ(camera_at(path, base, {.seconds = 0.0f}).eye, glm::vec3(0, 0, 4));
    EXPECT_EQ(camera_at(path, base, {.seconds = 9.0f}).eye, glm::vec3(4, 0, 0));
    EXPECT_NE(error_of([&] { (void)camera_at(CameraPath{CameraPath::Kind::Keyframes, {}, {}}, base, {}); })
                  .find("no keyframes"),
              std::string::npos);
}

std::string scene_error(const std::string& json) {
    return error_of([&] { (void)parse_scene_json(json, "scenes/x.json"); });
}

TEST(SceneFileAnimation, ReadsAnimationAndCameraKeys) {
    const SceneDesc plain = parse_scene_json(R"({"model": "a.glb"})", "x.json");
    EXPECT_FALSE(plain.animation.play);
    EXPECT_EQ(plain.animation.fps, 24.0f);
    EXPECT_EQ(plain.camera_path.kind, CameraPath::Kind::Fixed);

    const SceneDesc walk = parse_scene_json(
        R"({"model": "a.glb", "animation": {"clip": "Walk", "fps": 30, "frames": [2, 40]},
            "camera": {"eye": [0, -5, 0], "target": [0, 0, 0], "up": [0, 0, 1], "orbit": 90}})",
        "x.json");
    EXPECT_TRUE(walk.animation.play);
    ASSERT_EQ(walk.animation.clips.size(), 1u);
    EXPECT_EQ(walk.animation.clips[0].kind, ClipChoice::Kind::Name);
    EXPECT_EQ(walk.animation.clips[0].name, "Walk");
    EXPECT_EQ(walk.animation.fps, 30.0f);
    ASSERT_TRUE(walk.animation.frames.has_value());
    EXPECT_EQ(walk.animation.frames->first, 2);
    EXPECT_EQ(walk.animation.frames->last, 40);
    ASSERT_TRUE(walk.camera.has_value());
    EXPECT_EQ(walk.camera_path.kind, CameraPath::Kind::Orbit);
    EXPECT_EQ(walk.camera_path.orbit.degrees, 90.0f);
    EXPECT_EQ(walk.camera_path.orbit.axis, glm::vec3(0, 0, 1));  // about the camera's up

    const SceneDesc indexed = parse_scene_json(R"({"model": "a.glb", "animation": {"clip": 3}})", "x.json");
    EXPECT_EQ(indexed.animation.clips.at(0).kind, ClipChoice::Kind::Index);
    EXPECT_EQ(indexed.animation.clips.at(0).index, 3);
    EXPECT_FALSE(indexed.animation.frames.has_value());
    EXPECT_EQ(parse_scene_json(R"({"model": "a.glb", "animation": {"clip": "all"}})", "x.json").animation.clips.at(0).kind,
              ClipChoice::Kind::All);

    // An orbit alone turns the framing camera about +y.
    const SceneDesc turntable = parse_scene_json(R"({"model": "a.glb", "camera": {"orbit": 360, "fov": 30}})", "x.json");
    EXPECT_FALSE(turntable.camera.has_value());
    EXPECT_EQ(turntable.camera_path.kind, CameraPath::Kind::Orbit);
    EXPECT_EQ(turntable.camera_path.orbit.axis, glm::vec3(0, 1, 0));
    EXPECT_EQ(turntable.fov_deg, 30.0f);

    const SceneDesc keyed = parse_scene_json(R"({"model": "a.glb", "fov": 45, "camera_path": {"keyframes": [
        {"time": 0, "eye": [0, 0, 5], "target": [0, 0, 0]},
        {"time": 2.5, "eye": [5, 0, 0], "target": [0, 1, 0], "up": [0, 1, 0.1], "fov": 20}]}})",
                                             "x.json");
    EXPECT_FALSE(keyed.camera.has_value());
    ASSERT_EQ(keyed.camera_path.kind, CameraPath::Kind::Keyframes);
    ASSERT_EQ(keyed.camera_path.keyframes.size(), 2u);
    EXPECT_EQ(keyed.camera_path.keyframes[0].fov_deg, 45.0f);  // the scene's fov
    EXPECT_EQ(keyed.camera_path.keyframes[1].time, 2.5f);
    EXPECT_EQ(keyed.camera_path.keyframes[1].up, glm::vec3(0, 1, 0.1f));
    EXPECT_EQ(keyed.camera_path.keyframes[1].fov_deg, 20.0f);
}

TEST(SceneFileAnimation, ErrorsNameTheKey) {
    const auto starts = [](const std::string& error, const std::string& prefix) {
        EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
    };
    starts(scene_error(R"({"model": "a.glb", "animation": {"clip": 0, "speed": 2}})"),
           "scenes/x.json: animation.speed: unknown key (known here: clip, fps, frames)");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"clip": true}})"),
              "scenes/x.json: animation.clip: expected a clip name, a clip index or \"all\" (or an array of them, one per model), "
              "got boolean true");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"clip": 1.5}})"),
              "scenes/x.json: animation.clip: expected a clip name, a clip index or \"all\" (or an array of them, one per model), "
              "got number 1.5");
    starts(scene_error(R"({"model": "a.glb", "animation": {"clip": -1}})"), "scenes/x.json: animation.clip: clip index");
    starts(scene_error(R"({"model": "a.glb", "animation": {"clip": ""}})"), "scenes/x.json: animation.clip: empty name");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"fps": 0}})"),
              "scenes/x.json: animation.fps: must be a number of frames a second over 0, up to 1000, got 0");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"fps": -24}})"),
              "scenes/x.json: animation.fps: must be a number of frames a second over 0, up to 1000, got -24");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"frames": [10, 4]}})"),
              "scenes/x.json: animation.frames: last frame 4 is before first frame 10");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"frames": [1]}})"),
              "scenes/x.json: animation.frames: expected [first, last] frame numbers");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": "Walk"})"), "scenes/x.json: animation: must be an object");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera": {"orbit": "fast", "eye": [0,0,1], "target": [0,0,0]}})"),
              "scenes/x.json: camera.orbit: expected a number, got string");
    starts(scene_error(R"({"model": "a.glb", "camera": {"orbit": 90, "near": 1}})"), "scenes/x.json: camera.near: needs eye and target");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera": {"orbit": 90, "eye": [0,0,1]}})"),
              "scenes/x.json: camera.target: required");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera": {"target": [0,0,0]}})"), "scenes/x.json: camera.eye: required");

    const std::string key0 = R"({"time": 0, "eye": [0,0,5], "target": [0,0,0]})";
    starts(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": [)" + key0 + R"(], "loop": true}})"),
           "scenes/x.json: camera_path.loop: unknown key");
    starts(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": [{"time": 0, "eye": [0,0,5], "target": [0,0,0], "roll": 3}]}})"),
           "scenes/x.json: camera_path.keyframes[0].roll: unknown key");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": []}})"),
              "scenes/x.json: camera_path.keyframes: expected a non-empty array of keyframes");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera_path": {}})"), "scenes/x.json: camera_path.keyframes: required");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": [{"time": 1, "eye": [0,0,5]}]}})"),
              "scenes/x.json: camera_path.keyframes[0].target: required");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": [)" + key0 + ", " + key0 + "]}}"),
              "scenes/x.json: camera_path.keyframes[1].time: must be later than the previous keyframe's (0 after 0)");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera_path": {"keyframes": [{"time": 0, "eye": [0,0,5], "target": [0,0,5]}]}})"),
              "scenes/x.json: camera_path.keyframes[0]: eye and target coincide");
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "camera": {"eye": [0,0,1], "target": [0,0,0]}, "camera_path": {"keyframes": [)" +
                          key0 + "]}}"),
              "scenes/x.json: camera_path: cannot be combined with camera (the keyframes set the camera)");
}

// Models seldom share clip names: "clip" takes one choice per model, and one name for a
// scene of several models names the model that lacks it and the way out.
TEST(SceneFileAnimation, ClipPerModel) {
    const std::filesystem::path fox = models_dir() / "Fox/Fox.glb", man = models_dir() / "CesiumMan/CesiumMan.glb";
    const std::string both = R"({"model": [")" + fox.string() + R"(", ")" + man.string() + R"("], "animation": )";
    const SceneDesc per_model = parse_scene_json(both + R"({"clip": ["Walk", 0]}})", "scenes/x.json");
    ASSERT_EQ(per_model.animation.clips.size(), 2u);
    EXPECT_EQ(clip_of_model(per_model.animation, 0).name, "Walk");
    EXPECT_EQ(clip_of_model(per_model.animation, 1).index, 0);
    const LoadedScene scene = load_scene(per_model);
    // Both move: each model's triangles differ between two times.
    const TriangleMesh a = pose_scene(scene, 0.2f), b = pose_scene(scene, 0.6f);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    const size_t fox_vertices = flatten_posed(scene.models[0], rest_pose(scene.models[0])).positions.size();
    float fox_moved = 0.0f, man_moved = 0.0f;
    for (size_t i = 0; i < a.positions.size(); ++i) {
        float& moved = i < fox_vertices ? fox_moved : man_moved;
        moved = std::max(moved, glm::length(a.positions[i] - b.positions[i]));
    }
    EXPECT_GT(fox_moved, 1.0f);     // the Fox is about 100 units long
    EXPECT_GT(man_moved, 0.01f);    // CesiumMan about 1.5
    // The longer of the two clips: CesiumMan's 2 s, the Fox's Walk 0.71 s.
    EXPECT_EQ(animation_duration(scene), std::max(clip_duration(scene.models[0], find_clip(scene.models[0], "Walk")),
                                                  clip_duration(scene.models[1], 0)));

    const std::string one = error_of([&] { (void)load_scene(parse_scene_json(both + R"({"clip": "Walk"}})", "scenes/x.json")); });
    EXPECT_EQ(one.rfind("scenes/x.json: animation.clip: one clip for every model of the scene, and ", 0), 0u) << one;
    EXPECT_NE(one.find("CesiumMan.glb: no animation clip named \"Walk\""), std::string::npos) << one;
    EXPECT_NE(one.find("; give one per model, in \"model\" order"), std::string::npos) << one;
    // A clip the model lacks is named against the scene key that asked for it.
    const std::string alone = error_of([&] {
        (void)load_scene(parse_scene_json(R"({"model": ")" + fox.string() + R"(", "animation": {"clip": "Jump"}})", "scenes/x.json"));
    });
    EXPECT_EQ(alone.rfind("scenes/x.json: animation.clip: ", 0), 0u) << alone;
    EXPECT_NE(alone.find("Fox.glb: no animation clip named \"Jump\""), std::string::npos) << alone;
    const std::string second = error_of([&] { (void)load_scene(parse_scene_json(both + R"({"clip": ["Walk", 50]}})", "scenes/x.json")); });
    EXPECT_EQ(second.rfind("scenes/x.json: animation.clip[1]: ", 0), 0u) << second;
    EXPECT_NE(second.find("CesiumMan.glb: no animation clip 50 (clips: 0 to 18 (unnamed))"), std::string::npos) << second;
    EXPECT_EQ(scene_error(R"({"model": ["a.glb", "b.glb"], "animation": {"clip": ["Walk", 0, 1]}})"),
              "scenes/x.json: animation.clip: 3 clips for 2 models (one per model, in \"model\" order, or one for all)");
    EXPECT_EQ(parse_scene_json(R"({"model": ["a.glb", "b.glb"], "animation": {"clip": ["Walk"]}})", "x.json")
                  .animation.clips.size(),
              1u);  // one for all, as a plain "Walk"
    EXPECT_EQ(scene_error(R"({"model": "a.glb", "animation": {"clip": []}})"),
              "scenes/x.json: animation.clip: an empty array (give one clip per model, or one for all)");
    EXPECT_EQ(scene_error(R"({"model": ["a.glb", "b.glb"], "animation": {"clip": ["Walk", true]}})"),
              "scenes/x.json: animation.clip[1]: expected a clip name, a clip index or \"all\", got boolean true");

    // Written back as it was read.
    const SceneDesc again = parse_scene_json(scene_json(per_model, scene.camera, "/"), "scenes/y.json");
    ASSERT_EQ(again.animation.clips.size(), 2u);
    EXPECT_EQ(again.animation.clips[0].name, "Walk");
    EXPECT_EQ(again.animation.clips[1].kind, ClipChoice::Kind::Index);
}

// A model is drawn where its file places it: a second copy would lie on the first.
TEST(SceneFileAnimation, AModelListedTwiceIsRefused) {
    EXPECT_EQ(scene_error(R"({"model": ["a.glb", "b.glb", "./a.glb"]})"),
              "scenes/x.json: model: \"./a.glb\" is listed twice (items 0 and 2); a scene draws each model where its file "
              "places it, so a second copy would lie on the first");
}

}  // namespace
}  // namespace lw
