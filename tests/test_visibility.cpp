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
