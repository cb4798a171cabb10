// engine/scene/camera.h — a look-at camera and its Vulkan matrices.
//
// Conventions: right-handed world, y up (glTF); Vulkan clip space with depth in [0, 1] and
// y pointing down, so the projection's y is flipped here once and nowhere else. Pixel
// coordinates have (0, 0) at the top-left corner of the top-left pixel.
#pragma once

#include <glm/glm.hpp>

#include "scene/triangle_mesh.h"

namespace lw {

struct ViewCamera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_deg = 40.0f;  // vertical field of view
    float znear = 0.0f;     // 0 = derived from the scene bounds
    float zfar = 0.0f;      // 0 = derived from the scene bounds
};

struct CameraMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::mat4 view_proj{1.0f};
    float znear = 0.0f, zfar = 0.0f;
};

// A camera that looks at the bounds' centre from the front (+z) and a little above, far
// enough that the bounding sphere fits the narrower field of view with a 5 % margin.
[[nodiscard]] ViewCamera frame_bounds(const Bounds& bounds, float aspect, float fov_deg = 40.0f);

// View and projection for an image of the given aspect (width / height). Unset near/far
// planes enclose the bounds' sphere.
[[nodiscard]] CameraMatrices camera_matrices(const ViewCamera& camera, float aspect, const Bounds& bounds);

// World point to pixel coordinates (x right, y down) and its clip w; w <= 0 is behind the eye.
[[nodiscard]] glm::vec3 project_to_pixel(const CameraMatrices& m, glm::vec3 world, float width, float height);

}  // namespace lw
