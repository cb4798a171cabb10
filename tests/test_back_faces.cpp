// Back faces skipped where no pixel can see one (geometry/closed_surfaces.h): the closed
// surfaces found on meshes whose answer is known, the view test on views whose answer is
// known, and on lavapipe the surface pass's colour and depth equal to the byte with and
// without culling over orbits of open and closed models (and different where culling is
// forced on a view the test refuses, so that the comparison can fail).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "geometry/closed_surfaces.h"
#include "geometry/face_pairs.h"
#include "geometry/test_meshes.h"
#include "geometry/welded_mesh.h"
#include "render/surface_materials.h"
#include "render/surface_pass.h"
#include "scene/scene.h"
#include "scene/scene.h"
#include "test_support.h"

namespace lw {
namespace {

constexpr uint32_t kImage = 96;  // the GPU tests' image size

CameraMatrices look(glm::vec3 eye, glm::vec3 target, const Bounds& bounds) {
    return camera_matrices({.eye = eye, .target = target, .up = glm::vec3(0.0f, 0.0f, 1.0f)}, 1.0f, bounds);
}

std::vector<uint8_t> hidden_from(const TriangleMesh& mesh, glm::vec3 eye, glm::vec3 target = glm::vec3(0.0f)) {
    return back_faces_hidden(find_closed_surfaces(mesh), look(eye, target, compute_bounds(mesh.positions)));
}

// A unit cube with its own four vertices per face (split at every edge, as files split
// normals), faces counter-clockwise from outside.
TriangleMesh split_cube() {
    TriangleMesh mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side ? 1.0f : -1.0f;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (!side) std::swap(u, v);  // u × v points along n
            const uint32_t base = uint32_t(mesh.positions.size());
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                mesh.positions.push_back(0.5f * (n + c.x * u + c.y * v));
                mesh.normals.push_back(n);
            }
            for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + k);
        }
    return mesh;
}

TEST(ClosedSurfaces, SplitCubeAndSphereAreClosedAndOutward) {
    for (const TriangleMesh& mesh : {split_cube(), make_icosphere(1.0f, 2)}) {
        const ClosedSurfaces closed = find_closed_surfaces(mesh);
        ASSERT_EQ(closed.components.size(), 1u);
        EXPECT_TRUE(closed.components[0].caps.empty());
        EXPECT_TRUE(closed.components[0].outward);
        EXPECT_FALSE(closed.components[0].inward);
        EXPECT_EQ(hidden_from(mesh, glm::vec3(3.0f, 1.0f, 2.0f)), std::vector<uint8_t>{1});
    }
}

TEST(ClosedSurfaces, InsideOutAndFlatSurfacesAreNeverCulled) {
    TriangleMesh inverted = make_icosphere(1.0f, 2);
    for (size_t t = 0; t < inverted.indices.size(); t += 3) std::swap(inverted.indices[t + 1], inverted.indices[t + 2]);
    EXPECT_FALSE(find_closed_surfaces(inverted).components[0].outward);
    EXPECT_TRUE(find_closed_surfaces(inverted).components[0].inward);
    EXPECT_EQ(hidden_from(inverted, glm::vec3(3.0f, 1.0f, 2.0f)), std::vector<uint8_t>{0});
    // A flat sheet closed by its cap has no volume: seen from either side it stays drawn both ways.
    const TriangleMesh sheet = make_height_field([](double, double) { return 0.0; }, glm::vec2(-1), glm::vec2(1), 4, 4);
    const ClosedSurfaces closed = find_closed_surfaces(sheet);
    ASSERT_EQ(closed.components.size(), 1u);
    EXPECT_EQ(closed.components[0].caps.size(), 3u * 16u);  // a fan over the 16 rim edges
    EXPECT_FALSE(closed.components[0].inward);
    EXPECT_EQ(hidden_from(sheet, glm::vec3(0.5f, 0.3f, 3.0f)), std::vector<uint8_t>{0});
    EXPECT_EQ(hidden_from(sheet, glm::vec3(0.5f, 0.3f, -3.0f)), std::vector<uint8_t>{0});
}

