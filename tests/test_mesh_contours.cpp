// Mesh contours (issue 16 item 4): on a low-poly model the silhouettes taken from the mesh's
// own edges close the outline as the rasterized mesh draws it.
#include <algorithm>
#include <cmath>
#include <deque>

#include "geometry/subdivide.h"
#include "geometry/test_meshes.h"
#include "lines/chaining.h"
#include "lines/extract_reference.h"
#include "render/frame_renderer.h"
#include "scene/scene.h"
#include "test_support.h"

namespace lw {
namespace {

class MeshContours : public test::GpuTest {};

// How well the visible silhouettes close around what the surface covers: the pixels not
// reachable from the image border without crossing a silhouette (lines drawn 1 px wide) are
// the inside; against the coverage mask (depth < 1), the IoU over the pixels that are not on
// a line. A gap wider than a pixel lets the outside in (the IoU falls by the inside's
// share); an outline that strays from the polygon's leaves covered pixels outside.
struct Closure {
    double iou = 0.0;
    size_t inside = 0, covered = 0;
};

Closure outline_closure(const Frame& frame, int width, int height) {
    std::vector<uint8_t> line(size_t(width) * height, 0);
    for (const ScreenPath& p : frame.screen_paths) {
        if (p.type != LineType::Silhouette || !p.visible) continue;
        const size_t n = p.samples.size();
        for (size_t i = 0; i + 1 < n + (p.closed ? 1 : 0); ++i) {
            const glm::vec2 a = p.samples[i].pixel, b = p.samples[(i + 1) % n].pixel;
            const int steps = 1 + int(4.0f * glm::length(b - a));
            for (int k = 0; k <= steps; ++k) {
                const glm::vec2 q = glm::mix(a, b, float(k) / float(steps));
                const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
                if (x >= 0 && y >= 0 && x < width && y < height) line[size_t(y) * width + x] = 1;
            }
        }
    }
    std::vector<uint8_t> outside(line.size(), 0);
    std::deque<size_t> todo;
    for (int x = 0; x < width; ++x)
        for (int y : {0, height - 1}) todo.push_back(size_t(y) * width + x);
    for (int y = 0; y < height; ++y)
        for (int x : {0, width - 1}) todo.push_back(size_t(y) * width + x);
    while (!todo.empty()) {
        const size_t i = todo.front();
        todo.pop_front();
        if (outside[i] || line[i]) continue;
        outside[i] = 1;
        const int x = int(i % width), y = int(i / width);
        if (x > 0) todo.push_back(i - 1);
        if (x + 1 < width) todo.push_back(i + 1);
        if (y > 0) todo.push_back(i - width);
        if (y + 1 < height) todo.push_back(i + width);
    }
    Closure c;
    size_t both = 0, either = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        if (line[i]) continue;
        const bool inside = !outside[i], covered = frame.image.depth[i] < 1.0f;
        c.inside += inside;
        c.covered += covered;
        both += inside && covered;
        either += inside || covered;
    }
    c.iou = either ? double(both) / double(either) : 0.0;
    return c;
}

Frame render_silhouettes(const Context& ctx, const TriangleMesh& mesh, const glm::vec3& eye, const glm::vec3& target,
                         ContourMode mode, int width, int height) {
    const ViewCamera view{.eye = eye, .target = target, .fov_deg = 40.0f};
    const CameraMatrices camera = camera_matrices(view, float(width) / float(height), compute_bounds(mesh.positions));
    FrameRenderer renderer(ctx, uint32_t(width), uint32_t(height));
    renderer.set_mesh(mesh, true, 45.0f);
    LinesDesc lines;
    set_line_types(lines.params, 1u << uint32_t(LineType::Silhouette));
    lines.params.contours = mode;
    return renderer.render(camera, eye, SurfaceStyle{}, lines, FrameOutputs{.color = false, .depth = true});
}

// The glTF Fox from its side (its smooth contour leaves gaps at an ear, the chest and the
// tail base) and a level-1 icosphere: with mesh contours the visible outline is closed and
// lies on the rasterized outline (IoU ≥ 0.99 off the line pixels); `auto` takes the mesh's
// edges on both (median angles between neighbouring faces 16° and 37°, over 12°).
TEST_F(MeshContours, LowPolyOutlinesCloseOnTheRasterizedOutline) {
    const int width = 640, height = 480;
    const LoadedScene fox = load_scene(scene_for_model(test::data_dir() / "models/Fox/Fox.glb"));
    const glm::vec3 centre = fox.bounds.center();
    const glm::vec3 side = centre + 2.4f * fox.bounds.radius() * glm::normalize(glm::vec3(1.0f, 0.15f, 0.05f));
    const TriangleMesh ico = make_icosphere(1.0f, 1);
    struct Case {
        const char* name;
        const TriangleMesh* mesh;
        glm::vec3 eye, target;
    };
    for (const Case& c : {Case{"Fox", &fox.mesh, side, centre}, Case{"icosphere", &ico, {0.4f, 0.9f, 3.2f}, {0, 0, 0}}}) {
        for (const ContourMode mode : {ContourMode::Mesh, ContourMode::Auto}) {
            const Frame frame = render_silhouettes(ctx(), *c.mesh, c.eye, c.target, mode, width, height);
            const Closure closure = outline_closure(frame, width, height);
            size_t runs = 0;  // (the outline is pieces of several contours, met at T-junctions on screen)
            for (const ScreenPath& p : frame.screen_paths) runs += p.type == LineType::Silhouette && p.visible;
            RecordProperty(std::string(c.name) + "_" + contour_mode_name(mode) + "_visible_runs", int(runs));
            RecordProperty(std::string(c.name) + "_" + contour_mode_name(mode) + "_iou", std::to_string(closure.iou));
            EXPECT_GE(closure.iou, 0.99) << c.name << ", " << contour_mode_name(mode) << ": inside " << closure.inside
                                         << " px, covered " << closure.covered << " px";
            EXPECT_GT(closure.covered, 5000u) << c.name << ": the model fills a good part of the frame";
        }
    }
    // The smooth contour of the Fox does not close: the outside gets in.
    const Closure smooth = outline_closure(render_silhouettes(ctx(), fox.mesh, side, centre, ContourMode::Smooth, width, height),
                                           width, height);
    RecordProperty("Fox_smooth_iou", std::to_string(smooth.iou));
    EXPECT_LT(smooth.iou, 0.9);
}

// The outline as one stroke (a line set's "chaining": {"outline": true}, stroke/outline.h):
// the Fox's visible mesh contours, 20-odd runs met at T-junctions on screen, become one
// closed path whose samples lie at most 2δ apart and whose inside (even-odd fill) is the
// rasterized mesh (IoU ≥ 0.99 off the outline's own pixels).
TEST_F(MeshContours, FoxOutlineIsOneClosedPath) {
    const int width = 640, height = 480;
    const LoadedScene fox = load_scene(scene_for_model(test::data_dir() / "models/Fox/Fox.glb"));
    const glm::vec3 centre = fox.bounds.center();
    const glm::vec3 eye = centre + 2.4f * fox.bounds.radius() * glm::normalize(glm::vec3(1.0f, 0.15f, 0.05f));
    const ViewCamera view{.eye = eye, .target = centre, .fov_deg = 40.0f};
    const CameraMatrices camera = camera_matrices(view, float(width) / float(height), fox.bounds);
    FrameRenderer renderer(ctx(), uint32_t(width), uint32_t(height));
    renderer.set_mesh(fox.mesh, true, 45.0f);
    LinesDesc lines;
    lines.params.contours = ContourMode::Mesh;
    LineSetDesc set{.name = "outline"};
    set.select.types = 1u << uint32_t(LineType::Silhouette);
    set.style.chaining.outline = true;
    lines.sets = {set};
    Frame frame = renderer.render(camera, eye, SurfaceStyle{}, lines, FrameOutputs{.color = false, .depth = true});
    ASSERT_EQ(frame.sets.size(), 1u);
    const std::vector<ScreenPath>& outline = frame.sets[0].paths;
    ASSERT_EQ(outline.size(), 1u) << "one outline";
    const ScreenPath& loop = outline[0];
    EXPECT_TRUE(loop.closed);
    float widest = 0.0f;
    const size_t n = loop.samples.size();
    for (size_t i = 0; i < n; ++i) widest = std::max(widest, glm::distance(loop.samples[i].pixel, loop.samples[(i + 1) % n].pixel));
    RecordProperty("outline_samples", int(n));
    RecordProperty("widest_step_px", std::to_string(widest));
    EXPECT_LE(widest, 4.0f) << "a jump: the outline is not continuous";
    size_t runs = 0;
    for (const ScreenPath& p : frame.screen_paths) runs += p.visible;
    RecordProperty("visible_runs", int(runs));
    // Its inside, filled even-odd at pixel centres, against the coverage mask, off the
    // outline's own pixels (Closure's line mask).
    frame.screen_paths = outline;
    const Closure closure = outline_closure(frame, width, height);
    EXPECT_GE(closure.iou, 0.99);
    std::vector<uint8_t> filled(size_t(width) * height, 0);
    for (int y = 0; y < height; ++y) {
        const float cy = float(y) + 0.5f;
        std::vector<float> xs;
        for (size_t i = 0; i < n; ++i) {
            const glm::vec2 a = loop.samples[i].pixel, b = loop.samples[(i + 1) % n].pixel;
            if ((a.y <= cy) != (b.y <= cy)) xs.push_back(a.x + (cy - a.y) / (b.y - a.y) * (b.x - a.x));
        }
        std::sort(xs.begin(), xs.end());
        for (size_t k = 0; k + 1 < xs.size(); k += 2)
            for (int x = std::max(0, int(std::ceil(xs[k] - 0.5f))); x < width && float(x) + 0.5f < xs[k + 1]; ++x)
                filled[size_t(y) * width + size_t(x)] = 1;
    }
    std::vector<uint8_t> on_line(filled.size(), 0);  // within 1.5 px of the outline
    for (size_t i = 0; i < n; ++i) {
        const glm::vec2 a = loop.samples[i].pixel, b = loop.samples[(i + 1) % n].pixel;
        for (int k = 0; k <= 8; ++k) {
            const glm::vec2 q = glm::mix(a, b, float(k) / 8.0f);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = int(std::floor(q.x)) + dx, y = int(std::floor(q.y)) + dy;
                    if (x >= 0 && y >= 0 && x < width && y < height) on_line[size_t(y) * width + size_t(x)] = 1;
                }
        }
    }
    size_t both = 0, either = 0;
    for (size_t i = 0; i < filled.size(); ++i) {
        if (on_line[i]) continue;
        const bool covered = frame.image.depth[i] < 1.0f;
        both += filled[i] && covered;
        either += filled[i] || covered;
    }
    const double iou = either ? double(both) / double(either) : 0.0;
    RecordProperty("fill_iou", std::to_string(iou));
    EXPECT_GE(iou, 0.99);
}

