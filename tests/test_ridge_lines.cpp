// rtsc's other lines and material boundaries (issue 16 items 1 and 3): each on a generated
// surface where it lies at a known place, the GPU pass against the C++ reference on shared
// models, and thread counts.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "geometry/test_meshes.h"
#include "lines/chaining.h"
#include "lines/extract_reference.h"
#include "scene/scene.h"
#include "core/error.h"
#include "scene/scene_file.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

LineParams only(LineType type) {
    LineParams params;
    set_line_types(params, 1u << uint32_t(type));
    return params;
}

LineParams every_type() {
    LineParams params;
    set_line_types(params, kAllLineTypes);
    return params;
}

// Largest |coordinate − at| over the segments' endpoints, and their summed length.
struct Placement {
    float worst = 0.0f;
    float length = 0.0f;
    size_t segments = 0;
};

template <class Distance>
Placement place(const std::vector<LineSegment>& segments, LineType type, Distance distance) {
    Placement p;
    for (const LineSegment& s : segments) {
        EXPECT_EQ(s.type, uint32_t(type));
        p.worst = std::max({p.worst, distance(glm::vec3(s.p0)), distance(glm::vec3(s.p1))});
        p.length += glm::length(glm::vec3(s.p1) - glm::vec3(s.p0));
        ++p.segments;
    }
    return p;
}

// A smoothed roof z = ∓a·sqrt(x² + b²) over [−1, 1] × [−0.5, 0.5]: its cross-section's
// curvature peaks at x = 0 (|k1| = a/b there) and k2 = 0 along the ridge, so the ridge
// (valley, for the upturned roof) is the line x = 0. 161 × 40 cells, h = 2/161: the crest
// runs between two columns of vertices, not on one (on a column the symmetric estimates
// of the derivative are exactly 0 at both ends of an edge and rtsc's crossing is 0/0).
TriangleMesh roof(float sign) {
    constexpr double a = 0.5, b = 0.05;
    return make_height_field([&](double x, double) { return -sign * a * std::sqrt(x * x + b * b); }, {-1.0f, -0.5f},
                             {1.0f, 0.5f}, 161, 40);
}

TEST(RidgeLines, RidgeAndValleyLieOnTheRoofsCrest) {
    constexpr float h = 2.0f / 161.0f;
    for (const float sign : {1.0f, -1.0f}) {
        const LineMesh lm = build_line_mesh(roof(sign), 45.0f);
        const glm::vec3 eye(0.4f, 0.3f, 3.0f);
        const LineType wanted = sign > 0.0f ? LineType::Ridge : LineType::Valley;
        const LineType other = sign > 0.0f ? LineType::Valley : LineType::Ridge;
        const std::vector<LineSegment> lines = extract_lines_reference(lm, eye, only(wanted));
        const Placement p = place(lines, wanted, [](const glm::vec3& x) { return std::abs(x.x); });
        // Within half a cell of x = 0 and along the whole length.
        EXPECT_LE(p.worst, 0.5f * h) << line_type_name(wanted);
        EXPECT_GT(p.length, 0.95f) << line_type_name(wanted) << ": the crest is 1 long";
        EXPECT_TRUE(extract_lines_reference(lm, eye, only(other)).empty())
            << "a " << line_type_name(wanted) << " is not a " << line_type_name(other);
    }
}

// Seen from straight above the crest (x = 0), the view-dependent curvature of the roof is
// largest on the crest too (the surface is symmetric about x = 0 and so is the view), so the
// apparent ridge is the same line.
TEST(RidgeLines, ApparentRidgeLiesOnTheRoofsCrestSeenFromAbove) {
    constexpr float h = 2.0f / 161.0f;
    const LineMesh lm = build_line_mesh(roof(1.0f), 45.0f);
    const std::vector<LineSegment> lines = extract_lines_reference(lm, glm::vec3(0.0f, 0.2f, 3.0f), only(LineType::ApparentRidge));
    const Placement p = place(lines, LineType::ApparentRidge, [](const glm::vec3& x) { return std::abs(x.x); });
    // Between the two columns of vertices next to the crest (some pieces end on them:
    // rtsc's crossings along the crest-parallel edges, where t1's estimate turns).
    EXPECT_LE(p.worst, 0.5f * h * 1.001f);
    EXPECT_GT(p.length, 0.9f);
}

