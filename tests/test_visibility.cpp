// The visibility stage's samples (lines/visibility.h): each sample's surface point is the point
// of the 3D line that projects to its pixel, and its depth is that point's eye depth, however
// far a segment runs away from the eye. A low-poly model's edge is one long segment; sampled
// with screen fractions in place of perspective-correct ones, its samples' surface points sat
// pixels away from their pixels (the coherence tracker carried them back to the wrong place),
// and their depths behind the face they lie on.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lines/visibility.h"
#include "scene/camera.h"

namespace lw {
namespace {

constexpr int kWidth = 320, kHeight = 240;

// A camera low over the plane y = 0, looking along it: a segment on the plane from near to
// far covers a few hundred pixels while its far end is nine times as deep as its near end.
CameraMatrices grazing_camera() {
    const ViewCamera view{.eye = {0.0f, 0.6f, 1.0f}, .target = {0.0f, 0.0f, -4.0f}, .fov_deg = 50.0f,
                          .znear = 0.1f, .zfar = 40.0f};
    return camera_matrices(view, float(kWidth) / float(kHeight), Bounds{{-1.0f, -1.0f, -20.0f}, {1.0f, 1.0f, 1.0f}});
}

LinePath floor_segment() {
    LinePath path{.type = LineType::Crease};
    path.vertices.push_back({.position = {-0.3f, 0.0f, -0.6f}, .face = 0, .bary = {1, 0, 0}, .alpha = 1.0f});
    path.vertices.push_back({.position = {0.3f, 0.0f, -14.0f}, .face = 0, .bary = {1, 0, 0}, .alpha = 1.0f});
    return path;
}

// The window depth of the plane y = 0 at each pixel centre (background where the ray misses it).
std::vector<float> floor_depth(const CameraMatrices& camera) {
    const glm::mat4 inverse = glm::inverse(camera.view_proj);
    std::vector<float> depth(size_t(kWidth) * kHeight, 1.0f);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec2 ndc((float(x) + 0.5f) / kWidth * 2.0f - 1.0f, (float(y) + 0.5f) / kHeight * 2.0f - 1.0f);
            const glm::vec4 a = inverse * glm::vec4(ndc, 0.0f, 1.0f), b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 near = glm::vec3(a) / a.w, far = glm::vec3(b) / b.w;
            if (near.y * far.y > 0.0f) continue;
            const glm::vec3 hit = glm::mix(near, far, near.y / (near.y - far.y));
            const glm::vec4 clip = camera.view_proj * glm::vec4(hit, 1.0f);
            depth[size_t(y) * kWidth + size_t(x)] = clip.z / clip.w;
        }
    return depth;
}

TEST(VisibilitySamples, SurfacePointsProjectToTheirPixels) {
    const CameraMatrices camera = grazing_camera();
    const std::vector<float> background(size_t(kWidth) * kHeight, 1.0f);
    const DepthImage image{kWidth, kHeight, background, camera.znear, camera.zfar};
    const std::vector<ScreenPath> runs = compute_visibility({floor_segment()}, camera, image);
    const glm::vec3 ends[2] = {project_to_pixel(camera, floor_segment().vertices[0].position, kWidth, kHeight),
                               project_to_pixel(camera, floor_segment().vertices[1].position, kWidth, kHeight)};
    ASSERT_EQ(runs.size(), 1u) << ends[0].x << " " << ends[0].y << " " << ends[1].x << " " << ends[1].y;
    const ScreenPath& run = runs.front();
    ASSERT_GT(run.samples.size(), 40u);  // the segment covers about 100 px
    ASSERT_GT(ends[1].z / ends[0].z, 8.0f);  // the far end is nine times as deep
    double worst_px = 0.0, worst_depth = 0.0;
    for (const ScreenSample& sample : run.samples) {
        const glm::vec3 projected = project_to_pixel(camera, sample.position, kWidth, kHeight);
        worst_px = std::max(worst_px, double(glm::distance(glm::vec2(projected), sample.pixel)));
        worst_depth = std::max(worst_depth, double(std::abs(projected.z - sample.depth) / projected.z));
    }
    // Float rounding of the projection only (screen fractions put the middle samples tens of
    // pixels off on this segment).
    EXPECT_LT(worst_px, 0.01);
    EXPECT_LT(worst_depth, 1e-5);
}

TEST(VisibilitySamples, ALineOnTheSurfaceIsVisibleAllAlong) {
    // The segment lies on the floor: every sample is at the depth the floor has at its pixel
    // and must pass the depth test (with eye depths interpolated on screen, the samples in the
    // middle were behind the floor by up to half the segment's depth range).
    const CameraMatrices camera = grazing_camera();
    const std::vector<float> depth = floor_depth(camera);
    const DepthImage image{kWidth, kHeight, depth, camera.znear, camera.zfar};
    const std::vector<ScreenPath> runs = compute_visibility({floor_segment()}, camera, image);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_TRUE(runs.front().visible);
    EXPECT_GT(runs.front().samples.size(), 40u);
}

}  // namespace
}  // namespace lw

