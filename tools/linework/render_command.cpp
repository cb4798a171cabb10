// `linework render SCENE.json|MODEL.glb -o DIR` — headless render to PNG (and EXR).
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>

#include "coherence/path_dump.h"
#include "commands.h"
#include "progress.h"
#include "core/error.h"
#include "core/timer.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "render_layers.h"
#include "render_state.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon_strokes.h"
#include "lines/svg_export.h"
#include "render/frame_renderer.h"
#include "scene/scene.h"

namespace lw::cli {

namespace {

struct RenderOptions {
    std::string input;
    std::string output;
    std::string device = "auto";
    std::string compute = "auto";
    std::string size, eye, target, up;
    std::optional<float> fov;
    std::string shading;
    bool exr = false;
    bool validation = false;
    bool lines_only = false;
    bool no_lines = false;
    std::string svg;
    std::string hidden;
    std::string frames;
    int warmup = 0;
    std::optional<float> orbit;
    std::string param;
    std::string dump_paths;
    std::string slam;
    float stroke_width = 6.0f;
    float splat_radius = 0.0f;  // 0: twice the sample spacing
    float inlier_px = 1.5f;
    float min_stroke_length = CoherenceParams{}.min_stroke_length_px;
    bool resume = false;
    std::string signature;  // the options that shape the frames (--resume checks them)
    float length_scale = 0.0f;  // 0: square texels (the SLAM's height over the stroke width)
};

// Applies command-line overrides to the scene description. A partial camera (only --eye)
// keeps the framed target so that a user can move the eye alone.
void apply_overrides(const RenderOptions& o, SceneDesc& desc) {
    if (!o.size.empty()) {
        const glm::ivec2 size = parse_size(o.size, "--size");
        desc.width = size.x;
        desc.height = size.y;
    }
    if (o.fov) {
        if (!(*o.fov > 0.0f && *o.fov < 180.0f)) throw usage_error("--fov: must be between 0 and 180 degrees");
        desc.fov_deg = *o.fov;
        if (desc.camera) desc.camera->fov_deg = *o.fov;
    }
    if (!o.shading.empty()) {
        desc.style.draw_surface = o.shading != "none";
        if (o.shading == "flat") desc.style.shading = Shading::Flat;
        if (o.shading == "toon") desc.style.shading = Shading::Toon;
        if (o.shading == "unlit") desc.style.shading = Shading::Unlit;
    }
    if (o.lines_only) desc.style.draw_surface = false;
    if (o.no_lines) desc.lines.enabled = false;
    if (!o.hidden.empty())
        desc.lines.hidden = o.hidden == "dashed" ? HiddenLines::Dashed
                            : o.hidden == "faint" ? HiddenLines::Faint
                                                  : HiddenLines::None;
    if (o.lines_only && o.no_lines) throw usage_error("--lines-only and --no-lines leave nothing to draw");
    if (!o.svg.empty() && !desc.lines.enabled) throw usage_error("--svg needs lines (drop --no-lines)");
}

void apply_camera_overrides(const RenderOptions& o, LoadedScene& scene) {
    if (!o.eye.empty()) scene.camera.eye = parse_vec3(o.eye, "--eye");
    if (!o.target.empty()) scene.camera.target = parse_vec3(o.target, "--target");
    if (!o.up.empty()) scene.camera.up = parse_vec3(o.up, "--up");
    if (scene.camera.eye == scene.camera.target) throw usage_error("--eye and --target coincide");
}

// "A:B" (inclusive) or "N" (one frame).
FrameRange parse_frames(const std::string& text) {
    FrameRange range;
    const auto colon = text.find(':');
    try {
        size_t used = 0;
        if (colon == std::string::npos) {
            range.first = range.last = std::stoi(text, &used);
            if (used != text.size()) throw 0;
        } else {
            range.first = std::stoi(text.substr(0, colon), &used);
            if (used != colon) throw 0;
            range.last = std::stoi(text.substr(colon + 1), &used);
            if (used != text.size() - colon - 1) throw 0;
        }
    } catch (...) {
        throw usage_error("--frames: expected A:B (inclusive) or N, got \"" + text + "\"");
    }
    if (range.last < range.first) throw usage_error("--frames: " + text + " ends before it starts");
    return range;
}

std::string frame_name(int frame, const char* extension) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%04d.%s", frame, extension);
    return name;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out || !(out << text) || !out.flush()) throw Error(path.string() + ": cannot write");
}

volatile std::sig_atomic_t g_interrupted = 0;

