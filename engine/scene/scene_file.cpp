#include "scene/scene_file.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image.h"
#include "core/text.h"
#include "scene/line_set_file.h"
#include "scene/model.h"
#include "scene/object_reader.h"

namespace lw {

namespace {

using json = nlohmann::json;
using scene_detail::ObjectReader;


// A look-at camera must see something: eye and target apart, up not along the view.
void check_view(const ObjectReader& r, const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    if (eye == target) r.fail("eye and target coincide");
    if (glm::length(glm::cross(target - eye, up)) < 1e-9f) r.fail_key("up", "is parallel to the view direction");
}

// "camera": a fixed camera (eye and target), optionally turned by "orbit" degrees over the
// frame range. Eye and target may both be left out: the camera frames the bounding box (and
// turns, with "orbit"), and only "fov" (the framing field of view) may accompany them.
void read_camera(ObjectReader& parent, const std::filesystem::path& file, SceneDesc& scene) {
    ObjectReader r(parent.at("camera"), "camera", file);
    ViewCamera camera;
    const bool has_eye = r.has("eye"), has_target = r.has("target"), has_orbit = r.has("orbit");
    if (has_orbit) {
        scene.camera_path.kind = CameraPath::Kind::Orbit;
        scene.camera_path.orbit.degrees = static_cast<float>(r.number("orbit", -36000.0, 36000.0));
    }
    if (!has_eye && !has_target) {
        for (const char* key : {"up", "near", "far"})
            if (r.has(key))
                r.fail_key(key, has_orbit ? "needs eye and target (an orbit without them turns the framing camera)"
                                          : "needs eye and target (without them the camera frames the model)");
        if (r.has("fov")) scene.fov_deg = static_cast<float>(r.number("fov", 1.0, 170.0));
        r.reject_unknown();
        return;
    }
    // Every key is known before any is read, so that a misspelt one ("targt") is named
    // before the key it stands for is said to be missing.
    const bool has_up = r.has("up"), has_fov = r.has("fov"), has_near = r.has("near"), has_far = r.has("far");
    r.reject_unknown();
    if (!has_eye) r.fail_key("eye", "required");
    if (!has_target) r.fail_key("target", "required");
    camera.eye = r.vec3("eye");
    camera.target = r.vec3("target");
    if (has_up) camera.up = r.vec3("up");
    if (has_fov) camera.fov_deg = static_cast<float>(r.number("fov", 1.0, 170.0));
    if (has_near) camera.znear = static_cast<float>(r.number("near", 1e-6, 1e30));
    if (has_far) camera.zfar = static_cast<float>(r.number("far", 1e-6, 1e30));
    check_view(r, camera.eye, camera.target, camera.up);
    if (camera.zfar > 0.0f && camera.znear > 0.0f && camera.zfar <= camera.znear) r.fail_key("far", "must exceed near");
    // A turntable turns about the camera's own up: +y unless the scene is z-up.
    scene.camera_path.orbit.axis = camera.up;
    scene.fov_deg = camera.fov_deg;
    scene.camera = camera;
}

// "camera_path": {"keyframes": [{"time", "eye", "target", "up"?, "fov"?}, ...]}, times in
// seconds and strictly increasing; a keyframe without "fov" takes the scene's "fov".
CameraPath read_camera_path(ObjectReader& parent, const std::filesystem::path& file, float default_fov) {
    ObjectReader r(parent.at("camera_path"), "camera_path", file);
    if (!r.has("keyframes")) r.fail_key("keyframes", "required");
    const json& keys = r.at("keyframes");
    if (!keys.is_array() || keys.empty()) r.fail_key("keyframes", "expected a non-empty array of keyframes");
    CameraPath path;
    path.kind = CameraPath::Kind::Keyframes;
    for (size_t i = 0; i < keys.size(); ++i) {
        ObjectReader k(keys[i], "camera_path.keyframes[" + std::to_string(i) + "]", file);
        for (const char* key : {"time", "eye", "target"})
            if (!k.has(key)) k.fail_key(key, "required");
        CameraKeyframe key;
        key.time = static_cast<float>(k.number("time", 0.0, 1e6));
        if (!path.keyframes.empty() && !(key.time > path.keyframes.back().time))
            k.fail_key("time", "must be later than the previous keyframe's (" +
                                   k.at("time").dump() + " after " + keys[i - 1].at("time").dump() + ")");
        key.eye = k.vec3("eye");
        key.target = k.vec3("target");
        if (k.has("up")) key.up = k.vec3("up");
        key.fov_deg = k.has("fov") ? static_cast<float>(k.number("fov", 1.0, 170.0)) : default_fov;
        k.reject_unknown();
        check_view(k, key.eye, key.target, key.up);
        path.keyframes.push_back(key);
    }
    r.reject_unknown();
    return path;
}

// One "clip" value: a name, an index or "all". `key` names it in errors ("clip" or "clip[1]").
ClipChoice read_clip(ObjectReader& r, const json& v, const std::string& key) {
    ClipChoice clip;
    if (v.is_string()) {
        clip.name = v.get<std::string>();
        if (clip.name.empty()) r.fail_key(key, "empty name (an unnamed clip is chosen by its index)");
        clip.kind = clip.name == "all" ? ClipChoice::Kind::All : ClipChoice::Kind::Name;
    } else if (v.is_number_integer()) {
        const long long index = v.get<long long>();
        if (index < 0 || index > 1000000) r.fail_key(key, "clip index must be 0 or more, got " + v.dump());
        clip.kind = ClipChoice::Kind::Index;
        clip.index = static_cast<int>(index);
    } else {
        r.fail_key(key, "expected a clip name, a clip index or \"all\"" + std::string(key == "clip" ? " (or an array of them, one per model)" : "") +
                            ", got " + std::string(v.type_name()) + " " + v.dump());
    }
    return clip;
}

// "animation": {"clip": name | index | "all" | [one per model], "fps": 24, "frames":
// [first, last]}, all optional. Clip names are checked against the models when they are
// loaded (load_scene), the array's length against "model" here.
AnimationDesc read_animation(ObjectReader& parent, const std::filesystem::path& file, size_t models) {
    ObjectReader r(parent.at("animation"), "animation", file);
    AnimationDesc desc;
    desc.play = true;
    if (r.has("clip")) {
        const json& v = r.at("clip");
        if (v.is_array()) {
            if (v.empty()) r.fail_key("clip", "an empty array (give one clip per model, or one for all)");
            if (models > 0 && v.size() != models && v.size() != 1)
                r.fail_key("clip", std::to_string(v.size()) + " clips for " + std::to_string(models) +
                                       " models (one per model, in \"model\" order, or one for all)");
            desc.clips.clear();
            for (size_t i = 0; i < v.size(); ++i)
                desc.clips.push_back(read_clip(r, v[i], "clip[" + std::to_string(i) + "]"));
        } else {
            desc.clips = {read_clip(r, v, "clip")};
        }
    }
    if (r.has("fps")) {
        const json& fps = r.at("fps");
        if (!fps.is_number() || !(fps.get<double>() > 0.0 && fps.get<double>() <= 1000.0))
            r.fail_key("fps", "must be a number of frames a second over 0, up to 1000, got " + fps.dump());
        desc.fps = fps.get<float>();
    }
    if (r.has("frames")) {
        const json& f = r.at("frames");
        if (!f.is_array() || f.size() != 2 || !f[0].is_number_integer() || !f[1].is_number_integer())
            r.fail_key("frames", "expected [first, last] frame numbers");
        const long long first = f[0].get<long long>(), last = f[1].get<long long>();
        if (first < 0 || last > 10000000) r.fail_key("frames", "frame numbers must be 0..10000000");
        if (last < first)
            r.fail_key("frames", "last frame " + std::to_string(last) + " is before first frame " + std::to_string(first));
        desc.frames = FrameRange{static_cast<int>(first), static_cast<int>(last)};
    }
    r.reject_unknown();
    return desc;
}

// `ridge_threshold`: lines.ridge gave a threshold (lines.valley may not give another).
LineStyle read_line_type(ObjectReader& lines, LineType type, const std::filesystem::path& file, LinesDesc& desc,
                         bool& ridge_threshold) {
    const std::string name = line_type_name(type);
    ObjectReader r(lines.at(name), "lines." + name, file);
    LineStyle style = desc.styles[static_cast<size_t>(type)];
    LineParams& p = desc.params;
    bool enabled = line_type_enabled(p, type);
    if (r.has("enabled")) enabled = r.boolean("enabled");
    if (r.has("width")) style.width = static_cast<float>(r.number("width", 0.1, 64.0));
    if (r.has("color")) style.color = r.color("color");
    if (r.has("slam")) style.slam = r.file_path("slam", "a SLAM file (.exr)");
    if (r.has("taper")) style.taper_px = static_cast<float>(r.number("taper", 0.0, 4096.0));
    if (r.has("ribbon")) style.ribbon = r.file_path("ribbon", "a ribbon exemplar image (.png)");
    if (r.has("ribbon_scale")) style.ribbon_scale = static_cast<float>(r.number("ribbon_scale", 1.0, 4096.0));
    if (r.has("ribbon_scale") && style.ribbon.empty())
        r.fail_key("ribbon_scale", "sizes a ribbon's exemplar, and this type has no \"ribbon\"");
    if (!style.ribbon.empty() && !style.slam.empty())
        r.fail_key("ribbon", "a line type is drawn with a SLAM or a ribbon, not both");
    if (!style.ribbon.empty() && r.has("taper"))  // as a ribbon set's stroke keys are said
        r.warn("taper: a ribbon is drawn along the paths at its width, and a taper changes nothing there");
    if (float* threshold = line_type_threshold(p, type); threshold && r.has("threshold")) {
        const float value = static_cast<float>(r.number("threshold", 0.0, 10.0));
        // Ridges and valleys share rtsc's one rv_thresh.
        if (type == LineType::Valley && ridge_threshold && value != *threshold)
            r.fail_key("threshold", "ridges and valleys share one threshold (rtsc's rv_thresh); lines.ridge gives " +
                                        number_text(*threshold));
        ridge_threshold = ridge_threshold || type == LineType::Ridge;
        *threshold = value;
    }
    if (type == LineType::Suggestive && r.has("fade")) p.fade = r.boolean("fade");
    if (type == LineType::Crease && r.has("angle")) p.crease_angle_deg = static_cast<float>(r.number("angle", 0.0, 180.0));
    r.reject_unknown();
    set_line_type_enabled(p, type, enabled);
    return style;
}

// Beside "line_sets" a type's switch and style under "lines" draw nothing (the sets select and
// style the types); its thresholds still apply. Scenes written by earlier builds carry them at
// their defaults, which are not mentioned.
void warn_per_type_styles_beside_sets(const ObjectReader& scene, const LinesDesc& lines) {
    const LinesDesc defaults;
    std::string said;
    for (int t = 0; t < kLineTypeCount; ++t) {
        const LineType type = LineType(t);
        const LineStyle &s = lines.styles[size_t(t)], &d = defaults.styles[size_t(t)];
        std::string keys;
        const auto note = [&](bool differs, const char* key) {
            if (differs) keys += (keys.empty() ? "" : ", ") + std::string(key);
        };
        note(line_type_enabled(lines.params, type) != line_type_enabled(defaults.params, type), "enabled");
        note(s.width != d.width, "width");
        note(s.color != d.color, "color");
        note(s.slam != d.slam, "slam");
        note(s.taper_px != d.taper_px, "taper");
        note(s.ribbon != d.ribbon, "ribbon");
        note(s.ribbon_scale != d.ribbon_scale, "ribbon_scale");
        if (!keys.empty()) said += (said.empty() ? "lines." : "; lines.") + std::string(line_type_name(type)) + ": " + keys;
    }
    if (!said.empty())
        scene.warn(said + ": beside \"line_sets\" a type's switch and style under \"lines\" change nothing (the sets "
                          "select and style the types; thresholds still apply)");
}

LinesDesc read_lines(ObjectReader& parent, const std::filesystem::path& file) {
    LinesDesc desc;
    const json& v = parent.at("lines");
    if (v.is_boolean()) {
        desc.enabled = v.get<bool>();
        return desc;
    }
    ObjectReader r(v, "lines", file);
    bool ridge_threshold = false;
    for (int t = 0; t < kLineTypeCount; ++t) {
        const LineType type = static_cast<LineType>(t);
        if (r.has(line_type_name(type))) desc.styles[size_t(t)] = read_line_type(r, type, file, desc, ridge_threshold);
    }
    if (r.has("hidden")) {
        const std::string h = r.string_of("hidden", {"none", "dashed", "faint"});
        desc.hidden = h == "dashed" ? HiddenLines::Dashed : h == "faint" ? HiddenLines::Faint : HiddenLines::None;
    }
    if (r.has("hidden_levels")) {
        const double n = r.number("hidden_levels", 0, 1000);
        if (n != std::floor(n)) r.fail_key("hidden_levels", "expected a whole number of surfaces (0: all hidden lines)");
        desc.hidden_levels = uint32_t(n);
        // (Beside "line_sets" neither key applies: the scene reader says what does.)
        if (n > 0 && desc.hidden == HiddenLines::None && !parent.has("line_sets"))
            r.fail_key("hidden_levels", "hidden lines are not drawn (\"hidden\" is \"none\"): set it to \"dashed\" or "
                                        "\"faint\", or remove \"hidden_levels\"");
    }
    if (r.has("sample_spacing")) desc.sample_spacing_px = static_cast<float>(r.number("sample_spacing", 0.25, 64.0));
    if (r.has("contours")) desc.params.contours = contour_mode(r.string_of("contours", {"smooth", "mesh", "auto"}));
    if (r.has("curvature")) desc.params.curvature = curvature_fit(r.string_of("curvature", {"exact", "trimesh2"}));
    r.reject_unknown();
    return desc;
}

}  // namespace

bool is_model_path(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    return ext == ".gltf" || ext == ".glb" || is_mesh_file_path(path);
}

void check_scene_or_model_path(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(path.string() + ": a folder, not a model or a scene file");
    const std::string ext = lower(path.extension().string());
    if (is_model_path(path) || ext == ".json") return;
    throw Error(path.string() + ": unsupported model format" + extension_phrase(ext) +
                ": Linework reads glTF models (.gltf, .glb), OBJ and PLY meshes (.obj, .ply) and scene files (.json)");
}

SceneDesc scene_for_model(const std::filesystem::path& model) {
    SceneDesc scene;
    scene.models = {model};
    return scene;
}

// One 2D transform of a layer: {"center": [x, y], "scale": s, "rotate": degrees}.
LayerTransform read_layer_transform(ObjectReader& r) {
    LayerTransform t;
    if (r.has("center")) {
        const json& c = r.at("center");
        if (!c.is_array() || c.size() != 2 || !c[0].is_number() || !c[1].is_number() ||
            !(std::abs(c[0].get<double>()) <= 1e7) || !(std::abs(c[1].get<double>()) <= 1e7))
            r.fail_key("center", "expected [x, y] in drawing units (|x|, |y| up to 1e7)");
        t.center = glm::vec2(float(c[0].get<double>()), float(c[1].get<double>()));
    }
    if (r.has("scale")) t.scale = static_cast<float>(r.number("scale", 1e-4, 1e4));
    if (r.has("rotate")) t.rotate_deg = static_cast<float>(r.number("rotate", -36000.0, 36000.0));
    return t;
}

// "coherence": {"policy", "splat_radius", "inlier_distance", "min_stroke_length",
// "length_scale"}, all optional; pixels but for κ.
SceneCoherence read_scene_coherence(ObjectReader& scene, const std::filesystem::path& file) {
    ObjectReader r(scene.at("coherence"), "coherence", file);
    SceneCoherence c;
    const auto in = [&](const char* key, ValueRange range) { return float(r.number(key, range.min, range.max)); };
    if (r.has("policy")) c.policy = param_policy_named(r.string_of("policy", kParamPolicyNameSet));
    if (r.has("splat_radius")) c.splat_radius_px = in("splat_radius", kSplatRadiusRange);
    if (r.has("inlier_distance")) c.inlier_px = in("inlier_distance", kInlierDistanceRange);
    if (r.has("min_stroke_length")) c.min_stroke_length_px = in("min_stroke_length", kMinStrokeLengthRange);
    if (r.has("length_scale")) c.length_scale = in("length_scale", kLengthScaleRange);
    r.reject_unknown();
    return c;
}

// "layers": [{"strokes": FILE, "color", "width_scale", "scale_widths", "outline", "fill",
//             "slam" | "ribbon" (+ "ribbon_scale"), "taper", "transform" | "keyframes"}, ...]
std::vector<VectorLayerDesc> read_layers(ObjectReader& scene, const std::filesystem::path& file) {
    const json& list = scene.at("layers");
    if (!list.is_array()) scene.fail_key("layers", "expected an array of layers");
    std::vector<VectorLayerDesc> layers;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list[i], "layers[" + std::to_string(i) + "]", file);
        VectorLayerDesc layer;
        if (!r.has("strokes")) r.fail_key("strokes", "required (a stroke file, .json or .svg)");
        layer.strokes = r.string_of("strokes");
        if (layer.strokes.empty()) r.fail_key("strokes", "expected a stroke file (.json or .svg)");
        layer.strokes = scene_detail::resolve_against(file, layer.strokes);
        if (r.has("color")) layer.color = r.color("color");
        if (r.has("width_scale")) layer.width_scale = static_cast<float>(r.number("width_scale", 0.0, 1000.0));
        if (r.has("scale_widths")) layer.scale_widths = r.boolean("scale_widths");
        if (r.has("outline")) layer.outline = r.boolean("outline");
        if (r.has("fill")) layer.fill = r.color("fill");
        if (r.has("slam")) layer.slam = scene_detail::resolve_against(file, r.string_of("slam"));
        if (r.has("ribbon")) layer.ribbon = scene_detail::resolve_against(file, r.string_of("ribbon"));
        if (!layer.slam.empty() && !layer.ribbon.empty())
            r.fail_key("ribbon", "a layer is drawn with a SLAM or a ribbon, not both");
        if (r.has("ribbon_scale")) layer.ribbon_scale = static_cast<float>(r.number("ribbon_scale", 1.0, 4096.0));
        if (r.has("ribbon_scale") && layer.ribbon.empty())
            r.fail_key("ribbon_scale", "sizes a ribbon's exemplar, and this layer has no \"ribbon\"");
        if (r.has("taper")) layer.taper_px = static_cast<float>(r.number("taper", 0.0, 4096.0));
        // Settings that would draw nothing, or change nothing, were taken in silence.
        if (!layer.outline && !layer.fill && layer.ribbon.empty())
            r.fail_key("outline", "false and no \"fill\": the layer would draw nothing");
        if (!(layer.width_scale > 0.0f) && !layer.fill && layer.ribbon.empty())
            r.fail_key("width_scale", "0 and no \"fill\": the layer would draw nothing");
        if (r.has("transform")) {
            ObjectReader t(r.at("transform"), r.path("transform"), file);
            layer.keys.push_back({0.0f, read_layer_transform(t)});
            t.reject_unknown();
        }
        if (r.has("keyframes")) {
            if (r.has("transform")) r.fail_key("keyframes", "cannot be combined with transform");
            const json& keys = r.at("keyframes");
            if (!keys.is_array() || keys.empty()) r.fail_key("keyframes", "expected a non-empty array");
            for (size_t k = 0; k < keys.size(); ++k) {
                ObjectReader key(keys[k], r.path("keyframes") + "[" + std::to_string(k) + "]", file);
                if (!key.has("time")) key.fail_key("time", "required (seconds)");
                const auto time = static_cast<float>(key.number("time", 0.0, 1e6));
                if (!layer.keys.empty() && time <= layer.keys.back().time)
                    key.fail_key("time", "keyframes must be in increasing time");
                layer.keys.push_back({time, read_layer_transform(key)});
                key.reject_unknown();
            }
        }
        r.reject_unknown();
        layers.push_back(std::move(layer));
    }
    return layers;
}

