// python/session_bind.cpp — the Python face of session.h: classes, arguments, docstrings.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "core/text.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "session.h"
#include "synthesizers.h"

namespace lw::py {

namespace {

std::optional<glm::vec3> optional_vec3(const pyb::object& value, const char* name) {
    if (value.is_none()) return std::nullopt;
    return to_vec3(value, name);
}

// A view of one polyline's samples in its frame's store (`columns` values per sample); the
// array keeps the store alive.
template <typename T, typename V>
pyb::array_t<T> store_view(const Polyline& p, const std::vector<V> LineStore::*member, size_t columns) {
    static_assert(sizeof(T) == sizeof(V));
    const std::vector<V>& values = (*p.store).*member;
    auto* keep = new std::shared_ptr<const LineStore>(p.store);
    pyb::capsule base(keep, [](void* k) { delete static_cast<std::shared_ptr<const LineStore>*>(k); });
    std::vector<pyb::ssize_t> shape{pyb::ssize_t(p.count)};
    if (columns > 1) shape.push_back(pyb::ssize_t(columns));
    // Read-only: every read of the attribute is a view of the same frame's store.
    std::vector<pyb::ssize_t> strides{pyb::ssize_t(sizeof(T) * columns)};
    if (columns > 1) strides.push_back(pyb::ssize_t(sizeof(T)));
    T* data = const_cast<T*>(reinterpret_cast<const T*>(values.data() + p.first * columns));
    pyb::array_t<T> view(pyb::buffer_info(data, sizeof(T), pyb::format_descriptor<T>::format(), pyb::ssize_t(shape.size()),
                                          shape, strides, true),
                         base);
    view.attr("setflags")(pyb::arg("write") = false);
    return view;
}

pyb::array_t<float> vec3_array(const glm::vec3& v) { return to_array(std::vector<float>{v.x, v.y, v.z}, {3}); }

pyb::array_t<float> matrix_array(const glm::mat4& m) {
    std::vector<float> rows(16);  // row-major for NumPy: element [r][c] is column c's r
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows[size_t(r * 4 + c)] = m[c][r];
    return to_array(std::move(rows), {4, 4});
}

glm::mat4 array_matrix(const pyb::array& array) {
    auto a = pyb::array_t<float, pyb::array::c_style | pyb::array::forcecast>::ensure(array);
    if (!a || a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4) throw pyb::value_error("view: expected a 4×4 matrix");
    glm::mat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = a.data()[r * 4 + c];
    return m;
}

pyb::dict camera_dict(const ViewCamera& c) {
    pyb::dict d;
    d["eye"] = vec3_array(c.eye);
    d["target"] = vec3_array(c.target);
    d["up"] = vec3_array(c.up);
    d["fov"] = c.fov_deg;
    return d;
}

// `session.frames(...)`: a coherent sequence, frame by frame as it is iterated.
struct FrameIterator {
    Session* session;
    pyb::object keep;  // the Session object, alive while iterating
    FrameRange range;
    int next;
    bool image, depth, lines, hidden;
    FrameResult step() {
        while (next < range.first) session->frame_result(next++, range, false, false, false, false);  // warm-up
        if (next > range.last) throw pyb::stop_iteration();
        return session->frame_result(next++, range, image, depth, lines, hidden);
    }
};

// The triangles of a model file in world space, rest pose, as the renderer merges them.
pyb::tuple load_mesh(const std::filesystem::path& path) {
    SceneDesc desc = scene_for_model(path);
    const LoadedScene scene = reading_input([&] {
        if (!std::filesystem::exists(path)) throw Error(path.string() + ": no such file");
        if (!is_model_path(path))
            throw Error(path.string() + ": unsupported model format" + extension_phrase(lower(path.extension().string())) +
                        ": load_mesh reads .gltf, .glb, .obj and .ply models");
        return load_scene(desc);
    });
    TriangleMesh mesh = scene.mesh;
    const auto n = pyb::ssize_t(mesh.positions.size()), m = pyb::ssize_t(mesh.triangle_count());
    std::vector<float> v, normals;
    for (const glm::vec3& p : mesh.positions) v.insert(v.end(), {p.x, p.y, p.z});
    for (const glm::vec3& p : mesh.normals) normals.insert(normals.end(), {p.x, p.y, p.z});
    std::vector<int32_t> f(mesh.indices.begin(), mesh.indices.end());
    return pyb::make_tuple(to_array(std::move(v), {n, 3}), to_array(std::move(f), {m, 3}),
                           to_array(std::move(normals), {n, 3}));
}

}  // namespace

void bind_session(pyb::module_& m) {
    pyb::class_<Polyline>(m, "Polyline",
                          "One run of a brush path as the SVG's centre-line <polyline> holds it (closed loops without the "
                          "repeated first point), with per-point data the SVG lacks.")
        .def_property_readonly("points", [](const Polyline& p) { return store_view<float>(p, &LineStore::points, 2); },
                               "N×2 float32 pixels, x right, y down: the SVG's coordinates")
        .def_property_readonly("visible", [](const Polyline& p) { return store_view<bool>(p, &LineStore::visible, 1); },
                               "N bool: visible (a run has one visibility)")
        .def_property_readonly("fade", [](const Polyline& p) { return store_view<float>(p, &LineStore::fade, 1); },
                               "N float32: the line's fade alpha (suggestive contours fade in)")
        .def_property_readonly("depth", [](const Polyline& p) { return store_view<float>(p, &LineStore::depth, 1); },
                               "N float32: eye depth along the view axis")
        .def_property_readonly("s", [](const Polyline& p) { return store_view<float>(p, &LineStore::s, 1); },
                               "N float32: screen arc length from the run's start, pixels")
        .def_property_readonly("position", [](const Polyline& p) { return store_view<float>(p, &LineStore::position, 3); },
                               "N×3 float32: the world-space surface point")
        .def_readonly("closed", &Polyline::closed, "a whole loop, entirely visible")
        .def_readonly("qi", &Polyline::qi,
                      "occlusion level: 0 visible; hidden, the surfaces in front where a line set selects \"qi\" "
                      "(else 1)")
        .def_readonly("type", &Polyline::type, "line type: silhouette, suggestive, ... (README \"Line types\")")
        .def_readonly("line_set", &Polyline::line_set, "the line set (SVG group) it belongs to")
        .def("__len__", [](const Polyline& p) { return p.count; })
        .def("__repr__", [](const Polyline& p) {
            return "<linework.Polyline " + p.type + " in " + p.line_set + ", " + std::to_string(p.count) +
                   " points" + (p.closed ? ", closed" : "") + ">";
        });

    pyb::class_<FrameResult>(m, "FrameResult", "One frame of Session.frames().")
        .def_readonly("index", &FrameResult::index, "frame number")
        .def_readonly("seconds", &FrameResult::seconds, "time on the animation clock")
        .def_readonly("image", &FrameResult::image, "H×W×4 uint8 (None unless image=True)")
        .def_readonly("depth", &FrameResult::depth, "H×W float32 window depth in [0, 1] (None unless depth=True)")
        .def_readonly("lines", &FrameResult::lines, "as Session.lines() (None unless lines=True)")
        .def_readonly("timings", &FrameResult::timings,
                      "milliseconds per stage: total_ms, extract_ms, chain_ms, visibility_ms, coherence_ms, and "
                      "gpu_PASS_ms per timed GPU pass (gpu_surface_ms, gpu_lines_draw_ms, …)");

    pyb::class_<SceneSession::Snapshot>(m, "Snapshot",
                                        "The temporal state after a frame (every line set's and layer's "
                                        "parameterization); Session.restore() goes on from it exactly.")
        .def_readonly("seconds", &SceneSession::Snapshot::seconds, "the pose it was taken in");

    pyb::class_<FrameIterator>(m, "FrameIterator", "Session.frames(): a coherent sequence, drawn as it is iterated.")
        .def("__iter__", [](FrameIterator& it) -> FrameIterator& { return it; })
        .def("__next__", &FrameIterator::step);

    pyb::class_<Session>(m, "Session", R"(A scene made live, drawn as `linework render` draws it.

Session(scene=None, *, device="auto", size=None, eye=None, target=None, up=None, fov=None,
        vertices=None, faces=None, normals=None, name="mesh", compute="auto",
        coherent=False, validation=None)

scene: a scene file (.json), a model (.gltf, .glb, .obj, .ply), a dict of scene keys (the scene file's
format; relative paths from the working folder), or None with vertices (N×3) and faces
(M×3) — a dict may come beside them, without "model". device: "auto", "cpu" (lavapipe),
"gpu" or an index of `linework devices`. size=(w, h), eye/target/up (x, y, z) and fov
(degrees) override the scene's as the command line's flags do. coherent: parameterize
every line set's paths (RANSAC from frame to frame) even where no style needs it, as
`--dump-paths` does; a set whose strokes read no parameter is fitted beside its drawing and
drawn as without it (the module returns no parameters: it changes only the time a frame
takes and what snapshot() holds).
validation: the Khronos layer on (None: LINEWORK_VALIDATION decides); a call that makes it
speak raises RuntimeError. Bad input raises ValueError with the command line's message.)")
        .def(pyb::init([](const pyb::object& scene, const std::string& device, const pyb::object& size,
                          const pyb::object& eye, const pyb::object& target, const pyb::object& up,
                          std::optional<float> fov, const pyb::object& vertices, const pyb::object& faces,
                          const pyb::object& normals, const std::string& name, const std::string& compute,
                          bool coherent, std::optional<bool> validation) {
                 SessionArgs a{.device = device, .compute = compute, .validation = validation, .fov = fov,
                               .coherent = coherent, .vertices = vertices, .faces = faces, .normals = normals,
                               .name = name};
                 if (!size.is_none()) {
                     std::pair<int, int> wh;
                     try {
                         wh = size.cast<std::pair<int, int>>();
                     } catch (const pyb::cast_error&) {
                         throw pyb::value_error("size: expected (width, height), two integers");
                     }
                     check_image_size(wh.first, wh.second);
                     a.size = wh;
                 }
                 a.camera = {optional_vec3(eye, "eye"), optional_vec3(target, "target"), optional_vec3(up, "up")};
                 return with_python_warnings([&] { return std::make_unique<Session>(scene, a); });
             }),
             pyb::arg("scene") = pyb::none(), pyb::kw_only(), pyb::arg("device") = "auto",
             pyb::arg("size") = pyb::none(), pyb::arg("eye") = pyb::none(), pyb::arg("target") = pyb::none(),
             pyb::arg("up") = pyb::none(), pyb::arg("fov") = pyb::none(), pyb::arg("vertices") = pyb::none(),
             pyb::arg("faces") = pyb::none(), pyb::arg("normals") = pyb::none(), pyb::arg("name") = "mesh",
             pyb::arg("compute") = "auto", pyb::arg("coherent") = false, pyb::arg("validation") = pyb::none())
        .def("render", [](Session& s, std::optional<float> t, std::optional<int> frame, bool depth) {
                 return s.render(frame, t, depth);
             },
             pyb::arg("t") = pyb::none(), pyb::kw_only(), pyb::arg("frame") = pyb::none(), pyb::arg("depth") = false,
             "The frame as an H×W×4 uint8 array (the PNG `linework render` writes); with depth=True a tuple "
             "(image, H×W float32 window depth, 1 = background). t: seconds on the animation clock, or frame: a "
             "frame number (default: the first of the scene's range); the camera path's progress runs over the "
             "scene's range.")
        .def("lines", [](Session& s, std::optional<float> t, std::optional<int> frame, bool hidden) {
                 return s.lines(frame, t, hidden);
             },
             pyb::arg("t") = pyb::none(), pyb::kw_only(), pyb::arg("frame") = pyb::none(), pyb::arg("hidden") = false,
             "The frame's lines: a dict from line set (with per-type keys the type names silhouette, "
             "suggestive, crease, border) to a list of Polyline — the SVG's NAME-centerlines polylines. hidden=True "
             "adds the hidden runs that sets selecting hidden lines hold.")
        .def("frame", [](Session& s, std::optional<float> t, std::optional<int> frame, bool image, bool depth,
                            bool lines, bool hidden) { return s.frame_at(frame, t, image, depth, lines, hidden); },
             pyb::arg("t") = pyb::none(), pyb::kw_only(), pyb::arg("frame") = pyb::none(), pyb::arg("image") = true, pyb::arg("depth") = false, pyb::arg("lines") = true, pyb::arg("hidden") = false,
             "One frame with its image and its lines (and depth) from the same drawing, as a FrameResult. Every "
             "call of render(), lines() and frame() draws a frame: where a style is parameterized (a SLAM, "
             "dashes, coherent=True), consecutive calls are consecutive frames of a sequence.")
        .def(
            "frames",
            [](pyb::object self, const pyb::object& frames, bool image, bool depth, bool lines, bool hidden,
               int warmup) {
                Session& s = self.cast<Session&>();
                FrameRange range = s.range();
                if (!frames.is_none()) {
                    long long first = 0, last = 0;
                    try {
                        if (pyb::isinstance(frames, pyb::module_::import("builtins").attr("range"))) {
                            first = frames.attr("start").cast<long long>();
                            last = frames.attr("stop").cast<long long>() - 1;
                            if (frames.attr("step").cast<long long>() != 1 || last < first)
                                throw pyb::value_error("frames: expected consecutive frames, range(first, last + 1)");
                        } else {
                            const auto ab = frames.cast<std::pair<long long, long long>>();
                            first = ab.first;
                            last = ab.second;
                            if (last < first) throw pyb::value_error("frames: expected (first, last), first <= last");
                        }
                    } catch (const pyb::cast_error&) {
                        throw pyb::value_error("frames: expected range(first, last + 1) or (first, last), integers");
                    }
                    check_frame(first, "frames");
                    check_frame(last, "frames");
                    range = {int(first), int(last)};
                }
                if (warmup < 0 || warmup > kMaxFrame) throw pyb::value_error("warmup: must be 0 to " + std::to_string(kMaxFrame));
                check_frame(range.first - (long long)warmup, "frames (first - warmup)");
                return FrameIterator{&s, self, range, range.first - warmup, image, depth, lines, hidden};
            },
            pyb::arg("frames") = pyb::none(), pyb::kw_only(), pyb::arg("image") = true, pyb::arg("depth") = false,
            pyb::arg("lines") = false, pyb::arg("hidden") = false, pyb::arg("warmup") = 0,
            "Iterate a coherent sequence: frames is range(first, last + 1) or (first, last) (default: the "
            "scene's range), warmup frames before it are drawn and not returned — as `linework render --frames "
            "A:B --warmup K`. Yields FrameResult.")
        .def("snapshot", &Session::snapshot, "The temporal state after the last frame.")
        .def("restore", &Session::restore, pyb::arg("snapshot"),
             "Go on from a snapshot: the next frame continues its parameterization exactly.")
        .def_property_readonly("scene", &Session::scene,
                               "The scene keys as given, as a dict: a scene file's (its relative paths are the "
                               "file's), a dict's, or none for a bare model; with size= and configure()'s changes "
                               "merged. A bare model's path and eye=, target=, up=, fov= are not keys in it, so it "
                               "need not open a Session by itself: edit this session with configure() instead.")
        .def("configure", [](Session& s, const pyb::object& changes) { with_python_warnings([&] { s.configure(changes); }); },
             pyb::arg("changes"),
             "Merge scene keys into the scene (RFC 7396: nested dicts merge, None deletes), check them as a "
             "scene file, apply: lines, line_sets, shading and colours, size and camera take effect live; any "
             "other key reopens the session (its temporal state starts afresh, and a camera from set_camera() is "
             "dropped). A bad key raises ValueError and changes nothing.")
        .def_property_readonly("size", &Session::size, "(width, height) in pixels")
        .def_property_readonly("camera", [](const Session& s) { return camera_dict(s.camera()); },
                               "The camera of the next frame: dict(eye, target, up, fov).")
        .def(
            "set_camera",
            [](Session& s, const pyb::object& eye, const pyb::object& target, const pyb::object& up,
               std::optional<float> fov, const pyb::object& view) {
                if (!view.is_none()) {
                    if (!eye.is_none() || !target.is_none() || !up.is_none())
                        throw pyb::value_error("view: give a view matrix or eye/target/up, not both");
                    s.set_view_matrix(array_matrix(view));
                }
                s.set_camera(optional_vec3(eye, "eye"), optional_vec3(target, "target"), optional_vec3(up, "up"), fov);
            },
            pyb::kw_only(), pyb::arg("eye") = pyb::none(), pyb::arg("target") = pyb::none(),
            pyb::arg("up") = pyb::none(), pyb::arg("fov") = pyb::none(), pyb::arg("view") = pyb::none(),
            "Set the camera of every following frame (replacing the scene's camera and camera path): any of "
            "eye, target, up (x, y, z) and fov (degrees), or view, a 4×4 world-to-camera look-at matrix.")
        .def("reset_camera", &Session::reset_camera, "Back to the scene's camera (and camera path).")
        .def_property_readonly("view_matrix", [](const Session& s) { return matrix_array(s.matrices().view); },
                               "4×4 float32 world-to-camera matrix of the camera")
        .def_property_readonly("projection_matrix", [](const Session& s) { return matrix_array(s.matrices().proj); },
                               "4×4 float32 projection (Vulkan clip space, depth 0..1)")
        .def_property_readonly("frame_range", [](const Session& s) { return pyb::make_tuple(s.range().first, s.range().last); },
                               "(first, last): the frames a render draws without a range")
        .def_property_readonly("fps", &Session::fps, "frames per second of the scene's animation clock")
        .def_property_readonly("validation_messages", &Session::validation_messages,
                               "messages of the validation layer not yet raised (it is on with validation=True "
                               "or LINEWORK_VALIDATION=1)");

    m.def("load_mesh", &load_mesh, pyb::arg("path"),
          "The triangles of a model (.gltf, .glb, .obj, .ply) in world space (rest pose) as the renderer merges them: "
          "(vertices N×3 float32, faces M×3 int32, normals N×3 float32).");
}

}  // namespace lw::py
