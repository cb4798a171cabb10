// engine/scene/camera_path.cpp — orbit and keyframed cameras.
#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace lw {

namespace {

ViewCamera orbit_at(const OrbitPath& orbit, const ViewCamera& base, float progress) {
    const float axis_length = glm::length(orbit.axis);
    if (!(axis_length > 0.0f) || !std::isfinite(axis_length)) throw Error("camera orbit: the axis is zero");
    const glm::vec3 center = orbit.center.value_or(base.target);
    // A rotation, so distances to the centre and the angle between view and up are kept.
    const glm::mat3 turn(glm::rotate(glm::mat4(1.0f), glm::radians(orbit.degrees * progress), orbit.axis / axis_length));
    ViewCamera camera = base;
    camera.eye = center + turn * (base.eye - center);
    camera.target = center + turn * (base.target - center);
    camera.up = turn * base.up;
    return camera;
}

ViewCamera keyframes_at(const std::vector<CameraKeyframe>& keys, const ViewCamera& base, float seconds) {
    if (keys.empty()) throw Error("camera path: no keyframes");
    const auto with = [&base](const CameraKeyframe& key) {
        ViewCamera camera = base;  // near and far
        camera.eye = key.eye;
        camera.target = key.target;
        camera.up = key.up;
        camera.fov_deg = key.fov_deg;
        return camera;
    };
    // Held before the first key and after the last (also for NaN, which compares false).
    if (!(seconds > keys.front().time)) return with(keys.front());
    if (seconds >= keys.back().time) return with(keys.back());
    const auto next = std::upper_bound(keys.begin(), keys.end(), seconds,
                                       [](float t, const CameraKeyframe& key) { return t < key.time; });
    const CameraKeyframe& a = *(next - 1);
    const CameraKeyframe& b = *next;
    const float u = (seconds - a.time) / (b.time - a.time);
    ViewCamera camera = base;
    camera.eye = glm::mix(a.eye, b.eye, u);
    camera.target = glm::mix(a.target, b.target, u);
    // Opposite ups would cancel halfway; then the earlier key's up is the better guess.
    const glm::vec3 up = glm::mix(a.up, b.up, u);
    const float up_length = glm::length(up);
    camera.up = up_length > 1e-6f ? up / up_length : a.up;
    camera.fov_deg = a.fov_deg + (b.fov_deg - a.fov_deg) * u;
    return camera;
}

}  // namespace

PathTime frame_time(int frame, const FrameRange& range, float fps) {
    if (!(fps > 0.0f) || !std::isfinite(fps)) throw Error("frame_time: fps must be positive, got " + std::to_string(fps));
    if (range.last < range.first)
        throw Error("frame_time: frame range " + std::to_string(range.first) + ".." + std::to_string(range.last) +
                    " ends before it starts");
    PathTime when;
    when.seconds = static_cast<float>(frame) / fps;
    if (range.last > range.first)
        when.progress = static_cast<float>(frame - range.first) / static_cast<float>(range.last - range.first);
    return when;
}

ViewCamera camera_at(const CameraPath& path, const ViewCamera& base, const PathTime& when) {
    switch (path.kind) {
        case CameraPath::Kind::Fixed: return base;
        case CameraPath::Kind::Orbit: return orbit_at(path.orbit, base, when.progress);
        case CameraPath::Kind::Keyframes: return keyframes_at(path.keyframes, base, when.seconds);
    }
    return base;
}

}  // namespace lw