namespace lw {
namespace {

// A camera looking straight down at the plane z = 0: points there project linearly.
CameraMatrices facing_camera() {
    const ViewCamera view{.eye = {0.0f, 0.0f, 5.0f}, .target = {0.0f, 0.0f, 0.0f}, .fov_deg = 50.0f,
                          .znear = 0.1f, .zfar = 40.0f};
    return camera_matrices(view, float(kWidth) / float(kHeight), Bounds{{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}});
}

LinePath plane_path(const std::vector<glm::vec2>& points, bool closed) {
    LinePath path{.type = LineType::Silhouette, .closed = closed};
    for (const glm::vec2& p : points)
        path.vertices.push_back({.position = {p.x, p.y, 0.0f}, .face = 0, .bary = {1, 0, 0}, .alpha = 1.0f});
    return path;
}

// A path is sampled only near the image: one that runs a million pixels past it on both sides
// gives the samples of the image's width and a margin (it gave 400,000 and, panned farther,
// ran out of memory), its arc length s still counted from its start; one wholly far off
// gives none.
TEST(VisibilitySamples, PathsAreSampledOnlyNearTheImage) {
    const CameraMatrices camera = facing_camera();
    const std::vector<float> background(size_t(kWidth) * kHeight, 1.0f);
    const DepthImage image{kWidth, kHeight, background, camera.znear, camera.zfar};
    const LinePath across = plane_path({{-4000.0f, 0.1f}, {4000.0f, 0.1f}}, false);
    const glm::vec2 start(project_to_pixel(camera, across.vertices[0].position, kWidth, kHeight));
    ASSERT_LT(start.x, -1e5f);
    const std::vector<ScreenPath> runs = compute_visibility({across}, camera, image);
    size_t samples = 0;
    for (const ScreenPath& run : runs) {
        samples += run.samples.size();
        EXPECT_FALSE(run.closed);
        for (const ScreenSample& s : run.samples) {
            EXPECT_GE(s.pixel.x, -64.0f - 2.0f);
            EXPECT_LE(s.pixel.x, float(kWidth) + 64.0f + 2.0f);
            EXPECT_NEAR(s.s, s.pixel.x - start.x, 1e-6f * std::abs(start.x) + 0.5f);  // s from the path's start
        }
    }
    EXPECT_GE(samples, size_t(kWidth / 2));
    EXPECT_LE(samples, size_t((kWidth + 2 * 64) / 2 + 4));
    const std::vector<ScreenPath> visible_runs = [&] {
        std::vector<ScreenPath> v;
        for (const ScreenPath& run : runs)
            if (run.visible) v.push_back(run);
        return v;
    }();
    ASSERT_EQ(visible_runs.size(), 1u);  // across the image, ending at its edges as before
    EXPECT_LT(visible_runs[0].samples.front().pixel.x, 2.0f);
    EXPECT_GT(visible_runs[0].samples.back().pixel.x, float(kWidth) - 2.0f);

    const LinePath far_off = plane_path({{-4000.0f, 0.1f}, {-3000.0f, 0.1f}}, false);
    EXPECT_TRUE(compute_visibility({far_off}, camera, image).empty());
}

// A loop that leaves the image is cut where it goes past the margin; the piece through its
// start goes on after its last piece, so the part on the image is one run of increasing s.
TEST(VisibilitySamples, ALoopLeavingTheImageIsOneRunOnIt) {
    const CameraMatrices camera = facing_camera();
    const std::vector<float> background(size_t(kWidth) * kHeight, 1.0f);
    const DepthImage image{kWidth, kHeight, background, camera.znear, camera.zfar};
    // A circle of 200 px about the middle of the image's left edge, starting on the image
    // (angle 0, 200 px to the right): on the image from -37° to 37°, past the margin on the left.
    std::vector<glm::vec2> circle;
    const float origin_x = project_to_pixel(camera, {0, 0, 0}, kWidth, kHeight).x;
    const float px_per_unit = project_to_pixel(camera, {1, 0, 0}, kWidth, kHeight).x - origin_x;
    const glm::vec2 centre(-origin_x / px_per_unit, 0.0f);  // pixel x = 0
    for (int i = 0; i < 720; ++i) {
        const float a = 6.2831853f * float(i) / 720.0f;
        circle.push_back(centre + 200.0f / px_per_unit * glm::vec2(std::cos(a), std::sin(a)));
    }
    const std::vector<ScreenPath> runs = compute_visibility({plane_path(circle, true)}, camera, image);
    std::vector<const ScreenPath*> visible;
    for (const ScreenPath& run : runs)
        if (run.visible) visible.push_back(&run);
    ASSERT_EQ(visible.size(), 1u);
    for (size_t i = 1; i < visible[0]->samples.size(); ++i)
        EXPECT_GT(visible[0]->samples[i].s, visible[0]->samples[i - 1].s) << i;
    EXPECT_FALSE(visible[0]->closed);
}

}  // namespace
}  // namespace lw