int interrupted(int frame, int first) {
    std::fflush(stdout);
    if (frame >= first)
        std::fprintf(stderr, "\nlinework: interrupted after frame %d (written); run the same command with --resume to go on\n",
                     frame);
    else
        std::fprintf(stderr, "\nlinework: interrupted during the warm-up frames; nothing written\n");
    return 130;
}

int run_render(const RenderOptions& o) {
    // Usage first: a bad flag is exit code 2 whatever the files.
    const std::optional<FrameRange> frames_flag = o.frames.empty() ? std::nullopt : std::optional(parse_frames(o.frames));
    if (o.warmup < 0) throw usage_error("--warmup: must be 0 or more");
    const std::filesystem::path input(o.input);
    if (!std::filesystem::exists(input)) throw Error(o.input + ": no such file");
    SceneDesc desc = is_model_path(input) ? scene_for_model(input) : load_scene_file(input);
    apply_overrides(o, desc);
    if (o.orbit) desc.camera_path = CameraPath{.kind = CameraPath::Kind::Orbit, .orbit = {.degrees = *o.orbit}};
    if (!o.slam.empty()) use_slam_strokes(desc.lines, o.slam, o.stroke_width);

    std::filesystem::path out_dir(o.output);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec || !std::filesystem::is_directory(out_dir))
        throw Error(o.output + ": cannot create output folder" + (ec ? " (" + ec.message() + ")" : ""));
    if (!o.dump_paths.empty()) {
        std::filesystem::create_directories(o.dump_paths, ec);
        if (ec || !std::filesystem::is_directory(o.dump_paths))
            throw Error(o.dump_paths + ": cannot create dump folder" + (ec ? " (" + ec.message() + ")" : ""));
    }

    Timer load_timer;
    const bool has_model = !desc.models.empty();  // a scene may hold vector layers alone
    LoadedScene scene = has_model ? load_scene(desc) : LoadedScene{.desc = desc};
    apply_camera_overrides(o, scene);
    // Frames: the command line, else the scene's, else the clips' length (one frame without).
    const float fps = desc.animation.fps;
    FrameRange range{0, 0};
    if (frames_flag)
        range = *frames_flag;
    else if (desc.animation.frames)
        range = *desc.animation.frames;
    else if (desc.animation.play)
        range.last = std::max(0, int(std::ceil(animation_duration(scene) * fps)) - 1);
    const bool sequence = range.last > range.first || o.warmup > 0 || desc.animation.play ||
                          desc.camera_path.kind != CameraPath::Kind::Fixed;
    std::printf("scene: %s (%zu triangles, loaded in %.0f ms)\n", o.input.c_str(), scene.mesh.triangle_count(),
                load_timer.elapsed_ms());

    // SLAM files named by the styles (a SLAM shared by several types is read once).
    std::array<std::optional<Slam>, kLineTypeCount> slams;
    for (int t = 0; t < kLineTypeCount; ++t) {
        const std::string& file = desc.lines.styles[size_t(t)].slam;
        if (file.empty()) continue;
        for (int u = 0; u < t; ++u)
            if (slams[size_t(u)] && desc.lines.styles[size_t(u)].slam == file) slams[size_t(t)] = slams[size_t(u)];
        if (!slams[size_t(t)]) slams[size_t(t)] = read_slam(file);
    }
    // Ribbon exemplars, read before any rendering so that a bad file fails first.
    std::array<std::optional<Exemplar>, kLineTypeCount> ribbons;
    for (int t = 0; t < kLineTypeCount; ++t) {
        const std::string& file = desc.lines.styles[size_t(t)].ribbon;
        if (!file.empty()) ribbons[size_t(t)] = make_exemplar(read_image_rgba8(file), file);
    }
    SceneLayers layers = load_scene_layers(desc);
    const bool strokes = std::any_of(slams.begin(), slams.end(), [](const auto& s) { return s.has_value(); });
    const bool layer_slams = std::any_of(layers.styles.begin(), layers.styles.end(),
                                         [](const LayerStyle& s) { return s.slam.has_value(); });
    const bool coherent = (desc.lines.enabled && has_model && (strokes || !o.dump_paths.empty() || !o.param.empty())) ||
                          layer_slams;
    CoherenceParams coherence;
    if (o.param == "arclength") coherence.policy = ParamPolicy::Arclength;
    if (o.param == "stretch") coherence.policy = ParamPolicy::Stretch;
    coherence.splat_radius_px = o.splat_radius > 0.0f ? o.splat_radius : desc.lines.sample_spacing_px * 2.0f;
    coherence.ransac.inlier_px = o.inlier_px;
    coherence.min_stroke_length_px = o.min_stroke_length;
    for (int t = 0; t < kLineTypeCount; ++t)
        if (slams[size_t(t)]) {
            coherence.slam_length_px = float(slams[size_t(t)]->length);
            // κ default: texels stay square — the texture's height spans the stroke's width.
            coherence.length_scale = o.length_scale > 0.0f
                                         ? o.length_scale
                                         : float(slams[size_t(t)]->height) / desc.lines.styles[size_t(t)].width;
        }
    if (o.length_scale > 0.0f) coherence.length_scale = o.length_scale;
    for (LayerStyle& style : layers.styles) {  // the same policy and tracker settings for layers
        style.coherence.policy = coherence.policy;
        style.coherence.splat_radius_px = coherence.splat_radius_px;
        style.coherence.ransac = coherence.ransac;
        style.coherence.min_stroke_length_px = coherence.min_stroke_length_px;
        if (o.length_scale > 0.0f) style.coherence.length_scale = o.length_scale;
    }

    const bool validation = o.validation || validation_from_environment();
    Context ctx({.device = parse_device_choice(o.device), .validation = validation,
                 .compute_site = parse_compute_site(o.compute, "--compute")});
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("size: %dx%d\n", desc.width, desc.height);

    const auto width = static_cast<uint32_t>(desc.width), height = static_cast<uint32_t>(desc.height);
    FrameRenderer renderer(ctx, width, height);
    for (int t = 0; t < kLineTypeCount; ++t)
        if (slams[size_t(t)]) renderer.set_slam(LineType(t), *slams[size_t(t)]);
    Timer prepare_timer;
    const bool animated = desc.animation.play && animation_duration(scene) > 0.0f;  // clips move the mesh
    if (has_model)
        renderer.set_mesh(animated ? pose_scene(scene, frame_time(range.first - o.warmup, range, fps).seconds)
                                   : scene.mesh,
                          desc.lines.enabled, desc.lines.params.crease_angle_deg);
    if (!layers.descs.empty()) renderer.set_layers(layers.styles);
    if (const LineMesh* lm = renderer.line_mesh())
        std::printf("lines: %zu welded vertices, feature size %.4g, curvature in %.0f ms\n", lm->mesh.positions.size(),
                    double(lm->feature_size), prepare_timer.elapsed_ms());
    if (sequence)
        std::printf("frames: %d to %d%s at %g fps\n", range.first, range.last,
                    o.warmup ? (", after " + std::to_string(o.warmup) + " warm-up frames").c_str() : "", double(fps));

    // --resume: skip the frames already written; the parameterization goes on from the state
    // saved after the last of them (render_state.h), so the frames match an unbroken run.
    const std::filesystem::path state_path = out_dir / ".linework-state";
    int start = range.first - o.warmup;
    if (o.resume) {
        int first_missing = range.first;
        while (first_missing <= range.last && std::filesystem::exists(out_dir / frame_name(first_missing, "png")))
            ++first_missing;
        if (first_missing > range.last) {
            std::printf("all frames %d to %d are already in %s\n", range.first, range.last, out_dir.string().c_str());
            return 0;
        }
        if (first_missing > range.first) {
            const RenderState state = read_render_state(state_path);
            if (state.signature != o.signature)
                throw Error(state_path.string() + ": written by a render with other options; rerun that command "
                                                  "with --resume, or remove the file to start over");
            if (state.frame != first_missing - 1)
                throw Error(state_path.string() + ": holds the state after frame " + std::to_string(state.frame) +
                            ", but the first missing frame is " + std::to_string(first_missing));
            if (animated) renderer.deform(pose_scene(scene, frame_time(first_missing - 1, range, fps).seconds));
            renderer.restore_coherence(state.snapshot);
            start = first_missing;
            std::printf("resuming at frame %d (frames %d to %d already written)\n", first_missing, range.first,
                        first_missing - 1);
        }
    }

    // Ctrl-C finishes the frame in hand, writes it and the state, and stops (exit code 130).
    g_interrupted = 0;
    const auto previous_handler = std::signal(SIGINT, [](int) { g_interrupted = 1; });
    struct RestoreHandler {
        decltype(previous_handler) handler;
        ~RestoreHandler() { std::signal(SIGINT, handler); }
    } restore_handler{previous_handler};

    Progress progress(range.last - start + 1, "frame");
    int done = 0;
    double total_ms = 0.0;
    for (int f = start; f <= range.last; ++f) {
        const PathTime when = frame_time(f, range, fps);
        if (animated && f != range.first - o.warmup) renderer.deform(pose_scene(scene, when.seconds));
        const ViewCamera view = camera_at(desc.camera_path, scene.camera, when);
        const CameraMatrices camera =
            has_model ? camera_matrices(view, float(width) / float(height), scene.bounds) : CameraMatrices{};
        std::vector<LayerFrame> layer_frames =
            scene_layer_frames(layers, when.seconds, glm::vec2(width, height), desc.lines.sample_spacing_px);
        const bool write = f >= range.first;
        Frame frame = renderer.render(camera, view.eye, desc.style, desc.lines,
                                      {.color = write, .depth = write && o.exr}, coherent ? &coherence : nullptr,
                                      layers.descs.empty() ? nullptr : &layer_frames);
        for (int t = 0; t < kLineTypeCount && write; ++t)
            if (ribbons[size_t(t)]) {
                const LineStyle& style = desc.lines.styles[size_t(t)];
                const RibbonStrokeStats stats =
                    draw_ribbon_strokes(ctx, frame.screen_paths, LineType(t), *ribbons[size_t(t)],
                                        {.width = style.width, .scale = style.ribbon_scale, .seed = uint64_t(f) + 1},
                                        frame.image.color);
                frame.timings.total_ms += stats.ms;
                if (!sequence)
                    std::printf("ribbons (%s): %zu paths in %.0f ms, %zu too short\n", line_type_name(LineType(t)),
                                stats.paths, stats.ms, stats.skipped);
            }
        // Layers lie over the 3D lines, their ribbons too.
        if (write) frame.timings.total_ms += draw_layer_ribbons(ctx, layers, frame.layers, uint64_t(f) + 1, frame.image.color);
        ++done;
        total_ms += frame.timings.total_ms;
        progress.update(done, f, frame.timings.total_ms);
        if (!write) {
            if (g_interrupted) return interrupted(f, range.first);
            continue;
        }

        // Everything through a temporary name: a killed render never leaves half a file. The
        // PNG goes last, so that a frame whose PNG exists is complete (--resume).
        const std::filesystem::path png = out_dir / frame_name(f, "png");
        if (o.exr)
            write_atomically(out_dir / frame_name(f, "exr"), [&](const std::filesystem::path& file) {
                write_exr(file, frame.image.color, frame.image.depth);
            });
        if (!o.svg.empty()) {
            std::filesystem::path svg(o.svg);
            if (sequence) svg = svg.parent_path() / (svg.stem().string() + "_" + frame_name(f, "svg").substr(6));
            write_atomically(svg, [&](const std::filesystem::path& file) {
                write_lines_svg(file, desc.width, desc.height, frame.screen_paths, desc.lines.styles);
            });
        }
        if (!o.dump_paths.empty())
            write_atomically(std::filesystem::path(o.dump_paths) / frame_name(f, "json"), [&](const std::filesystem::path& file) {
                write_text(file, path_dump_json(f, desc.width, desc.height, frame.screen_paths, frame.params, frame.layers));
            });
        if (sequence) write_render_state(state_path, {o.signature, f, renderer.coherence_snapshot()});
        write_atomically(png, [&](const std::filesystem::path& file) { write_png(file, frame.image.color); });
        if (!sequence) {
            std::printf("frame %d: %.2f ms", f, frame.timings.total_ms);
            for (const PassTime& t : frame.timings.gpu)
                if (t.ms >= 0.0) std::printf(" (GPU %s %.3f ms)", t.name.c_str(), t.ms);
            std::printf("\n");
            if (desc.lines.enabled) {
                size_t visible = 0;
                for (const auto& p : frame.screen_paths) visible += p.visible;
                std::printf("lines: %zu segments, %zu paths, %zu visible runs (chain %.2f ms, visibility %.2f ms)\n",
                            frame.segments.size(), frame.paths.size(), visible, frame.timings.chain_ms,
                            frame.timings.visibility_ms);
            }
            std::printf("wrote %s\n", png.string().c_str());
            if (o.exr) std::printf("wrote %s\n", (out_dir / frame_name(f, "exr")).string().c_str());
            if (!o.svg.empty()) std::printf("wrote %s\n", o.svg.c_str());
        }
        if (g_interrupted && f < range.last) return interrupted(f, range.first);
    }
    if (sequence) {
        std::printf("time per frame: %.2f ms (mean of %d)\n", total_ms / std::max(done, 1), done);
        std::printf("wrote %s/frame_%04d.png … frame_%04d.png\n", out_dir.string().c_str(), range.first, range.last);
        if (!o.dump_paths.empty()) std::printf("wrote path dumps to %s\n", o.dump_paths.c_str());
    }

    return exit_code_after_validation(ctx, validation);
}

}  // namespace