// A thin open cylinder (radius R about z): k1 = 1/R around, k2 = 0 along. Its principal
// highlight is where the view looks along e2, v·e1 = 0: for an eye at d·(cos β, sin β) and
// any height that is −d·sin(φ − β) = 0 at every height, the generator φ = β facing the eye.
// β is half a cell, between two columns of vertices (on a column v·e1 is 0 at both ends of
// an edge, and rtsc draws nothing on a face crossed three times).
TEST(RidgeLines, PrincipalHighlightIsTheGeneratorFacingTheEye) {
    constexpr float radius = 0.25f;
    const LineMesh lm = build_line_mesh(make_open_cylinder(radius, 4.0f, 96, 64), 60.0f);
    const float beta = std::numbers::pi_v<float> / 96.0f;
    const glm::vec2 facing(std::cos(beta), std::sin(beta));
    const std::vector<LineSegment> lines =
        extract_lines_reference(lm, glm::vec3(3.0f * facing, 2.0f), only(LineType::PrincipalHighlight));
    std::vector<LineSegment> inside;  // away from the open ends, whose curvature the border skews
    for (const LineSegment& s : lines)
        if (std::min(s.p0.z, s.p1.z) > 0.25f && std::max(s.p0.z, s.p1.z) < 3.75f) inside.push_back(s);
    const Placement p = place(inside, LineType::PrincipalHighlight, [&](const glm::vec3& x) {
        return glm::length(glm::vec2(x.x, x.y) - radius * facing);
    });
    const float cell = 2.0f * std::numbers::pi_v<float> * radius / 96.0f;
    EXPECT_LE(p.worst, 0.5f * cell);
    EXPECT_GT(p.length, 0.95f * 3.5f);
}

// A wave z = A·sin(ωx) seen obliquely: kr = 0 on its inflection lines x = nπ/ω; where
// D_w kr > 0 they are suggestive contours, where it is < 0 suggestive highlights, in turn
// from one inflection to the next.
TEST(RidgeLines, SuggestiveHighlightsAreTheOtherInflections) {
    constexpr double amplitude = 0.2, omega = 3.0;
    const TriangleMesh wave = make_height_field([&](double x, double) { return amplitude * std::sin(omega * x); },
                                                {-2.0f, -1.0f}, {2.0f, 1.0f}, 200, 100);
    const LineMesh lm = build_line_mesh(wave, 60.0f);
    const glm::vec3 eye(4.0f, 0.3f, 2.5f);
    const float period = float(std::numbers::pi / omega);
    const auto inflection = [&](const glm::vec3& x) { return int(std::lround(x.x / period)); };
    const auto off_inflection = [&](const glm::vec3& x) { return std::abs(x.x - float(inflection(x)) * period); };
    std::vector<int> highlight_lines, contour_lines;
    for (const auto& [type, found] : {std::pair{LineType::SuggestiveHighlight, &highlight_lines},
                                      std::pair{LineType::Suggestive, &contour_lines}}) {
        std::vector<LineSegment> lines;
        for (const LineSegment& s : extract_lines_reference(lm, eye, only(type)))
            if (std::abs(s.p0.y) < 0.8f && std::abs(s.p0.x) < 1.8f) lines.push_back(s);  // off the borders
        const Placement p = place(lines, type, off_inflection);
        EXPECT_LE(p.worst, 0.02f) << line_type_name(type) << " (cells are 0.02 wide)";
        for (const LineSegment& s : lines) found->push_back(inflection(glm::vec3(s.p0)));
        std::sort(found->begin(), found->end());
        found->erase(std::unique(found->begin(), found->end()), found->end());
    }
    // (Here: highlights on x = −π/ω, contours on x = 0; the third line, x = π/ω, is under
    // both thresholds.)
    EXPECT_GE(highlight_lines.size(), 1u);
    EXPECT_GE(contour_lines.size(), 1u);
    for (int n : highlight_lines) {
        EXPECT_EQ(std::count(contour_lines.begin(), contour_lines.end(), n), 0) << "inflection " << n << " has both";
        for (int m : contour_lines) EXPECT_EQ(std::abs(n - m) % 2, 1) << "they alternate: " << n << ", " << m;
    }
}