// A closed part wound inside out is `inward` (its smooth contours are lost: frame_renderer
// warns) unless it lies inside an outward part: the wall of a cavity faces in by right. A
// flipped part inside the outward part's bounds but outside its volume is still inward.
TEST(ClosedSurfaces, ACavityWallIsNotInsideOut) {
    auto flipped_ball = [](float radius, glm::vec3 centre) {
        TriangleMesh ball = make_icosphere(radius, 2);
        for (glm::vec3& p : ball.positions) p += centre;
        for (size_t t = 0; t < ball.indices.size(); t += 3) std::swap(ball.indices[t + 1], ball.indices[t + 2]);
        return ball;
    };
    for (const auto& [centre, inside] : {std::pair{glm::vec3(0.1f, 0.0f, 0.0f), true},
                                        std::pair{glm::vec3(0.72f, 0.72f, 0.72f), false}}) {
        TriangleMesh mesh = make_icosphere(1.0f, 3);
        append_mesh(mesh, flipped_ball(0.05f, centre));
        const ClosedSurfaces closed = find_closed_surfaces(mesh);
        ASSERT_EQ(closed.components.size(), 2u);
        const ClosedSurfaces::Component& small = closed.components[size_t(closed.face_component.back())];
        EXPECT_FALSE(small.outward);
        EXPECT_EQ(small.inward, !inside) << "small ball at " << centre.x;
        EXPECT_TRUE(closed.components[size_t(closed.face_component.front())].outward);
    }
}

TEST(ClosedSurfaces, FoldsFinsAndSelfIntersectionsAreNeverCulled) {
    const glm::vec3 eye(3.0f, 1.0f, 2.0f);
    // A patch wound the wrong way (a common asset defect): its rim edges run twice one way.
    TriangleMesh patched = make_uv_sphere(1.0f, 24, 12);
    for (size_t t = 0; t < patched.indices.size(); t += 3) {
        const glm::vec3 centre = (patched.positions[patched.indices[t]] + patched.positions[patched.indices[t + 1]] +
                                  patched.positions[patched.indices[t + 2]]) / 3.0f;
        if (centre.z > 0.5f) std::swap(patched.indices[t + 1], patched.indices[t + 2]);
    }
    for (uint8_t h : hidden_from(patched, glm::vec3(10.0f, 0.0f, 0.4f))) EXPECT_EQ(h, 0);
    // A double-sided card: the same faces again, reversed (four faces on each inner edge).
    TriangleMesh card = make_height_field([](double x, double y) { return 0.1 * x * y; }, glm::vec2(-1), glm::vec2(1), 3, 3);
    const size_t n = card.indices.size();
    for (size_t t = 0; t < n; t += 3)
        for (int c : {0, 2, 1}) card.indices.push_back(card.indices[t + size_t(c)]);
    for (uint8_t h : hidden_from(card, eye)) EXPECT_EQ(h, 0);
    // A quad whose second triangle is wound the other way, open all round (its walk along
    // the border would find no way on), and a fin of three faces on a border edge.
    TriangleMesh quad;
    quad.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0.2f)};
    quad.normals.assign(4, glm::vec3(0, 0, 1));
    quad.indices = {0, 1, 2, 0, 3, 2};
    for (uint8_t h : hidden_from(quad, eye)) EXPECT_EQ(h, 0);
    TriangleMesh fin = quad;
    fin.indices = {0, 1, 2, 0, 2, 3, 0, 2, 1};
    fin.positions.push_back(glm::vec3(0.5f, 0.5f, 1.0f));
    fin.normals.push_back(glm::vec3(0, 0, 1));
    fin.indices.insert(fin.indices.end(), {0, 4, 2});
    for (uint8_t h : hidden_from(fin, eye)) EXPECT_EQ(h, 0);
    // One triangle both ways: closed, with no volume.
    TriangleMesh leaf;
    leaf.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0.3f)};
    leaf.normals.assign(3, glm::vec3(0, 0, 1));
    leaf.indices = {0, 1, 2, 0, 2, 1};
    EXPECT_EQ(hidden_from(leaf, eye), std::vector<uint8_t>{0});
}

