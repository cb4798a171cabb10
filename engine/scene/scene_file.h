// engine/scene/scene_file.h — scene files (JSON) and bare models as one description.
//
// Input:  a scene file (see README "Scene files") or a bare .gltf/.glb path.
// Output: `SceneDesc` — model paths (resolved against the scene file's folder), image
//         size, an optional fixed camera or a camera path, the animation timeline, and the
//         surface style.
//
// Every key is checked: an unknown key or a value of the wrong type or range is an
// lw::Error naming the file and the key path (e.g. `camera.fov`). No silent defaults for
// what the user wrote; defaults only for what they left out.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/animation.h"
#include "scene/camera.h"
#include "scene/camera_path.h"
#include "scene/style.h"
#include "scene/layer_desc.h"

namespace lw {

// The timeline of an image sequence ("animation" in the scene file).
struct AnimationDesc {
    bool play = false;                 // the file has "animation": clips play; else the rest pose
    // "clip": a name, an index or "all" (the default; the string "all" means every clip,
    // even if one is named so) for every model, or an array of them, one per model in
    // "model" order (models seldom share clip names). One entry here applies to every model.
    std::vector<ClipChoice> clips{ClipChoice{}};
    float fps = 24.0f;                 // "fps": frame f is at f / fps seconds, for the clips and
                                       // camera keyframes alike
    std::optional<FrameRange> frames;  // "frames": [first, last], inclusive; absent: the
                                       // renderer's default (frame 0 to the clips' duration)
};

// The clips model number `model` plays (`animation.clips`: one for all, or one per model).
inline const ClipChoice& clip_of_model(const AnimationDesc& animation, size_t model) {
    return animation.clips.size() == 1 ? animation.clips.front() : animation.clips.at(model);
}

// "coherence": the stroke parameterization's settings for the whole scene (Bénard et al.
// 2010 §4; the command line's --param, --splat-radius, --inlier-px, --min-stroke-length and
// --length-scale override them). A line set's own "coherence" overrides policy and
// length_scale for that set. Absent: the defaults the session picks.
struct SceneCoherence {
    std::optional<ParamPolicy> policy;            // absent: coherent
    std::optional<float> splat_radius_px;         // δ of the splat sprites; absent: twice the sample spacing
    std::optional<float> inlier_px;               // RANSAC's inlier distance along the path
    std::optional<float> min_stroke_length_px;    // shorter visible paths are not drawn as strokes
    std::optional<float> length_scale;            // κ for every set and layer; absent: each its own
};

struct SceneDesc {
    std::filesystem::path source;                // the scene file; empty for a bare model
    std::string description;                     // "description": what the image is for (not drawn)
    std::vector<std::filesystem::path> models;   // none only in a scene of vector layers alone
    int width = 960;
    int height = 720;
    std::optional<ViewCamera> camera;            // absent: frame the bounding box
    // Fixed, or "camera.orbit" (the axis is the camera's up, +y for the framing camera, and
    // the centre its target), or "camera_path" keyframes (then `camera` is absent).
    CameraPath camera_path;
    AnimationDesc animation;
    float fov_deg = 40.0f;                       // used when framing
    SurfaceStyle style;
    LinesDesc lines;
    SceneCoherence coherence;
    std::vector<VectorLayerDesc> layers;         // 2D drawings over the 3D frame, in order
};

// Reads and validates a scene file. Throws lw::Error("<file>: <key>: <problem>").
[[nodiscard]] SceneDesc load_scene_file(const std::filesystem::path& path);

// Parses scene JSON text; `source` names it in errors and anchors relative model paths.
// `models_given`: the caller brings the models (meshes as arrays), so "model" must be absent.
[[nodiscard]] SceneDesc parse_scene_json(const std::string& text, const std::filesystem::path& source,
                                         bool models_given = false);

// Scene JSON for `desc` with its fixed `camera` (what the viewer saves as "the current
// view"), in the format load_scene_file reads. Model, SLAM and ribbon paths are written
// relative to `dest_dir` (the folder the file will be in) when they can be. Written: models,
// size, fov, camera, shading and colours, lines (every type, thresholds, styles), the line
// sets (every key), the coherence settings given, the animation's clip and fps. Not written: camera paths (the view is one fixed camera) and
// vector layers.
[[nodiscard]] std::string scene_json(const SceneDesc& desc, const ViewCamera& camera,
                                     const std::filesystem::path& dest_dir);

// A scene of one model with every default.
[[nodiscard]] SceneDesc scene_for_model(const std::filesystem::path& model);

// Why hidden-line settings of "lines" (scene keys, --hidden) are refused beside "line_sets":
// they style the shorthand's lines only, and a set draws its hidden lines itself.
inline constexpr const char* kHiddenBesideLineSets =
    "styles the hidden lines of the \"lines\" shorthand only; with \"line_sets\" a set draws hidden lines "
    "itself (\"select\": {\"visibility\": \"hidden\"} or {\"qi\": [1, 1]}, with a style such as "
    "\"dashes\": [6, 4])";

// A file a scene key names (a style's SLAM or ribbon exemplar, a layer's strokes), checked
// when the scene loads: a missing one is refused naming the scene and the key as well as the
// file ("spot.json: line_sets[0].style.slam: nope.exr: no such file"), where the file's
// reader would name the file alone. Parsing does not look for files (a scene may be read
// where they are not: tests, scene editors).
void check_key_file(const SceneDesc& desc, const std::string& key, const std::string& path);

// "spot.json: line_sets[0].style.slam: " (or "scene: …" for a scene given as data): what an
// error about a file a scene key names starts with.
[[nodiscard]] std::string key_file_prefix(const SceneDesc& desc, const std::string& key);

// Returns `read()`, a reader of a file a scene key names; its error, which names the file
// alone, gains the scene and the key in front: "spot.json: layers[0].slam: bad.exr: cannot
// read SLAM: …".
template <class Read>
auto read_key_file(const SceneDesc& desc, const std::string& key, Read&& read) -> decltype(read()) {
    try {
        return read();
    } catch (const Error& e) {
        throw Error(key_file_prefix(desc, key) + e.what(), e.exit_code());
    }
}

// True when the path names a model (by extension: .gltf, .glb, .obj, .ply) rather than a scene file.
[[nodiscard]] bool is_model_path(const std::filesystem::path& path);

// Throws lw::Error naming the file unless its extension is a model's (.gltf, .glb, .obj, .ply)
// or a scene file's (.json): a PNG, an .stl or a typo gets "unsupported model format", not the
// JSON parser's complaint about its first byte; a folder, whatever its name, is named one.
void check_scene_or_model_path(const std::filesystem::path& path);

}  // namespace lw