// A sphere of two parts (northern and southern hemisphere, as two primitives would be):
// the material boundary is the equator, the ring of edges at z = 0 and radius R, drawn
// once all the way round and as nothing else; one part has none.
TEST(MaterialBoundaries, TwoHemispheresMeetOnTheEquator) {
    constexpr float radius = 1.5f;
    constexpr int slices = 48;
    TriangleMesh sphere = make_uv_sphere(radius, slices, 16);
    for (size_t t = 0; t < sphere.triangle_count(); ++t) {
        const glm::vec3 centroid = (sphere.positions[sphere.indices[3 * t]] + sphere.positions[sphere.indices[3 * t + 1]] +
                                    sphere.positions[sphere.indices[3 * t + 2]]) / 3.0f;
        sphere.face_part.push_back(centroid.z > 0.0f ? 0u : 1u);
    }
    sphere.part_count = 2;
    const glm::vec3 eye(0.5f, 4.0f, 2.0f);
    const std::vector<LineSegment> lines = extract_lines_reference(build_line_mesh(sphere, 45.0f), eye,
                                                                   only(LineType::MaterialBoundary));
    const Placement p = place(lines, LineType::MaterialBoundary, [&](const glm::vec3& x) {
        return std::max(std::abs(x.z), std::abs(glm::length(glm::vec2(x.x, x.y)) - radius));
    });
    EXPECT_EQ(p.segments, size_t(slices)) << "each edge of the equator once";
    EXPECT_LE(p.worst, 1e-5f);
    EXPECT_NEAR(p.length, 2.0f * slices * radius * std::sin(std::numbers::pi_v<float> / slices), 1e-3f);
    const std::vector<LinePath> paths = chain_segments(lines);
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_TRUE(paths[0].closed);

    sphere.face_part.assign(sphere.triangle_count(), 0u);
    EXPECT_TRUE(extract_lines_reference(build_line_mesh(sphere, 45.0f), eye, only(LineType::MaterialBoundary)).empty());
}

// A model of several primitives (CesiumMilkTruck: body, glass, wheels, …): every boundary
// segment is an edge between faces of two different primitives, and there are some.
TEST(MaterialBoundaries, EdgesBetweenPrimitivesOfAModel) {
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/CesiumMilkTruck/CesiumMilkTruck.glb"));
    ASSERT_EQ(scene.mesh.face_part.size(), scene.mesh.triangle_count());
    ASSERT_GT(scene.mesh.part_count, 2u);
    const LineMesh lm = build_line_mesh(scene.mesh, 45.0f);
    const std::vector<LineSegment> lines =
        extract_lines_reference(lm, scene.camera.eye, only(LineType::MaterialBoundary));
    ASSERT_GT(lines.size(), 20u);
    for (const LineSegment& s : lines) {
        // The edge from key0 to key1 (mesh vertices) is shared by its face and one of
        // another part.
        const uint32_t a = s.key0, b = s.key1;
        size_t other_parts = 0;
        for (uint32_t j = lm.vertex_face_offsets[a]; j < lm.vertex_face_offsets[a + 1]; ++j) {
            const uint32_t g = lm.vertex_faces[j];
            const glm::uvec3 c = lm.mesh.faces[g];
            if ((c.x == b || c.y == b || c.z == b) && lm.face_part[g] != lm.face_part[s.face]) ++other_parts;
        }
        EXPECT_EQ(other_parts, 1u) << "segment on face " << s.face;
    }
}

// rtsc sees each face's corners in trimesh2's strip order: on a quad of two faces, the
// strip starts at the second face (the last one left with a single free neighbour) from
// the corner that leads across the shared edge, strip 3, 0, 2, 1: faces (3, 0, 2) and
// (0, 2, 1), the second wound backwards.
TEST(RidgeLines, StripOrderIsTrimesh2s) {
    TriangleMesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.normals.assign(4, glm::vec3(0, 0, 1));
    quad.indices = {0, 1, 2, 0, 2, 3};
    const LineMesh lm = build_line_mesh(quad, 45.0f);
    ASSERT_EQ(lm.mesh.faces[0], glm::uvec3(0, 1, 2));
    ASSERT_EQ(lm.mesh.faces[1], glm::uvec3(0, 2, 3));
    const auto corners = [&](size_t f) {
        return glm::ivec3(strip_corner(lm.strip_corners[f], 0), strip_corner(lm.strip_corners[f], 1),
                          strip_corner(lm.strip_corners[f], 2));
    };
    EXPECT_EQ(corners(1), glm::ivec3(2, 0, 1));  // vertices 3, 0, 2
    EXPECT_EQ(corners(0), glm::ivec3(0, 2, 1));  // vertices 0, 2, 1
    // On a closed mesh every face gets a permutation of its corners.
    const LineMesh sphere = build_line_mesh(make_icosphere(1.0f, 2), 45.0f);
    for (size_t f = 0; f < sphere.mesh.faces.size(); ++f) {
        const int a = strip_corner(sphere.strip_corners[f], 0), b = strip_corner(sphere.strip_corners[f], 1),
                  c = strip_corner(sphere.strip_corners[f], 2);
        EXPECT_EQ((1 << a) | (1 << b) | (1 << c), 7) << f;
    }
}

// (The GPU pass against this reference for every type: tests/test_lines.cpp, LinesGpuMatchesCpu.)