SceneDesc parse_scene_json(const std::string& text, const std::filesystem::path& source, bool models_given) {
    json root;
    // JSON parsers keep one of a key given twice in an object (nlohmann the last): a scene
    // edited by hand with "model" twice drew one of them without a word.
    struct Open {  // an object or array being read: where it is, and an object's keys so far
        bool array = false;
        int index = -1;   // an array's element being read
        std::string key;  // an object's key being read
        std::set<std::string> keys;
    };
    std::vector<Open> open;
    const auto where = [&] {  // "lines.crease", "line_sets[0].style": the object being read
        std::string path;
        for (size_t i = 0; i + 1 < open.size(); ++i)
            path += open[i].array ? "[" + std::to_string(open[i].index) + "]" : (path.empty() ? "" : ".") + open[i].key;
        return path;
    };
    const json::parser_callback_t once = [&](int, json::parse_event_t event, json& parsed) {
        using E = json::parse_event_t;
        if ((event == E::object_start || event == E::array_start || event == E::value) && !open.empty() &&
            open.back().array)
            ++open.back().index;
        if (event == E::object_start || event == E::array_start) open.push_back({.array = event == E::array_start});
        if ((event == E::object_end || event == E::array_end) && !open.empty()) open.pop_back();
        if (event == E::key && !open.empty()) {
            open.back().key = parsed.get<std::string>();
            if (!open.back().keys.insert(open.back().key).second)
                throw Error(source.string() + ": " + (open.size() > 1 ? where() + ": " : "") + "\"" + open.back().key +
                            "\" is given twice in one object (JSON would keep only one of them): give it once");
        }
        return true;
    };
    try {
        root = json::parse(text, once);
    } catch (const json::exception& e) {  // syntax, and numbers past double's range (out_of_range)
        std::string what = e.what();
        const auto colon = what.find("parse error");
        throw Error(source.string() + ": invalid JSON: " + (colon == std::string::npos ? json_message(what) : what.substr(colon)));
    }

    SceneDesc scene;
    scene.source = source;
    ObjectReader r(root, "", source);

    if (r.has("version") && r.at("version") != 1)
        r.fail_key("version", "this Linework reads version 1 scene files, got " + r.at("version").dump());
    if (r.has("description")) scene.description = r.string_of("description");
    if (r.has("layers")) scene.layers = read_layers(r, source);
    if (models_given && r.has("model")) r.fail_key("model", "not allowed beside a mesh given as arrays");
    if (!r.has("model") && scene.layers.empty() && !models_given) {
        // A misspelt "model" is what is missing more often than a model: name the key first.
        static const std::set<std::string> kTopKeys{"version", "description", "model", "size", "fov", "camera",
                                                     "camera_path", "animation", "shading", "color", "materials",
                                                     "background", "samples", "lines", "line_sets", "layers",
                                                     "coherence"};
        for (const auto& [key, value] : root.items())
            if (!kTopKeys.count(key)) r.fail_key(key, "unknown key (and no \"model\")");
        r.fail_key("model", "required (a .gltf/.glb, .obj or .ply path, or an array of them) unless the scene has layers");
    }
    if (r.has("model")) {
        const json& m = r.at("model");
        std::vector<std::string> names;
        if (m.is_string()) {
            names.push_back(m.get<std::string>());
        } else if (m.is_array() && !m.empty()) {
            for (const auto& item : m) {
                if (!item.is_string()) r.fail_key("model", "array items must be strings");
                names.push_back(item.get<std::string>());
            }
        } else {
            r.fail_key("model", "expected a path or a non-empty array of paths");
        }
        for (const auto& name : names) {
            std::filesystem::path p(name);
            if (!is_model_path(p)) r.fail_key("model", "\"" + name + "\" is not a model file (.gltf, .glb, .obj or .ply)");
            const std::filesystem::path resolved = scene_detail::resolve_against(source, name);
            // A model is drawn where its file places it: a second copy would lie on the first,
            // its faces fused with the first's into edges of four faces, which break its lines.
            const auto same_file = [](const std::filesystem::path& a, const std::filesystem::path& b) {
                std::error_code error_a, error_b;  // a folder it cannot read: compare as written
                const std::filesystem::path ca = std::filesystem::weakly_canonical(a, error_a),
                                            cb = std::filesystem::weakly_canonical(b, error_b);
                return error_a || error_b ? a.lexically_normal() == b.lexically_normal() : ca == cb;
            };
            for (size_t i = 0; i < scene.models.size(); ++i)
                if (same_file(scene.models[i], resolved))
                    r.fail_key("model", "\"" + name + "\" is listed twice (items " + std::to_string(i) + " and " +
                                            std::to_string(scene.models.size()) +
                                            "); a scene draws each model where its file places it, so a second copy "
                                            "would lie on the first");
            scene.models.push_back(resolved);
        }
    }
    if (r.has("size")) {
        const json& s = r.at("size");
        if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer())
            r.fail_key("size", "expected [width, height] in pixels");
        const long long w = s[0].get<long long>(), h = s[1].get<long long>();
        if (w < 1 || h < 1 || w > kLargestImageSide || h > kLargestImageSide)
            r.fail_key("size", "width and height must be 1.." + std::to_string(kLargestImageSide));
        scene.width = static_cast<int>(w);
        scene.height = static_cast<int>(h);
    }
    if (r.has("fov")) scene.fov_deg = static_cast<float>(r.number("fov", 1.0, 170.0));
    if (r.has("camera")) read_camera(r, source, scene);
    if (r.has("camera_path")) {
        if (r.has("camera")) r.fail_key("camera_path", "cannot be combined with camera (the keyframes set the camera)");
        scene.camera_path = read_camera_path(r, source, scene.fov_deg);
    }
    if (r.has("animation")) scene.animation = read_animation(r, source, scene.models.size());
    if (r.has("shading")) {
        const std::string s = r.string_of("shading", {"flat", "toon", "unlit", "none"});
        if (s == "flat") scene.style.shading = Shading::Flat;
        if (s == "toon") scene.style.shading = Shading::Toon;
        if (s == "unlit") scene.style.shading = Shading::Unlit;
        if (s == "none") scene.style.draw_surface = false;
    }
    if (r.has("color")) scene.style.color = r.color("color");
    if (r.has("materials")) scene.style.materials = r.boolean("materials");
    if (r.has("background")) {
        if (r.at("background").is_string() && r.at("background").get<std::string>() == "transparent")
            scene.style.transparent = true;
        else
            scene.style.background = r.color("background");
    }
    if (r.has("samples")) {
        const json& n = r.at("samples");
        if (!n.is_number_integer() || (n.get<long long>() != 1 && n.get<long long>() != 4 && n.get<long long>() != 8))
            r.fail_key("samples", "expected 1, 4 or 8 (samples per pixel of the shaded surface)");
        scene.style.samples = static_cast<uint32_t>(n.get<long long>());
    }
    if (r.has("lines")) scene.lines = read_lines(r, source);
    if (r.has("coherence")) scene.coherence = read_scene_coherence(r, source);
    if (r.has("line_sets")) {
        if (!scene.lines.enabled) r.fail_key("line_sets", "cannot be combined with \"lines\": false");
        scene.lines.sets = read_line_sets(r, source);
        // "hidden" and "hidden_levels" style the shorthand's lines; a set draws hidden lines
        // itself, so beside "line_sets" they would change nothing.
        if (scene.lines.hidden != HiddenLines::None || scene.lines.hidden_levels > 0)
            r.fail_key(scene.lines.hidden != HiddenLines::None ? "lines.hidden" : "lines.hidden_levels",
                       std::string(kHiddenBesideLineSets));
        warn_per_type_styles_beside_sets(r, scene.lines);
    }
    r.reject_unknown();
    return scene;
}

void check_key_file(const SceneDesc& desc, const std::string& key, const std::string& path) {
    std::error_code ec;
    if (path.empty() || std::filesystem::exists(path, ec)) return;
    throw Error(key_file_prefix(desc, key) + path + ": no such file");
}

std::string key_file_prefix(const SceneDesc& desc, const std::string& key) {
    return (desc.source.empty() ? std::string("scene") : desc.source.string()) + ": " + key + ": ";
}

SceneDesc load_scene_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw Error(path.string() + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open scene file (" + (std::filesystem::exists(path) ? "unreadable" : "no such file") + ")");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return parse_scene_json(buffer.str(), path);
}

}  // namespace lw