// Mesh contours are the edges between a front- and a back-facing face, each once, emitted by
// the front face and keyed by their fans of front faces; on a closed mesh they chain into
// closed loops, also where two of them touch at a vertex.
TEST(MeshContoursReference, EdgesBetweenFrontAndBackFacesChainIntoLoops) {
    const LineMesh lm = build_line_mesh(make_icosphere(1.0f, 2), 45.0f);
    LineParams params;
    set_line_types(params, 1u << uint32_t(LineType::Silhouette));
    params.contours = ContourMode::Mesh;
    const glm::vec3 eye(0.3f, 0.5f, 4.0f);
    const std::vector<LineSegment> segments = extract_lines_reference(lm, eye, params);
    ASSERT_GT(segments.size(), 10u);
    const auto facing = [&](int f) {
        const glm::uvec3 c = lm.mesh.faces[size_t(f)];
        const glm::vec3 n = glm::cross(lm.mesh.positions[c.y] - lm.mesh.positions[c.x], lm.mesh.positions[c.z] - lm.mesh.positions[c.x]);
        return glm::dot(n, eye - lm.mesh.positions[c.x]) > 0.0f;
    };
    size_t expected = 0;
    for (const MeshEdge& e : lm.mesh.edges) expected += e.face_count == 2 && facing(e.f[0]) != facing(e.f[1]);
    EXPECT_EQ(segments.size(), expected);
    for (const LineSegment& s : segments) EXPECT_TRUE(facing(int(s.face))) << "emitted by the front face";
    const std::vector<LinePath> paths = chain_segments(segments);
    ASSERT_EQ(paths.size(), 1u) << "a convex mesh has one contour loop";
    EXPECT_TRUE(paths[0].closed);

    // On the Fox contours touch at vertices (four contour edges there): keyed by their fans of
    // front faces, each goes on through its own fan and every contour chains into a loop.
    const LoadedScene fox = load_scene(scene_for_model(test::data_dir() / "models/Fox/Fox.glb"));
    const LineMesh fox_lines = build_line_mesh(fox.mesh, 45.0f);
    const glm::vec3 side = fox.bounds.center() + 2.4f * fox.bounds.radius() * glm::normalize(glm::vec3(1.0f, 0.15f, 0.05f));
    size_t loops = 0, open = 0;
    for (const LinePath& p : chain_segments(extract_lines_reference(fox_lines, side, params))) (p.closed ? loops : open)++;
    EXPECT_EQ(open, 0u);
    EXPECT_GE(loops, 2u);
    RecordProperty("fox_contour_loops", int(loops));
}

