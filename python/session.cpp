// python/session.cpp — a Python session's scene and camera: construction from a file, a
// model, a dict or arrays; configure(); the camera by parts or by view matrix.
#include "session.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_file.h"

namespace lw::py {

namespace {

using json = nlohmann::json;

// The key path of the first float in `value` that is NaN or infinite ("lines.silhouette.width",
// "camera.eye[0]"), or nothing: JSON has no such numbers, and the json module's own complaint
// names no key.
std::optional<std::string> non_finite_at(const pyb::handle& value, const std::string& path) {
    if (pyb::isinstance<pyb::dict>(value)) {
        for (const auto& [key, item] : pyb::reinterpret_borrow<pyb::dict>(value)) {
            const std::string k = pyb::str(key);
            if (auto at = non_finite_at(item, path.empty() ? k : path + "." + k)) return at;
        }
        return std::nullopt;
    }
    if (pyb::isinstance<pyb::list>(value) || pyb::isinstance<pyb::tuple>(value)) {
        size_t i = 0;
        for (const pyb::handle item : value)
            if (auto at = non_finite_at(item, path + "[" + std::to_string(i++) + "]")) return at;
        return std::nullopt;
    }
    if (pyb::hasattr(value, "tolist") && !pyb::isinstance<pyb::str>(value))
        return non_finite_at(value.attr("tolist")(), path);
    if (pyb::isinstance<pyb::float_>(value) && !std::isfinite(value.cast<double>()))
        return (path.empty() ? std::string("the value") : path) + ": not a finite number (" +
               std::string(pyb::str(value)) + ")";
    return std::nullopt;
}

// Python data → JSON through the json module; NumPy arrays and scalars become lists/numbers.
json to_json(const pyb::object& value, const std::string& name) {
    pyb::object dumps = pyb::module_::import("json").attr("dumps");
    pyb::cpp_function listed([](const pyb::object& o) -> pyb::object {
        if (pyb::hasattr(o, "tolist")) return o.attr("tolist")();
        throw pyb::type_error("not JSON data: " + std::string(pyb::str(pyb::type::of(o))));
    });
    std::string text;
    try {
        text = dumps(value, pyb::arg("default") = listed, pyb::arg("allow_nan") = false).cast<std::string>();
    } catch (pyb::error_already_set& e) {
        if (const std::optional<std::string> at = non_finite_at(value, "")) throw pyb::value_error(name + ": " + *at);
        throw pyb::value_error(name + ": " + std::string(pyb::str(e.value())));
    }
    return json::parse(text);
}

std::string read_scene_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw pyb::value_error(path.string() + ": cannot open scene file (unreadable)");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// Keys a live session takes without starting afresh; any other change reopens it.
bool live_key(const std::string& key) {
    return key == "lines" || key == "line_sets" || key == "size" || key == "camera" || key == "fov" ||
           key == "shading" || key == "color" || key == "background" || key == "samples" || key == "version" ||
           key == "description";
}

}  // namespace

Session::Session(const pyb::object& scene, const SessionArgs& a)
    : ctx_(shared_context(a.device, a.compute, a.validation)) {
    const bool arrays = !a.vertices.is_none() || !a.faces.is_none();
    if (arrays && (a.vertices.is_none() || a.faces.is_none()))
        throw pyb::value_error("vertices and faces: give both (N×3 positions, M×3 vertex indices)");
    if (arrays)
        models_.push_back(reading_input([&] {
            return model_from_arrays(a.name, array_to_vec3(a.vertices, "vertices"), array_to_indices(a.faces, "faces"),
                                     a.normals.is_none() ? std::vector<glm::vec3>{} : array_to_vec3(a.normals, "normals"));
        }));
    // The scene as described: the file's JSON, {} beside a bare model or arrays, or the dict.
    source_ = "scene";  // a dict: relative paths from the working folder
    if (scene.is_none()) {
        if (!arrays) throw pyb::value_error("scene: give a scene file, a model, a dict, or vertices and faces");
        base_ = json::object();
    } else if (pyb::isinstance<pyb::dict>(scene)) {
        base_ = to_json(scene, "scene");
    } else {
        if (arrays) throw pyb::value_error("scene: a file and a mesh as arrays: give one (or a dict beside the arrays)");
        std::filesystem::path path;
        try {
            path = scene.cast<std::filesystem::path>();
        } catch (const pyb::cast_error&) {
            throw pyb::type_error("scene: expected a path (str or os.PathLike), a dict or None, got " +
                                  std::string(pyb::str(pyb::type::of(scene).attr("__name__"))));
        }
        if (!std::filesystem::exists(path)) throw pyb::value_error(path.string() + ": no such file");
        (void)reading_input([&] {
            check_scene_or_model_path(path);
            return true;
        });
        if (is_model_path(path)) {
            bare_model_ = true;
            model_path_ = path;
            base_ = json::object();
        } else {
            const std::string text = read_scene_text(path);
            source_ = path;  // open(parse(base_)) below checks every key, naming the file
            try {
                base_ = json::parse(text);
            } catch (const json::exception&) {  // the scene parser's message for bad JSON
                (void)reading_input([&] { return parse_scene_json(text, path); });
                throw;
            }
        }
    }
    if (!base_.is_object()) throw pyb::value_error("scene: expected a JSON object");
    if (a.size) base_["size"] = {a.size->first, a.size->second};
    camera_override_ = a.camera;
    fov_ = a.fov;
    coherent_ = a.coherent;
    open(parse(base_));
}

Session::~Session() {
    const std::lock_guard lock(gpu_mutex());
    session_.reset();
}

SceneDesc Session::parse(const json& scene) const {
    SceneDesc desc = reading_input([&] {
        const bool given = bare_model_ || !models_.empty();
        SceneDesc d = parse_scene_json(scene.dump(), source_, given);
        if (bare_model_) {  // as scene_for_model: no scene file behind it
            d.models = {model_path_};
            d.source.clear();
        }
        return d;
    });
    // As --fov: the framing camera's and the scene camera's.
    if (fov_) {
        if (!(*fov_ > 0.0f && *fov_ < 180.0f)) throw pyb::value_error("fov: must be between 0 and 180 degrees");
        desc.fov_deg = *fov_;
        if (desc.camera) desc.camera->fov_deg = *fov_;
    }
    return desc;
}

void Session::open(SceneDesc desc) {
    SessionOptions options = default_session_options(desc);
    options.coherent = coherent_;
    options.camera = camera_override_;
    const std::lock_guard lock(gpu_mutex());
    // The new session first: when it fails (a missing model, a bad layer file) the old one
    // stays, as configure() promises.
    std::unique_ptr<SceneSession> opened =
        reading_input([&] { return std::make_unique<SceneSession>(*ctx_, std::move(desc), options, models_); });
    session_ = std::move(opened);
    check_validation(*ctx_);
    check_camera(camera(), "camera");
}

pyb::object Session::scene() const { return pyb::module_::import("json").attr("loads")(base_.dump()); }

void Session::configure(const pyb::object& patch) {
    if (!pyb::isinstance<pyb::dict>(patch)) throw pyb::value_error("configure: expected a dict of scene keys");
    const json changes = to_json(patch, "configure");
    json merged = base_;
    merged.merge_patch(changes);
    SceneDesc desc = parse(merged);  // a bad key throws here, with the session untouched
    // session_ is read below without gpu_mutex: only frames run without the GIL, and they
    // do not change what is read here (the description, the size).
    bool live = true;
    for (const auto& [key, value] : changes.items()) live = live && live_key(key);
    // A camera path (an orbit, keyframes) is the session's own: changing to or from one reopens it.
    const bool camera_change = changes.contains("camera") || changes.contains("fov");
    if (camera_change && (desc.camera_path.kind != CameraPath::Kind::Fixed ||
                          session_->desc().camera_path.kind != CameraPath::Kind::Fixed))
        live = false;
    if (!live) {  // a new session: the scene's camera again, set_camera()'s dropped
        open(std::move(desc));
        camera_.reset();
        scene_camera_.reset();
        base_ = std::move(merged);
        return;
    }
    const std::lock_guard lock(gpu_mutex());
    reading_input([&] {
        session_->set_lines(desc.lines);
        return 0;
    });
    session_->surface() = desc.style;
    if (std::pair(desc.width, desc.height) != size())
        session_->resize(uint32_t(desc.width), uint32_t(desc.height));
    if (camera_change) {  // the scene's camera now; a set_camera() camera is dropped
        const float aspect = float(desc.width) / float(desc.height);
        scene_camera_ = desc.camera ? *desc.camera
                                    : (session_->has_model() ? frame_bounds(session_->scene().bounds, aspect, desc.fov_deg)
                                                             : ViewCamera{});
        camera_.reset();
    }
    base_ = std::move(merged);
}

ViewCamera Session::camera() const {
    if (camera_) return *camera_;
    if (scene_camera_) return *scene_camera_;
    return session_->camera_at(last_when_);
}

void Session::check_camera(const ViewCamera& c, const std::string& name) {
    const glm::vec3 view = c.target - c.eye;
    if (!std::isfinite(glm::length(view)) || !std::isfinite(glm::length(c.up)))
        throw pyb::value_error(name + ": eye, target and up must be finite and not so large that their distances overflow");
    if (c.eye == c.target) throw pyb::value_error(name + ": the eye and the target coincide");
    if (glm::length(glm::cross(glm::normalize(view), c.up)) <= 1e-6f * glm::length(c.up))
        throw pyb::value_error(name + ": up is parallel to the view direction");
}

void Session::set_camera(const std::optional<glm::vec3>& eye, const std::optional<glm::vec3>& target,
                         const std::optional<glm::vec3>& up, std::optional<float> fov) {
    ViewCamera c = camera();
    if (eye) c.eye = *eye;
    if (target) c.target = *target;
    if (up) c.up = *up;
    if (fov) {
        if (!(*fov > 0.0f && *fov < 180.0f)) throw pyb::value_error("fov: must be between 0 and 180 degrees");
        c.fov_deg = *fov;
    }
    check_camera(c, "camera");
    camera_ = c;
}

void Session::set_view_matrix(const glm::mat4& view) {
    // The camera a look-at matrix came from: its inverse holds the eye (column 3), the up
    // (column 1) and the backward axis (column 2, OpenGL's convention, which lookAt makes).
    // Only a rigid look-at (rotation and translation, last row 0 0 0 1, right-handed with
    // the camera looking down −z) names a camera; a transposed, scaled or mirrored matrix
    // would be taken for another one silently.
    const glm::mat3 r(view);
    const glm::mat3 rrt = r * glm::transpose(r);
    bool rigid = std::abs(view[0][3]) < 1e-5f && std::abs(view[1][3]) < 1e-5f && std::abs(view[2][3]) < 1e-5f &&
                 std::abs(view[3][3] - 1.0f) < 1e-5f && glm::determinant(r) > 0.0f;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rigid = rigid && std::abs(rrt[i][j] - (i == j ? 1.0f : 0.0f)) < 1e-3f;
    if (!rigid)
        throw pyb::value_error("view: expected a rigid world-to-camera matrix (a rotation and a translation, last row "
                               "0 0 0 1, looking down -z, as lookAt makes; column vectors: p_camera = view @ p_world)");
    const glm::mat4 to_world = glm::inverse(view);
    const glm::vec3 eye(to_world[3]), up(to_world[1]), forward = -glm::vec3(to_world[2]);
    if (!std::isfinite(eye.x + eye.y + eye.z) || glm::length(forward) < 1e-6f)
        throw pyb::value_error("view: not an invertible view matrix");
    // The target only orients the camera (near and far come from the scene's bounds): the
    // point along the view axis as far away as the scene's centre.
    const float distance =
        session_->has_model() ? std::max(glm::length(session_->scene().bounds.center() - eye), 1e-3f) : 1.0f;
    ViewCamera c = camera();
    c.eye = eye;
    c.up = glm::normalize(up);
    c.target = eye + glm::normalize(forward) * distance;
    camera_ = c;
}

CameraMatrices Session::matrices() const {
    const auto [w, h] = size();
    return camera_matrices(camera(), float(w) / float(h), session_->scene().bounds);
}

}  // namespace lw::py