// A sphere with a vertex pushed through the far wall: the surface passes through itself and
// the spike beyond the far wall encloses a pocket inside out.
TriangleMesh dented_sphere() {
    TriangleMesh dented = make_icosphere(1.0f, 2);
    dented.positions[0] *= -1.6f;
    return dented;
}

TEST(ClosedSurfaces, FacesNearAPocketInsideOutAreDrawnBothWays) {
    const TriangleMesh dented = dented_sphere();
    const ClosedSurfaces closed = find_closed_surfaces(dented);
    ASSERT_EQ(closed.components.size(), 1u);
    EXPECT_TRUE(closed.components[0].outward);
    // The spike's faces (those at vertex 0) cross the far wall or bound the pocket.
    size_t spike = 0, both_ways = 0;
    for (size_t t = 0; t < dented.triangle_count(); ++t) {
        const bool at_spike = dented.indices[3 * t] == 0 || dented.indices[3 * t + 1] == 0 || dented.indices[3 * t + 2] == 0;
        spike += at_spike;
        both_ways += closed.face_both_ways[t];
        if (at_spike) {
            EXPECT_TRUE(closed.face_both_ways[t]) << "face " << t;
        }
    }
    EXPECT_EQ(spike, 5u);
    EXPECT_LT(both_ways, dented.triangle_count() / 4);
    // A plain sphere has none.
    const ClosedSurfaces plain = find_closed_surfaces(make_icosphere(1.0f, 2));
    EXPECT_EQ(std::count(plain.face_both_ways.begin(), plain.face_both_ways.end(), 1), 0);
}

TEST(ClosedSurfaces, FacesSharingAVertexThatCrossBeyondItMeet) {
    // f = (v, a1, a2) and g = (v, b1, b2): g's edge b1b2 pierces f at (1, 0, 0).
    WeldedMesh m;
    m.positions = {glm::vec3(0, 0, 0), glm::vec3(2, -1, 0), glm::vec3(2, 1, 0), glm::vec3(1, 0, -1), glm::vec3(1, 0, 1)};
    m.faces = {glm::uvec3(0, 1, 2), glm::uvec3(0, 3, 4)};
    EXPECT_TRUE(triangles_meet(m, 0, 1));
    m.positions[3] = glm::vec3(-1, 0, -1), m.positions[4] = glm::vec3(-1, 0, 1);  // behind v: only v in common
    EXPECT_FALSE(triangles_meet(m, 0, 1));
    // Sharing an edge: apart when they turn away from each other, meeting when folded flat
    // onto the same side.
    m.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0.5f)};
    m.faces = {glm::uvec3(0, 1, 2), glm::uvec3(1, 0, 3)};
    EXPECT_FALSE(triangles_meet(m, 0, 1));
    m.positions[3] = glm::vec3(0.5f, 0.8f, 0.0f);
    EXPECT_TRUE(triangles_meet(m, 0, 1));
}

TEST(ClosedSurfaces, ShellsMeetingAtAVertexAreJudgedApart) {
    // A sphere and a small inside-out one touching it at a vertex: two components, of which
    // only the outward one may be culled.
    TriangleMesh mesh = make_icosphere(1.0f, 2);
    const TriangleMesh small = make_icosphere(0.2f, 1, mesh.positions[0] * 1.2f);
    const uint32_t base = uint32_t(mesh.positions.size());
    size_t nearest = 0;
    for (size_t v = 0; v < small.positions.size(); ++v)
        if (glm::length(small.positions[v] - mesh.positions[0]) < glm::length(small.positions[nearest] - mesh.positions[0]))
            nearest = v;
    mesh.positions.insert(mesh.positions.end(), small.positions.begin(), small.positions.end());
    mesh.normals.insert(mesh.normals.end(), small.normals.begin(), small.normals.end());
    mesh.positions[base + nearest] = mesh.positions[0];  // welded there
    for (size_t t = 0; t < small.indices.size(); t += 3)
        for (int c : {0, 2, 1}) mesh.indices.push_back(base + small.indices[t + size_t(c)]);
    EXPECT_EQ(find_closed_surfaces(mesh).components.size(), 2u);
    EXPECT_EQ(hidden_from(mesh, glm::vec3(4.0f, 1.0f, 2.0f)), (std::vector<uint8_t>{1, 0}));
}

