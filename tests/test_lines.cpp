// Feature lines: analytic checks, GPU against the CPU reference, SVG output.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "core/error.h"
#include "core/random.h"
#include "io/image_io.h"
#include "lines/chaining.h"
#include "lines/extract_gpu.h"
#include "lines/extract_reference.h"
#include "lines/face_scan.h"
#include "lines/svg_export.h"
#include "vector/xml.h"
#include "render/frame_renderer.h"
#include "scene/scene.h"
#include "geometry/test_meshes.h"
#include "test_support.h"

namespace lw {
namespace {

class LinesTest : public test::GpuTest {};

// The silhouette of a sphere seen in perspective is the circle of tangency: on screen a
// circle around the projected centre, of radius f·tan(asin(R/d)) for a camera looking at
// the centre from distance d (f = focal length in pixels).
TEST_F(LinesTest, SphereSilhouetteIsTheAnalyticCircle) {
    const float radius = 1.3f, distance = 6.0f, fov = 40.0f;
    const int width = 400, height = 300;
    const TriangleMesh sphere = make_icosphere(radius, 6, glm::vec3(0.5f, -0.2f, 0.1f));
    const Bounds bounds = compute_bounds(sphere.positions);
    const ViewCamera view{.eye = glm::vec3(0.5f, -0.2f, 0.1f) + distance * glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f)),
                          .target = glm::vec3(0.5f, -0.2f, 0.1f),
                          .fov_deg = fov};
    const CameraMatrices camera = camera_matrices(view, float(width) / float(height), bounds);

    FrameRenderer renderer(ctx(), width, height);
    renderer.set_mesh(sphere, true, 45.0f);
    LinesDesc lines;
    const Frame frame = renderer.render(camera, view.eye, SurfaceStyle{}, lines);

    std::vector<const ScreenPath*> silhouettes;
    for (const auto& p : frame.screen_paths) {
        EXPECT_NE(p.type, LineType::Suggestive) << "a sphere has no suggestive contours (kr > 0 everywhere)";
        if (p.type == LineType::Silhouette) silhouettes.push_back(&p);
    }
    ASSERT_EQ(silhouettes.size(), 1u);
    EXPECT_TRUE(silhouettes[0]->closed);
    EXPECT_TRUE(silhouettes[0]->visible);

    const float focal = 0.5f * float(height) / std::tan(glm::radians(fov) * 0.5f);
    const float expected_radius = focal * std::tan(std::asin(radius / distance));
    const glm::vec2 center(width * 0.5f, height * 0.5f);
    float worst = 0.0f;
    for (const ScreenSample& s : silhouettes[0]->samples)
        worst = std::max(worst, std::abs(glm::length(s.pixel - center) - expected_radius));
    EXPECT_LT(worst, 1.0f) << "expected radius " << expected_radius << " px";
    // The loop goes all the way round: its length is the circle's circumference.
    const float length = silhouettes[0]->samples.back().s;
    EXPECT_NEAR(length, 2.0f * std::numbers::pi_v<float> * expected_radius, 0.02f * expected_radius * 6.3f);
}

// GPU extraction equals the CPU reference: same segments (after sorting), endpoints within
// 1e-4, same keys, faces and alphas; with the default types, with all ten (rtsc's other
// lines and material boundaries; contours `auto`), of which those in `present` must be
// found, and with the default types and mesh contours.
struct GpuCase {
    std::string model;
    glm::vec3 direction;  // from the centre towards the eye
    uint32_t present = 0;  // bits (1 << LineType) that all-types extraction must find here
};

constexpr uint32_t kRtscOthers = (1u << uint32_t(LineType::Ridge)) | (1u << uint32_t(LineType::Valley)) |
                                 (1u << uint32_t(LineType::ApparentRidge)) |
                                 (1u << uint32_t(LineType::SuggestiveHighlight)) |
                                 (1u << uint32_t(LineType::PrincipalHighlight));
constexpr uint32_t kBoundaries = 1u << uint32_t(LineType::MaterialBoundary);

