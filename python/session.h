// python/session.h — what `linework.Session` is on the C++ side (bound in session_bind.cpp).
//
// Input:  a scene (file, bare model, dict, or a mesh as arrays) and the command line's
//         overrides (device, size, camera, fov).
// Output: per call, one frame of a SceneSession as Python data: `Polyline`s grouped as the
//         SVG groups them, an H×W×4 image (and depth), a `FrameResult` per frame of a sequence.
//
// The scene is kept as the JSON it was described with (`base_`); configure() merges a patch
// into it (RFC 7396) and parses the whole again with the scene-file parser, so every edit is
// checked as a file would be and leaves the session unchanged when it is wrong.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "convert.h"
#include "session/scene_session.h"

namespace lw::py {

// Frame numbers a session takes: far past any animation, far from int's limits.
inline constexpr int kMaxFrame = 10'000'000;
inline void check_frame(long long f, const char* name) {
    if (f < -kMaxFrame || f > kMaxFrame)
        throw pyb::value_error(std::string(name) + ": " + std::to_string(f) + " is past ±" + std::to_string(kMaxFrame));
}

struct SessionArgs {
    std::string device = "auto", compute = "auto";
    std::optional<bool> validation;
    std::optional<std::pair<int, int>> size;
    CameraOverride camera;
    std::optional<float> fov;
    bool coherent = false;  // parameterize every set (RANSAC fits in each frame's lines)
    pyb::object vertices = pyb::none(), faces = pyb::none(), normals = pyb::none();
    std::string name = "mesh";  // an array mesh's name in errors and line sets' "models"
};

// The per-point data of one frame's polylines, packed: each Polyline's arrays are views into
// it (made when read), so that lines() costs one pass over the samples, not six arrays per
// path. Kept alive by every Polyline and every array view of it.
struct LineStore {
    std::vector<float> points;    // 2 per sample: pixels, x right, y down (the SVG's coordinates)
    std::vector<uint8_t> visible; // 1 per sample (a NumPy bool)
    std::vector<float> fade;      // the line's fade alpha (suggestive contours fade in)
    std::vector<float> depth;     // eye depth
    std::vector<float> s;         // screen arc length from the run's start, pixels
    std::vector<float> position;  // 3 per sample: the world-space surface point
};

// One visible (or hidden) run of a brush path, as the SVG's <polyline> holds it, with what
// the SVG does not: per point its visibility, fade, eye depth, arc length and surface point.
struct Polyline {
    std::shared_ptr<const LineStore> store;
    size_t first = 0, count = 0;  // its samples in the store
    bool closed = false;          // a whole loop: the SVG repeats the first point
    uint32_t qi = 0;              // occlusion level (ScreenPath::qi)
    std::string type, line_set;
};

struct FrameResult {
    int index = 0;
    float seconds = 0.0f;
    pyb::object image = pyb::none(), depth = pyb::none(), lines = pyb::none();
    pyb::dict timings;
};

class Session {
public:
    Session(const pyb::object& scene, const SessionArgs& args);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // The frame at `frame` (a frame number of the scene's range) or `seconds`.
    pyb::object render(std::optional<int> frame, std::optional<float> seconds, bool depth);
    pyb::dict lines(std::optional<int> frame, std::optional<float> seconds, bool hidden);
    // Frame `index` of `range` (a sequence's), or of the scene's range at `frame` / `seconds`.
    FrameResult frame_result(int index, const FrameRange& range, bool image, bool depth, bool lines, bool hidden);
    FrameResult frame_at(std::optional<int> frame, std::optional<float> seconds, bool image, bool depth, bool lines,
                         bool hidden);
    FrameRange range() const { return session_->default_frames(); }
    float fps() const { return session_->desc().animation.fps; }

    SceneSession::Snapshot snapshot() const { return session_->snapshot(); }
    void restore(const SceneSession::Snapshot& snapshot) {
        const std::lock_guard lock(gpu_mutex());
        reading_input([&] {  // another scene's snapshot is bad input, refused before any change
            session_->restore(snapshot);
            return 0;
        });
    }

    pyb::object scene() const;                  // the scene as described and configured
    void configure(const pyb::object& patch);   // merged into it, checked, applied
    std::pair<int, int> size() const { return {int(session_->target().width), int(session_->target().height)}; }

    ViewCamera camera() const;
    void set_camera(const std::optional<glm::vec3>& eye, const std::optional<glm::vec3>& target,
                    const std::optional<glm::vec3>& up, std::optional<float> fov);
    void set_view_matrix(const glm::mat4& view);
    CameraMatrices matrices() const;
    void reset_camera() { camera_.reset(); }  // back to the scene's (as configured)

    std::vector<std::string> validation_messages() const { return ctx_->validation_messages(); }

private:
    SceneDesc parse(const nlohmann::json& scene) const;
    static void check_camera(const ViewCamera& camera, const std::string& name);
    void open(SceneDesc desc);
    Frame draw(const PathTime& when, uint64_t seed, const FrameOutputs& outputs);
    PathTime time_of(std::optional<int> frame, std::optional<float> seconds, uint64_t& seed) const;
    pyb::dict lines_of(const Frame& frame, bool hidden) const;
    FrameResult result(int index, const PathTime& when, uint64_t seed, bool image, bool depth, bool lines, bool hidden);

    std::shared_ptr<Context> ctx_;
    nlohmann::json base_;
    std::filesystem::path source_;     // relative paths resolve beside it; errors name it
    bool bare_model_ = false;          // a .gltf/.glb given alone: the command line's defaults
    std::filesystem::path model_path_;
    std::vector<Model> models_;        // a mesh given as arrays
    CameraOverride camera_override_;   // the constructor's eye, target, up
    std::optional<float> fov_;
    bool coherent_ = false;
    std::optional<ViewCamera> camera_;        // set_camera(): replaces the scene's in every frame
    std::optional<ViewCamera> scene_camera_;  // configure()'s "camera": the scene's fixed camera now
    PathTime last_when_;
    std::unique_ptr<SceneSession> session_;
};

}  // namespace lw::py
