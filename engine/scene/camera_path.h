// engine/scene/camera_path.h — a camera that moves over an image sequence.
//
// Input:  a `CameraPath` (from the scene file's "camera.orbit" or "camera_path"), the base
//         camera (the scene's fixed camera, or the one framing the bounds) and the frame's
//         place in time.
// Output: the `ViewCamera` for that frame.
//
// Two kinds of motion, each timed the way it is written:
// - Orbit: a turntable. The base camera (eye, target and up) turns about an axis through
//   the centre (default: the base camera's target, i.e. the bounds centre for a framing
//   camera, which then stays put) by `degrees` × progress, where progress runs 0 → 1 over
//   the rendered frame range. Distances to the centre are kept; positive degrees turn
//   counter-clockwise seen from the tip of the axis (right-hand rule).
// - Keyframes: eye, target, up and fov at times in seconds, interpolated linearly between
//   keys (up renormalized) and held before the first and after the last key. near/far come
//   from the base camera.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"

namespace lw {

struct OrbitPath {
    float degrees = 360.0f;                  // total turn over the frame range
    glm::vec3 axis{0.0f, 1.0f, 0.0f};        // need not be unit length; must not be zero
    std::optional<glm::vec3> center;         // absent: the base camera's target
};

struct CameraKeyframe {
    float time = 0.0f;                       // seconds
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_deg = 40.0f;
};

struct CameraPath {
    enum class Kind { Fixed, Orbit, Keyframes };
    Kind kind = Kind::Fixed;                 // Fixed: the base camera every frame
    OrbitPath orbit;                         // Kind::Orbit
    std::vector<CameraKeyframe> keyframes;   // Kind::Keyframes: at least one, times increasing
};

// A frame's place in time: `progress` ∈ [0, 1] across the rendered frame range (drives
// orbits), `seconds` on the animation clock (drives keyframes and glTF animation).
struct PathTime {
    float progress = 0.0f;
    float seconds = 0.0f;
};

// Inclusive range of frame numbers; frame f is at f / fps seconds.
struct FrameRange {
    int first = 0;
    int last = 0;
};

// The time of frame `frame` of `range` at `fps` frames per second. A one-frame range has
// progress 0. Progress reaches 1 on the last frame, so an orbit's last frame shows the full
// turn (for 360°, the first frame again: a seamless loop leaves the last frame out, as it
// does for a looping clip whose last key repeats its first). Throws lw::Error for fps <= 0
// or last < first.
[[nodiscard]] PathTime frame_time(int frame, const FrameRange& range, float fps);

// The camera at `when`. Throws lw::Error for an orbit about a zero axis or a keyframe path
// without keyframes.
[[nodiscard]] ViewCamera camera_at(const CameraPath& path, const ViewCamera& base, const PathTime& when);

}  // namespace lw