// Apparent ridges' derivative pass reads every vertex's curvature: threads meet at a barrier
// before it, and the output stays the same bytes at any thread count. A workspace kept from
// view to view (the first view of a pose finds ridges face by face, the second fills the
// cache, later ones read it) gives the same bytes as a fresh one, and follows a new pose.
TEST(RidgeLinesThreads, SameSegmentsAtAnyThreadCountAndFromTheCache) {
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb"));
    LineMesh lm = build_line_mesh(scene.mesh, 30.0f);
    const LineParams params = every_type();
    const glm::vec3 eyes[2] = {scene.camera.eye, scene.camera.eye + glm::vec3(4.0f, 2.0f, -3.0f)};
    const auto same = [](const std::vector<LineSegment>& a, const std::vector<LineSegment>& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(LineSegment)) == 0;
    };
    const std::vector<LineSegment> one = extract_lines_reference(lm, eyes[0], params, 1);
    ASSERT_GT(one.size(), 500u);
    for (size_t threads : {2u, 3u}) EXPECT_TRUE(same(extract_lines_reference(lm, eyes[0], params, threads), one)) << threads;

    ExtractWorkspace kept;
    std::vector<LineSegment> out;
    for (int round = 0; round < 2; ++round) {
        for (int view = 0; view < 4; ++view) {
            const glm::vec3& eye = eyes[view % 2];
            extract_lines_reference(lm, eye, params, out, kept, size_t(1 + view % 2));
            EXPECT_TRUE(same(out, extract_lines_reference(lm, eye, params))) << "round " << round << ", view " << view;
        }
        EXPECT_TRUE(kept.ridge_cache[0].use && kept.ridge_cache[1].use) << "a still pose reads the cache";
        TriangleMesh moved = scene.mesh;  // another pose: the cache must not serve it
        for (glm::vec3& p : moved.positions) p.y += 0.05f * std::sin(3.0f * p.x);
        pose_line_mesh(lm, moved);
    }
}

// lines.curvature "trimesh2" (or --curvature) fits the curvature as newer trimesh2 does: the
// line mesh of a session, of every pose, and of a session told so later; the scene key reads
// back and a bad value names it. (What the fit does to the lines: docs/research/rtsc-lines.md
// §7.4; CurvatureOptions itself: tests/test_curvature.cpp.)
TEST(CurvatureFitKey, Trimesh2FitReachesEveryLineMesh) {
    const std::filesystem::path dir = test::temp_dir();
    const SceneDesc read = parse_scene_json(R"({"model": "m.glb", "lines": {"curvature": "trimesh2"}})", dir / "in.json");
    EXPECT_EQ(read.lines.params.curvature, CurvatureFit::Trimesh2);
    EXPECT_EQ(parse_scene_json(scene_json(read, ViewCamera{}, dir), dir / "out.json").lines.params.curvature,
              CurvatureFit::Trimesh2);
    try {
        (void)parse_scene_json(R"({"model": "m.glb", "lines": {"curvature": "fast"}})", dir / "bad.json");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.json: lines.curvature"), std::string::npos) << e.what();
    }

    // The fits differ on a scan's irregular triangles; the line mesh keeps its fit in a new pose.
    SceneDesc desc = scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb");
    desc.width = 160;
    desc.height = 120;
    const LoadedScene scene = load_scene(desc);
    const SurfaceCurvature exact = build_line_mesh(scene.mesh, 45.0f).curvature;
    LineMesh fitted = build_line_mesh(scene.mesh, 45.0f, curvature_options(CurvatureFit::Trimesh2));
    const SurfaceCurvature newer = compute_curvature(fitted.mesh, {.trimesh2_ldlt_shortcut = true});
    ASSERT_EQ(fitted.curvature.k1.size(), exact.k1.size());
    EXPECT_EQ(fitted.curvature.k1, newer.k1);
    EXPECT_NE(fitted.curvature.k1, exact.k1);
    pose_line_mesh(fitted, scene.mesh);
    EXPECT_EQ(fitted.curvature.k1, newer.k1);

    Context ctx({.device = {DeviceChoice::Kind::Cpu}, .validation = true});
    {
        desc.lines.params.curvature = CurvatureFit::Trimesh2;
        SceneSession session(ctx, desc);
        ASSERT_NE(session.renderer().line_mesh(), nullptr);
        EXPECT_EQ(session.renderer().line_mesh()->curvature.k1, newer.k1);
        LinesDesc lines = desc.lines;
        lines.params.curvature = CurvatureFit::Exact;
        session.set_lines(lines);  // rebuilds the line mesh
        EXPECT_EQ(session.renderer().line_mesh()->curvature.k1, exact.k1);
    }
    EXPECT_TRUE(ctx.validation_messages().empty());
}

}  // namespace
}  // namespace lw