// `auto` judges a model on its own edges: the Fox is coarse, also once subdivided (its new
// edges are flat); LeePerrySmith is not; in a scene of both each keeps its own contours.
TEST(MeshContoursReference, AutoJudgesEachModelOnItsOwnEdges) {
    SceneDesc desc;
    desc.models = {test::data_dir() / "models/Fox/Fox.glb", test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb"};
    const LoadedScene scene = load_scene(desc);
    ASSERT_EQ(scene.mesh.face_model.size(), scene.mesh.triangle_count());
    for (const int levels : {0, 1}) {
        const TriangleMesh mesh = subdivide_midpoint(scene.mesh, levels);
        const LineMesh lm = build_line_mesh(mesh, 45.0f);
        size_t coarse[2] = {0, 0}, faces[2] = {0, 0};
        for (size_t f = 0; f < lm.mesh.faces.size(); ++f) {
            const uint32_t model = mesh.face_model[lm.mesh.source_face[f]];
            ++faces[model];
            coarse[model] += lm.face_coarse[f];
        }
        EXPECT_EQ(coarse[0], faces[0]) << "the Fox, " << levels << " subdivisions";
        EXPECT_EQ(coarse[1], 0u) << "LeePerrySmith, " << levels << " subdivisions";
    }
}

}  // namespace
}  // namespace lw