TEST(ClosedSurfaces, DrawsCullOnlyWhereEveryComponentIsOpaqueAndHidden) {
    // Two components of 3 faces (0–2 and 3–5) and a face with no area (6), in three draws
    // whose index buffer takes the faces in another order.
    ClosedSurfaces surfaces;
    surfaces.face_component = {0, 0, 0, 1, 1, 1, -1};
    surfaces.face_both_ways.assign(7, 0);
    surfaces.components.resize(2);
    const std::vector<uint32_t> face_order = {3, 0, 1, 6, 4, 2, 5};
    const std::vector<MeshDraw> draws = {{.material = 0, .first_index = 0, .index_count = 3 * 4},   // 3 0 1 6
                                         {.material = 1, .first_index = 12, .index_count = 3},      // 4
                                         {.material = 2, .first_index = 15, .index_count = 3 * 2}};  // 2 5
    // Each decision twice: with the draws' faces walked there, and with draw_surfaces found
    // beforehand (as FrameRenderer keeps it per mesh).
    const auto cull = [&](std::vector<uint8_t> hidden, std::vector<uint8_t> opaque) {
        const std::vector<DrawSurfaces> per_draw = draw_surfaces(draws, face_order, surfaces);
        const BackFaceCulling walked{.surfaces = &surfaces, .hidden = hidden};
        const BackFaceCulling found{.surfaces = &surfaces, .hidden = std::move(hidden), .draws = &per_draw};
        const std::vector<uint8_t> result = cullable_draws(draws, face_order, opaque, &walked);
        EXPECT_EQ(cullable_draws(draws, face_order, opaque, &found), result);
        return result;
    };
    const std::vector<DrawSurfaces> per_draw = draw_surfaces(draws, face_order, surfaces);
    ASSERT_EQ(per_draw.size(), 3u);
    EXPECT_EQ(per_draw[0].components, (std::vector<int32_t>{0, 1}));  // faces 3 0 1 6
    EXPECT_EQ(per_draw[1].components, (std::vector<int32_t>{1}));
    EXPECT_EQ(per_draw[2].components, (std::vector<int32_t>{0, 1}));
    EXPECT_EQ(cull({1, 1}, {1, 1, 1}), (std::vector<uint8_t>{1, 1, 1}));
    EXPECT_EQ(cull({1, 0}, {1, 1, 1}), (std::vector<uint8_t>{0, 0, 0}));  // 1 is in every draw
    EXPECT_EQ(cull({1, 1}, {1, 0, 1}), (std::vector<uint8_t>{0, 0, 0}));  // a masked face of 1 lets the eye in
    EXPECT_EQ(cull({1, 1}, {1, 1, 0}), (std::vector<uint8_t>{0, 0, 0}));
    // A list that does not fit hides nothing.
    EXPECT_EQ(cull({}, {1, 1, 1}), (std::vector<uint8_t>{0, 0, 0}));
    EXPECT_EQ(cull({1, 1, 1}, {1, 1, 1}), (std::vector<uint8_t>{0, 0, 0}));
    // A face drawn both ways keeps its draw from culling, not the others.
    surfaces.face_both_ways[2] = 1;
    EXPECT_EQ(cull({1, 1}, {1, 1, 1}), (std::vector<uint8_t>{1, 1, 0}));
}

