#include "session/scene_session.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "geometry/subdivide.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "render/line_sets.h"
#include "ribbon/ribbon_strokes.h"

namespace lw {

namespace {

// What each welded face belongs to: its model (by the triangle ranges of the merged mesh)
// and its glTF material.
FaceGroups face_groups(const LoadedScene& scene, const TriangleMesh& mesh, const LineMesh& lines, int subdivide) {
    FaceGroups groups;
    if (mesh.face_material.size() != mesh.triangle_count()) return groups;
    const std::vector<size_t> model_of = model_of_faces(scene, mesh.triangle_count(), subdivide);
    std::vector<std::pair<size_t, int32_t>> keys;  // (model, material) of each group
    for (uint32_t source : lines.mesh.source_face) {
        const std::pair key{model_of[source], mesh.face_material[source]};
        auto it = std::find(keys.begin(), keys.end(), key);
        if (it == keys.end()) {
            keys.push_back(key);
            it = keys.end() - 1;
            const Model& model = scene.models[key.first];
            groups.model_names.push_back(model.path.filename().string());
            groups.material_names.push_back(key.second >= 0 && size_t(key.second) < model.materials.size()
                                                ? model.materials[size_t(key.second)].name
                                                : "");
        }
        groups.face_group.push_back(uint32_t(it - keys.begin()));
    }
    return groups;
}


// The scene's models: read from the description's paths, or given (meshes as arrays), then
// named in the description so that line sets' "models" and messages see them.
LoadedScene load_models(SceneDesc& desc, std::vector<Model> models) {
    if (models.empty()) return desc.models.empty() ? LoadedScene{.desc = desc} : load_scene(desc);
    desc.models.clear();
    for (const Model& model : models) desc.models.push_back(model.path);
    return load_scene(desc, std::move(models));
}

}  // namespace

SessionOptions default_session_options(const SceneDesc& desc) {
    SessionOptions options;
    CoherenceParams& c = options.coherence;
    const SceneCoherence& given = desc.coherence;
    c.policy = given.policy.value_or(c.policy);
    c.splat_radius_px = given.splat_radius_px.value_or(desc.lines.sample_spacing_px * 2.0f);
    c.ransac.inlier_px = given.inlier_px.value_or(c.ransac.inlier_px);
    c.min_stroke_length_px = given.min_stroke_length_px.value_or(c.min_stroke_length_px);
    // The scene's κ is not copied into options.length_scale: --length-scale overrides every
    // set's own, the scene's only fills in for sets without one (load_line_styles).
    return options;
}

SceneSession::SceneSession(const Context& ctx, SceneDesc desc, const SessionOptions& options)
    : SceneSession(ctx, std::move(desc), options, {}) {}

SceneSession::SceneSession(const Context& ctx, SceneDesc desc, const SessionOptions& options, std::vector<Model> models)
    : ctx_(&ctx),
      desc_(std::move(desc)),
      options_(options),
      scene_(load_models(desc_, std::move(models))),
      layers_(load_scene_layers(desc_)),
      renderer_(ctx, uint32_t(desc_.width), uint32_t(desc_.height), options.color_format) {
    if (options.subdivide > 0) scene_.mesh = subdivide_midpoint(scene_.mesh, options.subdivide);
    if (options.camera.eye) scene_.camera.eye = *options.camera.eye;
    if (options.camera.target) scene_.camera.target = *options.camera.target;
    if (options.camera.up) scene_.camera.up = *options.camera.up;
    if (scene_.camera.eye == scene_.camera.target) throw Error("camera: the eye and the target coincide");
    load_line_styles();
    // Layers: the same policy and tracker settings, and κ from --length-scale or the scene.
    const float layer_kappa = options.length_scale > 0.0f ? options.length_scale : desc_.coherence.length_scale.value_or(0.0f);
    for (LayerStyle& style : layers_.styles) {
        if (layer_kappa > 0.0f) style.coherence.length_scale = layer_kappa;
        style.coherence.policy = options.coherence.policy;
        style.coherence.splat_radius_px = options.coherence.splat_radius_px;
        style.coherence.ransac = options.coherence.ransac;
        style.coherence.min_stroke_length_px = options.coherence.min_stroke_length_px;
    }
    if (!layers_.descs.empty()) renderer_.set_layers(layers_.styles);
    animated_ = has_model() && desc_.animation.play && animation_duration(scene_) > 0.0f;
    if (has_model()) {
        textures_loaded_ = scene_needs_textures(scene_, desc_.style);
        renderer_.set_materials(scene_materials(scene_, scene_.mesh, options.subdivide, textures_loaded_));
        build_meshes();
    }
}

namespace {

// A file some set already read: the value of the first set in `sets` (in order, of which
// `values` are the first values.size()) whose style names the same file.
template <typename T>
std::optional<T> already_read(const std::string& file, std::string LineSetStyle::*member,
                              const std::vector<LineSetDesc>& sets, const std::vector<std::optional<T>>& values) {
    for (size_t j = 0; j < values.size() && !file.empty(); ++j)
        if (sets[j].style.*member == file && values[j]) return values[j];
    return std::nullopt;
}

// A set that names a model or material the scene does not have would select nothing, quietly:
// refused, naming the set, the key and what the scene has.
void check_line_set_groups(const std::vector<LineSetDesc>& sets, const LoadedScene& scene, const std::string& source) {
    std::vector<std::string> models, materials;
    for (const Model& model : scene.models) {
        models.push_back(model.path.filename().string());
        for (const Material& material : model.materials) materials.push_back(material.name);
    }
    for (std::vector<std::string>* names : {&models, &materials}) {  // sorted, each name once
        std::sort(names->begin(), names->end());
        names->erase(std::unique(names->begin(), names->end()), names->end());
    }
    const auto check = [&](size_t index, const char* key, const std::vector<std::string>& names,
                           const std::vector<std::string>& have) {
        for (const std::string& name : names) {
            if (std::binary_search(have.begin(), have.end(), name)) continue;
            std::string list;
            for (const std::string& h : have) list += (list.empty() ? "\"" : ", \"") + h + "\"";
            throw Error(source + ": line_sets[" + std::to_string(index) + "].select." + key + ": \"" + name +
                        "\" is none of the scene's " + key + " (" + (list.empty() ? "it has none" : list) + ")");
        }
    };
    // Sets tell models apart by file name: one that names two models (a folder of downloads
    // each called scene.gltf) would select both, quietly.
    const auto check_unique = [&](size_t index, const std::string& name) {
        std::string paths;
        size_t count = 0;
        for (const Model& model : scene.models)
            if (model.path.filename().string() == name) paths += (count++ == 0 ? "" : ", ") + model.path.string();
        if (count > 1)
            throw Error(source + ": line_sets[" + std::to_string(index) + "].select.models: \"" + name +
                        "\" names more than one of the scene's models (" + paths +
                        "); sets select models by file name, so give each a name of its own");
    };
    for (size_t i = 0; i < sets.size(); ++i) {
        check(i, "models", sets[i].select.models, models);
        for (const std::string& name : sets[i].select.models) check_unique(i, name);
        check(i, "materials", sets[i].select.materials, materials);
    }
}

}  // namespace

void SceneSession::load_line_styles() {
    if (has_model()) check_line_set_groups(desc_.lines.sets, scene_, desc_.source.empty() ? "scene" : desc_.source.string());
    // κ: --length-scale for every set.
    if (options_.length_scale > 0.0f) {
        desc_.lines.length_scale = options_.length_scale;
        for (LineSetDesc& set : desc_.lines.sets) set.coherence.length_scale = options_.length_scale;
    }
    const std::vector<LineSetDesc> previous = std::move(sets_);  // what slams_ and ribbons_ were read for
    sets_ = effective_line_sets(desc_.lines);
    // A ribbon draws visible runs only: a set of its own that selects hidden ones is refused
    // when read; the shorthand's types under hidden lines ("hidden", --hidden) are said here.
    if (desc_.lines.sets.empty())
        for (const LineSetDesc& set : sets_)
            if (set.enabled && !set.style.ribbon.empty() && set.select.selects_hidden())
                log_warning(key_file_prefix(desc_, "lines." + set.name + ".ribbon") +
                            "a ribbon draws visible lines only; its hidden lines are not drawn");
    // Else the scene's "coherence.length_scale" for the sets (and the shorthand's) that give
    // none of their own: filled in the sets drawn, not in the description, which a saved view
    // writes back with the key as it was.
    if (const std::optional<float>& kappa = desc_.coherence.length_scale; kappa && !(options_.length_scale > 0.0f))
        for (LineSetDesc& set : sets_)
            if (!(set.coherence.length_scale > 0.0f)) set.coherence.length_scale = *kappa;
    // Every file a style names, read before any rendering so that a bad one fails first; a
    // SLAM or ribbon exemplar shared by several sets (or kept from before) is read once.
    std::vector<std::optional<Slam>> slams;
    std::vector<std::optional<Exemplar>> ribbons;
    for (size_t i = 0; i < sets_.size(); ++i) {
        const LineSetStyle& style = sets_[i].style;
        const std::string key = desc_.lines.sets.empty() ? "lines." + sets_[i].name + "."
                                                         : "line_sets[" + std::to_string(i) + "].style.";
        check_key_file(desc_, key + "slam", style.slam);
        check_key_file(desc_, key + "ribbon", style.ribbon);
        std::optional<Slam> slam = already_read(style.slam, &LineSetStyle::slam, sets_, slams);
        if (!slam) slam = already_read(style.slam, &LineSetStyle::slam, previous, slams_);
        if (!style.slam.empty() && !slam) slam = read_key_file(desc_, key + "slam", [&] { return read_slam(style.slam); });
        slams.push_back(std::move(slam));
        std::optional<Exemplar> ribbon = already_read(style.ribbon, &LineSetStyle::ribbon, sets_, ribbons);
        if (!ribbon) ribbon = already_read(style.ribbon, &LineSetStyle::ribbon, previous, ribbons_);
        if (!style.ribbon.empty() && !ribbon)
            ribbon = read_key_file(desc_, key + "ribbon",
                                   [&] { return make_exemplar(read_image_rgba8(style.ribbon), style.ribbon); });
        ribbons.push_back(std::move(ribbon));
    }
    // Every file read: only now is the old state replaced.
    for (size_t i = 0; i < std::max(slams.size(), slams_.size()); ++i) {
        if (i < slams.size() && slams[i]) renderer_.set_slam(i, *slams[i]);
        else if (i < slams_.size() && slams_[i]) renderer_.clear_slam(i);
    }
    slams_ = std::move(slams);
    ribbons_ = std::move(ribbons);
    textured_.assign(sets_.size(), true);
}

void SceneSession::set_lines(const LinesDesc& lines) {
    const LinesDesc before = desc_.lines;
    desc_.lines = lines;
    try {
        load_line_styles();
    } catch (...) {
        desc_.lines = before;
        sets_ = effective_line_sets(desc_.lines);
        throw;
    }
    if (lines.enabled != before.enabled || lines.params.crease_angle_deg != before.params.crease_angle_deg ||
        lines.params.curvature != before.params.curvature)
        rebuild_lines();
}

float SceneSession::duration_s() const { return has_model() ? animation_duration(scene_) : 0.0f; }

FrameRange SceneSession::default_frames() const {
    if (desc_.animation.frames) return *desc_.animation.frames;
    FrameRange range{0, 0};
    if (desc_.animation.play) range.last = std::max(0, int(std::ceil(duration_s() * desc_.animation.fps)) - 1);
    return range;
}

bool SceneSession::has_ribbons() const {
    const bool layer_ribbons = std::any_of(layers_.ribbons.begin(), layers_.ribbons.end(),
                                           [](const auto& r) { return r.has_value(); });
    for (size_t i = 0; i < sets_.size(); ++i)
        if (ribbons_[i] && sets_[i].enabled) return true;
    return layer_ribbons;
}

void SceneSession::set_line_set_textured(size_t set, bool on) {
    if (set >= sets_.size() || !slams_[set]) return;
    textured_[set] = on;
    if (on) renderer_.set_slam(set, *slams_[set]);
    else renderer_.clear_slam(set);
}

bool SceneSession::line_set_textured(size_t set) const { return set < textured_.size() && slams_[set] && textured_[set]; }

void SceneSession::rebuild_lines() {
    if (!has_model()) return;
    const std::optional<float> at = posed_at_;
    build_meshes();
    if (at) pose(*at);
}

// An animated model's line mesh is welded, and its feature size and feature edges taken, in
// the pose at 0 s, whatever frame is drawn first: a frame is then the same drawn alone, in a
// sequence, in a farm's chunk or after a rebuild (built in the first frame drawn, frame 2 of
// the Fox's run had 139 crease polylines drawn alone and 163 after frames 0 and 1). Later
// poses move its vertices and curvature (pose_line_mesh).
void SceneSession::build_meshes() {
    renderer_.set_mesh(animated_ ? posed_mesh(0.0f) : scene_.mesh, desc_.lines.enabled,
                       desc_.lines.params.crease_angle_deg, desc_.lines.params.curvature, !animated_);
    posed_at_.reset();
    if (animated_) posed_at_ = 0.0f;
    if (const LineMesh* lines = renderer_.line_mesh())
        renderer_.set_face_groups(face_groups(scene_, scene_.mesh, *lines, options_.subdivide));
}

// The scene at `seconds`, subdivided as the rest mesh was: the triangles (and so the
// materials' face list and the line mesh) are the same in every pose.
TriangleMesh SceneSession::posed_mesh(float seconds) const {
    TriangleMesh posed = pose_scene(scene_, seconds);
    if (options_.subdivide > 0) posed = subdivide_midpoint(posed, options_.subdivide);
    return posed;
}

void SceneSession::pose(float seconds) {
    if (!animated_ || posed_at_ == seconds) return;
    renderer_.deform(posed_mesh(seconds));
    posed_at_ = seconds;
}

ViewCamera SceneSession::camera_at(const PathTime& when) const {
    return lw::camera_at(desc_.camera_path, scene_.camera, when);
}

bool SceneSession::parameterized() const {
    const bool layer_slams = std::any_of(layers_.styles.begin(), layers_.styles.end(),
                                         [](const LayerStyle& s) { return s.slam.has_value(); });
    if (layer_slams) return true;
    if (!desc_.lines.enabled || !has_model()) return false;
    if (options_.coherent) return true;
    for (size_t i = 0; i < sets_.size(); ++i)
        if (reads_parameter(i)) return true;
    return false;
}

bool SceneSession::reads_parameter(size_t set) const {
    return sets_[set].enabled && (line_set_textured(set) || needs_parameterization(sets_[set].style));
}

bool SceneSession::strokes_carry_state() const {
    const auto coherent = [&](const std::optional<ParamPolicy>& own) {
        return own.value_or(options_.coherence.policy) == ParamPolicy::Coherent;
    };
    for (const LayerStyle& s : layers_.styles)
        if (s.slam && options_.coherence.policy == ParamPolicy::Coherent) return true;
    if (!desc_.lines.enabled || !has_model()) return false;
    for (size_t i = 0; i < sets_.size(); ++i)
        if (reads_parameter(i) && coherent(sets_[i].coherence.policy)) return true;
    return false;
}

void SceneSession::begin_frame(const FrameRequest& request) {
    sets_ = effective_line_sets(desc_.lines);  // the panel may have changed styles
    if (has_model() && !textures_loaded_ && scene_needs_textures(scene_, desc_.style)) {  // the panel turned shading on
        renderer_.set_materials(scene_materials(scene_, scene_.mesh, options_.subdivide, true));
        textures_loaded_ = true;
    }
    pose(request.when.seconds);
    const ViewCamera view = request.camera ? *request.camera : camera_at(request.when);
    const uint32_t width = renderer_.target().width, height = renderer_.target().height;
    const CameraMatrices camera =
        has_model() ? camera_matrices(view, float(width) / float(height), scene_.bounds) : CameraMatrices{};
    std::vector<LayerFrame> layer_frames = scene_layer_frames(layers_, request.when.seconds, glm::vec2(width, height),
                                                              desc_.lines.sample_spacing_px);
    // Ribbons are synthesized on the host over the read-back colour.
    const bool ribbons = has_ribbons() && request.outputs.draw && (request.outputs.color || request.ribbons_to_target);
    FrameOutputs outputs = request.outputs;
    outputs.color = outputs.draw && (outputs.color || ribbons);
    renderer_.begin({.camera = camera,
                     .eye = view.eye,
                     .surface = desc_.style,
                     .lines = desc_.lines,
                     .outputs = outputs,
                     .coherence = parameterized() ? std::optional(options_.coherence) : std::nullopt,
                     .parameterize_every_set = options_.coherent,
                     .layers = layers_.descs.empty() ? std::nullopt : std::optional(std::move(layer_frames))});
    pending_.push_back({.seconds = request.when.seconds,
                        .seed = request.seed,
                        .ribbons = ribbons,
                        .color = request.outputs.color,
                        .ribbons_to_target = request.ribbons_to_target});
}

Frame SceneSession::finish_frame() {
    if (pending_.empty()) throw Error("session: no frame in flight to finish");
    const Pending request = pending_.front();
    pending_.erase(pending_.begin());
    Frame frame = renderer_.finish();
    if (request.ribbons) {
        frame.timings.total_ms += draw_ribbons(frame, request.seed);
        if (request.ribbons_to_target) renderer_.target().write_color(*ctx_, frame.image.color.pixels);
        if (!request.color) frame.image.color = {};
    }
    last_seconds_ = request.seconds;
    return frame;
}

double SceneSession::draw_ribbons(Frame& frame, uint64_t seed) {
    double ms = 0.0;
    ribbon_reports_.clear();
    for (const LineSetFrame& set : frame.sets) {
        if (!ribbons_[set.set]) continue;
        const LineSetStyle& style = sets_[set.set].style;
        RibbonStrokeStats stats;
        try {
            stats = draw_ribbon_strokes(*ctx_, set.paths, std::nullopt, *ribbons_[set.set],
                                        {.width = style.width, .scale = style.ribbon_scale, .seed = seed},
                                        frame.image.color);
        } catch (const ParameterError& e) {  // the style's width and ribbon_scale set them
            throw Error(desc_.source.string() + ": line set " + set.name + ": " + e.what(), 1);
        } catch (const Error& e) {  // an exemplar the paths cannot use: name it and the keys that shape its pieces
            throw Error(desc_.source.string() + ": line set " + set.name + ", ribbon " + style.ribbon + ": " +
                            e.what() + " (here s is \"ribbon_scale\" and δ half the set's \"width\")",
                        e.exit_code());
        }
        ms += stats.ms;
        ribbon_reports_.push_back({set.name, stats});
    }
    // Layers lie over the 3D lines, their ribbons too.
    return ms + draw_layer_ribbons(*ctx_, layers_, frame.layers, seed, frame.image.color);
}

void SceneSession::resize(uint32_t width, uint32_t height) {
    if (!pending_.empty()) throw Error("session: resize with a frame in flight (finish it first)");
    renderer_.resize(width, height);
}

SceneSession::Snapshot SceneSession::snapshot() const {
    const LineMesh* lines = renderer_.line_mesh();
    return {.seconds = last_seconds_,
            .coherence = renderer_.coherence_snapshot(),
            .width = renderer_.target().width,
            .height = renderer_.target().height,
            .welded_vertices = lines ? lines->mesh.positions.size() : 0};
}

void SceneSession::restore(const Snapshot& snapshot) {
    const auto count = [](size_t n, const char* what) { return std::to_string(n) + " " + what; };
    if (snapshot.coherence.sets.size() > sets_.size() || snapshot.coherence.layers.size() != layers_.descs.size())
        throw Error("snapshot: taken of another scene (" + count(snapshot.coherence.sets.size(), "line sets, ") +
                    count(snapshot.coherence.layers.size(), "layers; this one has ") + count(sets_.size(), "and ") +
                    count(layers_.descs.size(), "layers)"));
    const LineMesh* lines = renderer_.line_mesh();
    const size_t welded = lines ? lines->mesh.positions.size() : 0;
    if (snapshot.width != 0 && (snapshot.width != renderer_.target().width ||
                                snapshot.height != renderer_.target().height || snapshot.welded_vertices != welded))
        throw Error("snapshot: taken of another scene or size (" + std::to_string(snapshot.width) + "x" +
                    std::to_string(snapshot.height) + ", " + count(snapshot.welded_vertices, "welded vertices; this one ") +
                    std::to_string(renderer_.target().width) + "x" + std::to_string(renderer_.target().height) + ", " +
                    count(welded, "welded vertices)"));
    pose(snapshot.seconds);
    renderer_.restore_coherence(snapshot.coherence);
    last_seconds_ = snapshot.seconds;
}

std::vector<SvgGroup> SceneSession::svg_groups(const Frame& frame, bool with_shapes) const {
    return line_set_svg_groups(desc_.lines, frame, with_shapes);
}

std::vector<DumpGroup> SceneSession::dump_groups(const Frame& frame) const {
    return line_set_dump_groups(frame);
}

}  // namespace lw