class LinesGpuMatchesCpu : public test::GpuTest, public ::testing::WithParamInterface<GpuCase> {};

TEST_P(LinesGpuMatchesCpu, SameSegments) {
    const GpuCase& c = GetParam();
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models" / c.model));
    const LineMesh line_mesh = build_line_mesh(scene.mesh, 45.0f);
    const glm::vec3 eye = scene.bounds.center() + 3.0f * scene.bounds.radius() * glm::normalize(c.direction);
    LineParams every, mesh_contours;
    set_line_types(every, kAllLineTypes);
    every.contours = ContourMode::Auto;
    mesh_contours.contours = ContourMode::Mesh;
    LineExtractor extractor(ctx());
    extractor.set_mesh(line_mesh);
    for (const LineParams& params : {LineParams{}, every, mesh_contours}) {
        const bool all = params.ridges;
        std::vector<LineSegment> cpu = extract_lines_reference(line_mesh, eye, params);
        std::vector<LineSegment> gpu = extractor.extract(eye, params);
        sort_segments(cpu);
        sort_segments(gpu);
        ASSERT_GT(cpu.size(), 10u);
        ASSERT_EQ(gpu.size(), cpu.size()) << (all ? "all types" : "default types") << ", contours "
                                          << contour_mode_name(params.contours);
        std::array<size_t, kLineTypeCount> by_type{};
        for (size_t i = 0; i < cpu.size(); ++i) {
            const LineSegment &a = cpu[i], &b = gpu[i];
            ASSERT_EQ(a.type, b.type) << i;
            ASSERT_EQ(a.face, b.face) << i;
            EXPECT_EQ(a.key0, b.key0) << i;
            EXPECT_EQ(a.key1, b.key1) << i;
            EXPECT_EQ(a.other_face, kNoFace) << i;  // no extracted type lies on a second surface
            EXPECT_EQ(b.other_face, kNoFace) << i;
            EXPECT_LE(glm::length(glm::vec3(a.bary0) - glm::vec3(b.bary0)), 1e-4f) << i;
            EXPECT_LE(glm::length(glm::vec3(a.bary1) - glm::vec3(b.bary1)), 1e-4f) << i;
            EXPECT_LE(glm::length(glm::vec3(a.p0) - glm::vec3(b.p0)), 1e-4f) << i << " " << line_type_name(LineType(a.type));
            EXPECT_LE(glm::length(glm::vec3(a.p1) - glm::vec3(b.p1)), 1e-4f) << i << " " << line_type_name(LineType(a.type));
            EXPECT_NEAR(a.p0.w, b.p0.w, 1e-4f) << i;
            EXPECT_NEAR(a.p1.w, b.p1.w, 1e-4f) << i;
            ++by_type[a.type];
        }
        for (int t = 0; t < kLineTypeCount && all; ++t) {
            RecordProperty(line_type_name(LineType(t)), int(by_type[size_t(t)]));
            if (c.present & (1u << t)) {
                EXPECT_GT(by_type[size_t(t)], 0u) << line_type_name(LineType(t)) << ": none to compare";
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Models, LinesGpuMatchesCpu,
    ::testing::Values(GpuCase{"spot/spot.glb", {0.8f, 0.3f, -0.7f}, kRtscOthers}, GpuCase{"spot/spot.glb", {-1.0f, 0.1f, 0.2f}},
                      GpuCase{"LeePerrySmith/LeePerrySmith.glb", {0.0f, 0.1f, 1.0f}, kRtscOthers},
                      GpuCase{"LeePerrySmith/LeePerrySmith.glb", {0.7f, -0.2f, 0.5f}, kRtscOthers},
                      GpuCase{"Suzanne/Monkey.glb", {0.3f, 0.2f, 1.0f}, kRtscOthers},
                      GpuCase{"craft_speederD/craft_speederD.gltf", {1.0f, 0.6f, 0.4f}},
                      GpuCase{"FlightHelmet/FlightHelmet.gltf", {0.2f, 0.1f, 1.0f}, kRtscOthers},
                      GpuCase{"CesiumMilkTruck/CesiumMilkTruck.glb", {0.6f, 0.4f, 1.0f}, kBoundaries}),
    [](const auto& param_info) { return "Case" + std::to_string(param_info.index); });

// An animation pose uploads only the vertices (set_pose): the GPU then extracts the posed
// mesh's lines, all types, as the reference does; a mesh of other counts is refused.
TEST_F(LinesTest, APoseUploadsOnlyTheVerticesAndExtractsThePosedLines) {
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/spot/spot.glb"));
    LineMesh lm = build_line_mesh(scene.mesh, 45.0f);
    LineExtractor extractor(ctx());
    extractor.set_mesh(lm);
    TriangleMesh moved = scene.mesh;
    for (glm::vec3& p : moved.positions) p += glm::vec3(0.0f, 0.08f * std::sin(4.0f * p.x), 0.05f * p.y);
    pose_line_mesh(lm, moved);
    extractor.set_pose(lm);
    LineParams params;
    set_line_types(params, kAllLineTypes);
    const glm::vec3 eye = scene.bounds.center() + 3.0f * scene.bounds.radius() * glm::vec3(0.6f, 0.3f, 0.74f);
    std::vector<LineSegment> cpu = extract_lines_reference(lm, eye, params), gpu = extractor.extract(eye, params);
    sort_segments(cpu);
    sort_segments(gpu);
    ASSERT_GT(cpu.size(), 100u);
    ASSERT_EQ(gpu.size(), cpu.size());
    for (size_t i = 0; i < cpu.size(); ++i) {
        ASSERT_EQ(cpu[i].face, gpu[i].face) << i;
        EXPECT_LE(glm::length(glm::vec3(cpu[i].p0) - glm::vec3(gpu[i].p0)), 1e-4f) << i;
    }
    const LineMesh other = build_line_mesh(make_icosphere(1.0f, 2), 45.0f);
    EXPECT_THROW(extractor.set_pose(other), Error);
}

TEST_F(LinesTest, SvgIsValidAndLinesUpWithThePng) {
    const int width = 320, height = 240;
    SceneDesc desc = scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb");
    desc.width = width;
    desc.height = height;
    desc.style.draw_surface = false;  // lines over white
    const LoadedScene scene = load_scene(desc);
    const CameraMatrices camera = camera_matrices(scene.camera, float(width) / float(height), scene.bounds);
    FrameRenderer renderer(ctx(), width, height);
    renderer.set_mesh(scene.mesh, true, desc.lines.params.crease_angle_deg);
    const Frame frame = renderer.render(camera, scene.camera.eye, desc.style, desc.lines);

    const std::string svg = lines_svg(width, height, line_set_svg_groups(desc.lines, frame));
    // Well-formed XML (pugixml, as the SVG readers use), with every group.
    std::unique_ptr<pugi::xml_document> doc;
    ASSERT_NO_THROW(doc = parse_xml(svg, "lines.svg"));
    EXPECT_NE(svg.find("viewBox=\"0 0 320 240\""), std::string::npos);
    for (const char* id : {"silhouette", "suggestive", "crease", "border"})
        EXPECT_NE(svg.find("<g id=\"" + std::string(id) + "\""), std::string::npos) << id;

    // Every SVG point lies on drawn ink in the PNG (within one pixel).
    size_t total = 0, on_ink = 0;
    for (const pugi::xpath_node& polyline : doc->select_nodes("//polyline")) {
        std::istringstream list(polyline.node().attribute("points").value());
        std::string pair;
        while (list >> pair) {
            float x = 0, y = 0;
            ASSERT_EQ(std::sscanf(pair.c_str(), "%f,%f", &x, &y), 2) << pair;
            ++total;
            bool ink = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int px = int(x) + dx, py = int(y) + dy;
                    if (px < 0 || py < 0 || px >= width || py >= height) continue;
                    ink |= frame.image.color.at(px, py)[0] < 200;
                }
            on_ink += ink;
        }
    }
    ASSERT_GT(total, 100u);
    EXPECT_GE(double(on_ink) / double(total), 0.98) << on_ink << " of " << total;
}

TEST_F(LinesTest, HiddenLinesAreHiddenAndCanBeDrawn) {
    // Two spheres, one behind the other: the far one's silhouette is partly hidden.
    TriangleMesh mesh = make_icosphere(1.0f, 4);
    append_mesh(mesh, make_icosphere(1.0f, 4, glm::vec3(0.8f, 0.0f, -3.0f)));
    const Bounds bounds = compute_bounds(mesh.positions);
    const ViewCamera view{.eye = {0, 0, 6}, .target = {0.4f, 0, -1.5f}, .fov_deg = 40};
    const CameraMatrices camera = camera_matrices(view, 4.0f / 3.0f, bounds);
    FrameRenderer renderer(ctx(), 320, 240);
    renderer.set_mesh(mesh, true, 45.0f);
    LinesDesc lines;
    const Frame frame = renderer.render(camera, view.eye, SurfaceStyle{}, lines);
    size_t hidden_samples = 0, visible_samples = 0;
    for (const auto& p : frame.screen_paths) (p.visible ? visible_samples : hidden_samples) += p.samples.size();
    EXPECT_GT(hidden_samples, 20u);
    EXPECT_GT(visible_samples, hidden_samples);

    // Dashed hidden lines add ink that the default does not.
    lines.hidden = HiddenLines::Dashed;
    const Frame dashed = renderer.render(camera, view.eye, SurfaceStyle{}, lines);
    auto ink = [](const ImageRGBA8& im) {
        size_t n = 0;
        for (size_t i = 0; i < im.pixels.size(); i += 4) n += im.pixels[i] < 60;
        return n;
    };
    EXPECT_GT(ink(dashed.image.color), ink(frame.image.color) + 20);
}

// Threads over face blocks merge in block order: the same segments, bit for bit, in the same
// order, at any thread count (18 blocks of 1024 faces here), and a workspace kept from view
// to view (as a frame keeps it) changes nothing. With mesh contours too: each member finds
// the facing of the faces in proportion to its vertices, so the shares must tile the faces.
TEST(LinesThreads, SameSegmentsInTheSameOrderAtAnyThreadCount) {
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb"));
    const LineMesh lm = build_line_mesh(scene.mesh, 30.0f);
    for (const ContourMode contours : {ContourMode::Smooth, ContourMode::Mesh, ContourMode::Auto}) {
        SCOPED_TRACE(contour_mode_name(contours));
        LineParams params;
        params.creases = params.borders = true;
        params.contours = contours;
        const std::vector<LineSegment> one = extract_lines_reference(lm, scene.camera.eye, params, 1);
        size_t suggestive = 0;
        for (const LineSegment& s : one) suggestive += s.type == uint32_t(LineType::Suggestive);
        ASSERT_GT(one.size(), 200u);
        EXPECT_GT(suggestive, 10u);
        ExtractWorkspace workspace;
        std::vector<LineSegment> kept;
        for (size_t threads : {2u, 3u, 7u, 1u, 2u}) {
            const std::vector<LineSegment> many = extract_lines_reference(lm, scene.camera.eye, params, threads);
            ASSERT_EQ(many.size(), one.size()) << threads << " threads";
            EXPECT_EQ(std::memcmp(many.data(), one.data(), one.size() * sizeof(LineSegment)), 0)
                << threads << " threads";
            // Another view first, so that the kept output and scratch hold other data.
            const glm::vec3 other_eye = scene.camera.eye + glm::vec3(3.0f, -1.0f, 0.0f);
            extract_lines_reference(lm, other_eye, params, kept, workspace, threads);
            extract_lines_reference(lm, scene.camera.eye, params, kept, workspace, threads);
            ASSERT_EQ(kept.size(), one.size()) << threads << " threads, kept workspace";
            EXPECT_EQ(std::memcmp(kept.data(), one.data(), one.size() * sizeof(LineSegment)), 0)
                << threads << " threads";
        }
    }
}

// Mesh contours keep each face's normal and first corner per pose (ExtractWorkspace::
// FacePlanes): a pose's first view computes the facing from the corners, its second fills
// the arrays, later views read them. A workspace kept across a new pose (an animation frame)
// finds the new pose's facing at each of those steps: the same segments as a fresh
// workspace, and not the old pose's.
TEST(LinesThreads, MeshContoursFollowANewPoseWithAKeptWorkspace) {
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/spot/spot.glb"));
    LineMesh lm = build_line_mesh(scene.mesh, 45.0f);
    LineParams params;
    params.contours = ContourMode::Mesh;
    const glm::vec3 eye = scene.bounds.center() + 3.0f * scene.bounds.radius() * glm::vec3(0.6f, 0.3f, 0.74f);
    ExtractWorkspace kept;
    std::vector<LineSegment> first_pose, view;
    const auto same = [](const std::vector<LineSegment>& a, const std::vector<LineSegment>& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(LineSegment)) == 0;
    };
    for (int k = 0; k < 3; ++k) {  // corners, fill, stream
        extract_lines_reference(lm, eye, params, view, kept);
        if (k == 0) first_pose = view;
        EXPECT_TRUE(same(view, first_pose)) << "view " << k << " of the first pose";
    }
    TriangleMesh moved = scene.mesh;
    for (glm::vec3& p : moved.positions) p += glm::vec3(0.0f, 0.08f * std::sin(4.0f * p.x), 0.05f * p.y);
    pose_line_mesh(lm, moved);
    const std::vector<LineSegment> fresh = extract_lines_reference(lm, eye, params);
    EXPECT_FALSE(same(fresh, first_pose)) << "the pose moved the contours";
    for (int k = 0; k < 3; ++k) {
        extract_lines_reference(lm, eye, params, view, kept);
        EXPECT_TRUE(same(view, fresh)) << "view " << k << " of the new pose";
    }
}

// The face scan finds the same candidate faces eight at a time (AVX2, where the CPU has
// it) as one by one, on every combination of sign bytes: random bytes on random faces,
// ranges that do not start or end on a multiple of eight.
TEST(LinesThreads, VectorFaceScanEqualsTheScalarScan) {
    Rng rng(7);
    const size_t vertices = 500, faces = 4000;
    std::vector<uint8_t> signs(vertices + kSignPadding, 0);
    for (size_t v = 0; v < vertices; ++v) signs[v] = uint8_t(rng.index(256));
    std::vector<glm::uvec3> corners(faces);
    for (glm::uvec3& c : corners) c = {uint32_t(rng.index(vertices)), uint32_t(rng.index(vertices)), uint32_t(rng.index(vertices))};
    for (const auto& [begin, end] : {std::pair{0u, 4000u}, std::pair{3u, 1030u}, std::pair{17u, 22u}, std::pair{5u, 5u}}) {
        std::vector<uint32_t> s1(end - begin + 8), c1(end - begin + 8), s2(end - begin + 8), c2(end - begin + 8);
        const FaceCandidates a = scan_faces_scalar(corners.data(), begin, end, signs.data(), s1.data(), c1.data());
        const FaceCandidates b = scan_faces(corners.data(), begin, end, signs.data(), s2.data(), c2.data());
        ASSERT_EQ(a.suggestive, b.suggestive) << begin << ".." << end;
        ASSERT_EQ(a.contour, b.contour) << begin << ".." << end;
        EXPECT_TRUE(std::equal(s1.begin(), s1.begin() + std::ptrdiff_t(a.suggestive), s2.begin()));
        EXPECT_TRUE(std::equal(c1.begin(), c1.begin() + std::ptrdiff_t(a.contour), c2.begin()));
        if (end - begin == 4000) {
            EXPECT_GT(a.suggestive, 400u) << "the bytes give both kinds of candidate";
            EXPECT_GT(a.contour, 400u);
        }
    }
}

}  // namespace
}  // namespace lw