Runner add_render_command(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Render a scene file or a glTF model headlessly to OUT/frame_0000.png.\n"
        "Without a camera in the scene (or --eye/--target), the camera frames the bounding box.");
    cmd->add_option("input", o->input, "Scene file (.json) or model (.gltf/.glb)")->required();
    cmd->add_option("-o,--output", o->output, "Output folder (created if missing)")->required();
    cmd->add_option("--device", o->device,
                    "auto (discrete GPU if present, else lavapipe), cpu, gpu, or an index from `linework devices`")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WxH (default: the scene's, else 960x720)");
    cmd->add_option("--compute", o->compute, kComputeSiteHelp)->capture_default_str();
    cmd->add_option("--eye", o->eye, "Camera position x,y,z");
    cmd->add_option("--target", o->target, "Point looked at x,y,z");
    cmd->add_option("--up", o->up, "Up vector x,y,z (default 0,1,0)");
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees (default 40)");
    cmd->add_option("--shading", o->shading, "Surface shading")->check(CLI::IsMember({"flat", "toon", "unlit", "none"}));
    cmd->add_flag("--exr", o->exr, "Also write OUT/frame_0000.exr (RGBA + depth channel Z)");
    cmd->add_flag("--lines-only", o->lines_only, "Draw the lines over the background, without shading");
    cmd->add_flag("--no-lines", o->no_lines, "Shading only, no feature lines");
    cmd->add_option("--svg", o->svg,
                    "Also write the visible lines as SVG (pixel coordinates, one <g> per line type)");
    cmd->add_option("--hidden", o->hidden, "Hidden lines: none (default), dashed or faint")
        ->check(CLI::IsMember({"none", "dashed", "faint"}));
    cmd->add_option("--frames", o->frames,
                    "Render frames A:B (inclusive) to OUT/frame_NNNN.png (default: the scene's, else one frame)");
    cmd->add_option("--warmup", o->warmup,
                    "Render K frames before A without writing them, so a range starts coherent");
    cmd->add_option("--orbit", o->orbit, "Turn the camera DEG degrees about the bounding-box centre over the frames");
    cmd->add_option("--param", o->param,
                    "Stroke parameterization: coherent (default; Bénard et al. 2010 §4), arclength (tiling) or "
                    "stretch (one texture per path)")
        ->check(CLI::IsMember({"coherent", "arclength", "stretch"}));
    cmd->add_option("--slam", o->slam, "Draw silhouettes and suggestive contours as strokes textured by this SLAM (.exr)");
    cmd->add_option("--length-scale", o->length_scale,
                    "κ: SLAM periods per native texture length (default: square texels, the SLAM's height over "
                    "the stroke width)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--stroke-width", o->stroke_width, "Width of SLAM strokes in pixels (default 6)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--splat-radius", o->splat_radius,
                    "δ of the parameterization sprites, pixels (default: twice the sample spacing); larger keeps "
                    "fast lines coherent, smaller keeps nearby lines apart (§4.1)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--inlier-px", o->inlier_px, "RANSAC inlier distance along the path, pixels (§4.2)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--min-stroke-length", o->min_stroke_length,
                    "Visible paths shorter than this many pixels are not drawn as strokes, splatted or dumped "
                    "(0 keeps every fragment)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--dump-paths", o->dump_paths,
                    "Write DIR/frame_NNNN.json per frame: visible paths, their (ρ, φ), level and samples");
    cmd->add_flag("--validation", o->validation,
                  "Enable the Khronos validation layer; any warning or error fails the run "
                  "(also LINEWORK_VALIDATION=1)");
    cmd->add_flag("--resume", o->resume,
                  "Go on with an interrupted sequence: skip the frames already in the output folder and "
                  "restore the parameterization from its .linework-state");
    return [o, cmd] {
        // The options as given, less --resume itself: what a resumed run must repeat.
        std::string signature;
        for (const CLI::Option* option : cmd->get_options())
            if (option->count() > 0 && option->get_name() != "--resume") {
                signature += option->get_name() + "=";
                for (const std::string& value : option->results()) signature += value + ";";
                signature += "\n";
            }
        o->signature = signature;
        return run_render(*o);
    };
}

}  // namespace lw::cli