TEST(ClosedSurfaces, CapsCloseTheHolesAndDecide) {
    // An open cylinder about z from 0 to 2: two rings of 12 open edges, each capped by a fan
    // whose triangles face out of the tube (the rim runs the other way in them).
    const TriangleMesh tube = make_open_cylinder(1.0f, 2.0f, 12, 3);
    const ClosedSurfaces closed = find_closed_surfaces(tube);
    ASSERT_EQ(closed.components.size(), 1u);
    const std::vector<glm::vec3>& caps = closed.components[0].caps;
    ASSERT_EQ(caps.size(), 2u * 12u * 3u);
    for (size_t k = 0; k < caps.size(); k += 3) {
        const glm::vec3 n = glm::cross(caps[k + 1] - caps[k], caps[k + 2] - caps[k]);
        EXPECT_GT(caps[k].z > 1.0f ? n.z : -n.z, 0.0f) << "cap triangle " << k / 3;
    }
    EXPECT_TRUE(closed.components[0].outward);
    // Wound the other way, a capped tube is no inside-out solid (an open surface has no inside).
    TriangleMesh reversed = tube;
    for (size_t t = 0; t < reversed.indices.size(); t += 3) std::swap(reversed.indices[t + 1], reversed.indices[t + 2]);
    EXPECT_FALSE(find_closed_surfaces(reversed).components[0].inward);
    // From the side, between the rims, both caps face away; from above, the top one faces
    // the eye (the inside shows through the opening); from below, the bottom one.
    const glm::vec3 centre(0.0f, 0.0f, 1.0f);
    EXPECT_EQ(hidden_from(tube, glm::vec3(6.0f, 2.0f, 1.2f), centre), std::vector<uint8_t>{1});
    EXPECT_EQ(hidden_from(tube, glm::vec3(3.0f, 2.0f, 6.0f), centre), std::vector<uint8_t>{0});
    EXPECT_EQ(hidden_from(tube, glm::vec3(3.0f, 2.0f, -4.0f), centre), std::vector<uint8_t>{0});
}

TEST(ClosedSurfaces, TheEyeInsideOrTheNearPlaneThroughItIsRefused) {
    const TriangleMesh sphere = make_icosphere(1.0f, 2);
    EXPECT_EQ(hidden_from(sphere, glm::vec3(0.1f, 0.2f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)), std::vector<uint8_t>{0});
    // Outside the sphere but inside its bounds: the box test is conservative.
    EXPECT_EQ(hidden_from(sphere, glm::vec3(0.95f, 0.95f, 0.0f), glm::vec3(2.0f, 2.0f, 0.0f)), std::vector<uint8_t>{0});
    // Outside, with a near plane that cuts the sphere open.
    const ClosedSurfaces closed = find_closed_surfaces(sphere);
    const CameraMatrices camera = camera_matrices(
        {.eye = glm::vec3(0.0f, 0.0f, 1.5f), .target = glm::vec3(0.0f), .up = glm::vec3(0.0f, 1.0f, 0.0f), .znear = 0.8f, .zfar = 10.0f},
        1.0f, compute_bounds(sphere.positions));
    EXPECT_EQ(back_faces_hidden(closed, camera), std::vector<uint8_t>{0});
}

TEST(ClosedSurfaces, AScanMeetingItselfKeepsMostFacesCulled) {
    // LeePerrySmith's surface meets itself in 250 pairs of faces (folds of the scan), and one
    // fold encloses a pocket inside out (about 1e-4 of a unit across): the 238 faces of the
    // folds are drawn both ways, the rest of the head may skip its back faces.
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb"));
    const ClosedSurfaces closed = find_closed_surfaces(scene.mesh);
    ASSERT_EQ(closed.components.size(), 1u);
    EXPECT_TRUE(closed.components[0].caps.empty());
    EXPECT_TRUE(closed.components[0].outward);
    const auto both_ways = size_t(std::count(closed.face_both_ways.begin(), closed.face_both_ways.end(), 1));
    EXPECT_GE(both_ways, 200u);
    EXPECT_LT(both_ways, scene.mesh.triangle_count() / 20);
}

// The mesh's polygonal contour in pixels (x0, y0, x1, y1 per edge): welded edges between a
// face turned to the eye and one turned away, and open edges.
std::vector<glm::vec4> contour_edges(const TriangleMesh& mesh, const CameraMatrices& camera) {
    const WeldedMesh welded = weld(mesh);
    const glm::vec3 eye = glm::vec3(glm::inverse(camera.view)[3]);
    std::vector<bool> front(welded.faces.size());
    for (size_t f = 0; f < welded.faces.size(); ++f) {
        const glm::vec3 a = welded.positions[welded.faces[f][0]], b = welded.positions[welded.faces[f][1]],
                        c = welded.positions[welded.faces[f][2]];
        front[f] = glm::dot(glm::cross(b - a, c - a), eye - a) > 0.0f;
    }
    std::vector<glm::vec4> out;
    for (const MeshEdge& e : welded.edges) {
        if (e.face_count == 2 && front[size_t(e.f[0])] == front[size_t(e.f[1])]) continue;
        const glm::vec3 p = project_to_pixel(camera, welded.positions[e.v[0]], float(kImage), float(kImage));
        const glm::vec3 q = project_to_pixel(camera, welded.positions[e.v[1]], float(kImage), float(kImage));
        out.emplace_back(p.x, p.y, q.x, q.y);
    }
    return out;
}

