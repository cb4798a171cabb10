#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace lw {

ViewCamera frame_bounds(const Bounds& bounds, float aspect, float fov_deg) {
    const float radius = std::max(bounds.radius(), 1e-6f);
    const float half_fov_y = glm::radians(fov_deg) * 0.5f;
    const float half_fov_x = std::atan(std::tan(half_fov_y) * aspect);
    const float half_fov = std::min(half_fov_y, half_fov_x);
    const float distance = 1.05f * radius / std::sin(half_fov);
    const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    return ViewCamera{.eye = bounds.center() + distance * direction, .target = bounds.center(), .fov_deg = fov_deg};
}

CameraMatrices camera_matrices(const ViewCamera& camera, float aspect, const Bounds& bounds) {
    const glm::vec3 forward = camera.target - camera.eye;
    if (glm::length(forward) <= 0.0f) throw Error("camera: eye and target coincide");
    if (glm::length(glm::cross(forward, camera.up)) <= 1e-6f * glm::length(forward) * glm::length(camera.up))
        throw Error("camera: up is parallel to the view direction");

    CameraMatrices m;
    m.view = glm::lookAt(camera.eye, camera.target, camera.up);
    // Near and far from the bounding sphere, seen along the view axis.
    const float radius = std::max(bounds.radius(), 1e-6f);
    const float center_depth = glm::dot(bounds.center() - camera.eye, glm::normalize(forward));
    m.zfar = camera.zfar > 0.0f ? camera.zfar : (center_depth + radius) * 1.01f;
    m.znear = camera.znear > 0.0f ? camera.znear : std::max(center_depth - radius, 0.0f) * 0.99f;
    m.znear = std::max(m.znear, m.zfar * 1e-4f);
    if (m.zfar <= m.znear) m.zfar = m.znear * 2.0f;
    m.proj = glm::perspective(glm::radians(camera.fov_deg), aspect, m.znear, m.zfar);
    m.proj[1][1] *= -1.0f;  // Vulkan's clip-space y points down
    m.view_proj = m.proj * m.view;
    return m;
}

glm::vec3 project_to_pixel(const CameraMatrices& m, glm::vec3 world, float width, float height) {
    const glm::vec4 clip = m.view_proj * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * width, (ndc.y * 0.5f + 0.5f) * height, clip.w};
}

}  // namespace lw