float distance_to(const std::vector<glm::vec4>& segments, glm::vec2 point) {
    float best = 1e30f;
    for (const glm::vec4& s : segments) {
        const glm::vec2 a(s.x, s.y), ab = glm::vec2(s.z, s.w) - a;
        const float t = glm::clamp(glm::dot(point - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
        best = std::min(best, glm::length(point - (a + t * ab)));
    }
    return best;
}

// Colour and depth of the surface pass, drawn with `culling` (or every face without).
struct SurfaceImage {
    std::vector<uint8_t> color;
    std::vector<float> depth;
};

class BackFaceCullingGpu : public test::GpuTest {
protected:
    static constexpr uint32_t kSize = kImage;

    SurfaceImage draw(const GpuMesh& mesh, const CameraMatrices& camera, glm::vec3 eye, const BackFaceCulling* culling,
                      uint32_t samples = 1) {
        const SurfacePass pass(ctx(), VK_FORMAT_R8G8B8A8_UNORM, samples);
        RenderTarget target(ctx(), kSize, kSize, VK_FORMAT_R8G8B8A8_UNORM, samples);
        const VkDeviceSize bytes = VkDeviceSize(kSize) * kSize * 4;
        Buffer color(ctx(), {.size = bytes, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             .purpose = MemoryPurpose::Readback, .name = "test colour"});
        Buffer depth(ctx(), {.size = bytes, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             .purpose = MemoryPurpose::Readback, .name = "test depth"});
        ctx().submit_and_wait([&](VkCommandBuffer cmd) {
            pass.record(cmd, target, mesh, camera, eye, SurfaceStyle{.samples = samples}, nullptr, culling);
            record_image_to_buffer(cmd, target.color, color);
            record_image_to_buffer(cmd, target.depth, depth);
            record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        SurfaceImage out;
        out.color = read_rgba8(ctx(), color, kSize, kSize, VK_FORMAT_R8G8B8A8_UNORM).pixels;
        depth.invalidate(ctx());
        out.depth.resize(size_t(kSize) * kSize);
        std::memcpy(out.depth.data(), depth.mapped(), out.depth.size() * sizeof(float));
        return out;
    }

    // Over an orbit at several heights: where the view test lets a component be culled, the
    // images are the same to the byte but for at most 4 pixels on the polygonal contour, where
    // a back face folded behind a front one ties with it in depth (a 1-pixel z-fight that the
    // unculled pass may lose either way). Returns how many views culled something.
    int expect_same_images(const TriangleMesh& mesh, uint32_t samples = 1) {
        const ClosedSurfaces closed = find_closed_surfaces(mesh);
        const GpuMesh gpu = upload_mesh(ctx(), mesh, nullptr, &closed.face_both_ways);
        const Bounds bounds = compute_bounds(mesh.positions);
        int culled = 0;
        for (float height : {-1.6f, -0.5f, 0.0f, 0.4f, 1.6f})
            for (int step = 0; step < 6; ++step) {
                const float angle = 1.047f * float(step) + 0.3f;
                const glm::vec3 eye = bounds.center() + 2.6f * bounds.radius() *
                                                            glm::normalize(glm::vec3(std::cos(angle), height, std::sin(angle)));
                const CameraMatrices camera =
                    camera_matrices({.eye = eye, .target = bounds.center(), .up = glm::vec3(0, 1, 0)}, 1.0f, bounds);
                const BackFaceCulling culling{.surfaces = &closed, .hidden = back_faces_hidden(closed, camera)};
                if (std::find(culling.hidden.begin(), culling.hidden.end(), 1) == culling.hidden.end()) continue;
                ++culled;
                const SurfaceImage all = draw(gpu, camera, eye, nullptr, samples);
                const SurfaceImage some = draw(gpu, camera, eye, &culling, samples);
                const std::vector<glm::vec4> contour = contour_edges(mesh, camera);
                int differ = 0;
                for (size_t i = 0; i < all.depth.size(); ++i) {
                    if (all.depth[i] == some.depth[i] && std::memcmp(&all.color[4 * i], &some.color[4 * i], 4) == 0)
                        continue;
                    ++differ;
                    const glm::vec2 centre(float(i % kSize) + 0.5f, float(i / kSize) + 0.5f);
                    EXPECT_LE(distance_to(contour, centre), 1.0f)
                        << "pixel " << centre.x << ", " << centre.y << " (height " << height << ", step " << step << ")";
                }
                EXPECT_LE(differ, 4) << "height " << height << ", step " << step;
            }
        return culled;
    }
};

TEST_F(BackFaceCullingGpu, ScanOpenTubeAndPocketSameImagesWhereCulled) {
    // LeePerrySmith is closed (its neck has a cap of its own) and meets itself (its folds
    // drawn both ways): culled from everywhere outside it.
    const LoadedScene scene = load_scene(scene_for_model(test::data_dir() / "models/LeePerrySmith/LeePerrySmith.glb"));
    EXPECT_EQ(expect_same_images(scene.mesh), 30);
    // The tube is open at both ends (about z; the orbit's heights are along y): the views
    // that look into an end are refused (all but those from between the rims' planes).
    const int culled = expect_same_images(make_open_cylinder(1.0f, 2.0f, 24, 4));
    EXPECT_GE(culled, 2);
    EXPECT_LE(culled, 12);
    // The spike's pocket, seen from all round.
    EXPECT_EQ(expect_same_images(dented_sphere()), 30);
}

TEST_F(BackFaceCullingGpu, SkinnedPoseSameImages) {
    // The Fox mid-stride, its pose found anew (the renderer culls no pose but set_mesh's):
    // skinned, its seams move together, and it stays closed.
    const std::string model = (test::data_dir() / "models/Fox/Fox.glb").string();
    const LoadedScene scene =
        load_scene(parse_scene_json(R"({"model": ")" + model + R"(", "animation": {"clip": "Walk"}})", "fox.json"));
    const TriangleMesh posed = pose_scene(scene, 0.4f);
    ASSERT_NE(posed.positions, scene.mesh.positions);
    EXPECT_EQ(expect_same_images(posed), 30);
}

TEST_F(BackFaceCullingGpu, ClosedAndMultisampledSameImages) {
    EXPECT_EQ(expect_same_images(split_cube(), 4), 30);
    EXPECT_EQ(expect_same_images(make_icosphere(1.0f, 2)), 30);
}

TEST_F(BackFaceCullingGpu, ForcedOnARefusedViewTheImagesDiffer) {
    // The tube seen from above, where its top cap faces the eye: culling would remove the
    // inside seen through the opening. The comparison above would catch it.
    const TriangleMesh tube = make_open_cylinder(1.0f, 2.0f, 24, 4);
    const ClosedSurfaces closed = find_closed_surfaces(tube);
    const GpuMesh gpu = upload_mesh(ctx(), tube, nullptr, &closed.face_both_ways);
    const glm::vec3 eye(2.0f, 1.5f, 6.0f);
    const CameraMatrices camera = look(eye, glm::vec3(0.0f, 0.0f, 1.0f), compute_bounds(tube.positions));
    EXPECT_EQ(back_faces_hidden(closed, camera), std::vector<uint8_t>{0});
    const BackFaceCulling forced{.surfaces = &closed, .hidden = {1}};
    const SurfaceImage all = draw(gpu, camera, eye, nullptr);
    const SurfaceImage culled = draw(gpu, camera, eye, &forced);
    EXPECT_NE(all.depth, culled.depth);
}

}  // namespace
}  // namespace lw
