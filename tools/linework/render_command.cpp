// `linework render SCENE.json|MODEL.glb -o DIR` — headless render to PNG (and EXR, SVG, dumps).
//
// A platform over SceneSession: options → scene description → session → the frame loop
// writing files (render_output.h). --resume goes on from OUT/.linework-state.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.h"
#include "core/timer.h"
#include "progress.h"
#include "render_output.h"
#include "render_state.h"
#include "scene_options.h"

namespace lw::cli {

namespace {

struct RenderOptions {
    SceneOptions scene;
    std::string output, eye, target, up, shading, svg, hidden, frames, dump_paths;
    std::optional<float> fov, orbit;
    bool exr = false, lines_only = false, no_lines = false, resume = false;
    int warmup = 0;
    std::string signature;  // the options that shape the frames (--resume checks them)
};

// Overrides of the scene description. A partial camera (only --eye) keeps the framed target.
void apply_overrides(const RenderOptions& o, SceneDesc& desc) {
    if (o.fov) {
        if (!(*o.fov > 0.0f && *o.fov < 180.0f)) throw usage_error("--fov: must be between 0 and 180 degrees");
        desc.fov_deg = *o.fov;
        if (desc.camera) desc.camera->fov_deg = *o.fov;
    }
    if (!o.shading.empty()) {
        desc.style.draw_surface = o.shading != "none";
        desc.style.shading = o.shading == "flat" ? Shading::Flat : o.shading == "unlit" ? Shading::Unlit : Shading::Toon;
    }
    if (o.lines_only && o.no_lines) throw usage_error("--lines-only and --no-lines leave nothing to draw");
    if (o.lines_only) desc.style.draw_surface = false;
    if (o.no_lines) desc.lines.enabled = false;
    if (!o.hidden.empty())
        desc.lines.hidden = o.hidden == "dashed" ? HiddenLines::Dashed : o.hidden == "faint" ? HiddenLines::Faint : HiddenLines::None;
    if (!o.svg.empty() && !desc.lines.enabled) throw usage_error("--svg needs lines (drop --no-lines)");
    if (o.orbit) desc.camera_path = CameraPath{.kind = CameraPath::Kind::Orbit, .orbit = {.degrees = *o.orbit}};
}

CameraOverride camera_override(const RenderOptions& o) {
    CameraOverride c;
    if (!o.eye.empty()) c.eye = parse_vec3(o.eye, "--eye");
    if (!o.target.empty()) c.target = parse_vec3(o.target, "--target");
    if (!o.up.empty()) c.up = parse_vec3(o.up, "--up");
    return c;
}

volatile std::sig_atomic_t g_interrupted = 0;

int run_render(const RenderOptions& o) {
    const std::optional<FrameRange> frames_flag = o.frames.empty() ? std::nullopt : std::optional(parse_frames(o.frames));
    if (o.warmup < 0) throw usage_error("--warmup: must be 0 or more");
    SceneDesc desc = scene_from_options(o.scene);
    apply_overrides(o, desc);
    FrameFiles files{o.output, o.svg, o.dump_paths, o.exr};
    create_folders(files);

    const bool validation = validation_on(o.scene);
    Context ctx({.device = parse_device_choice(o.scene.device), .validation = validation,
                 .compute_site = parse_compute_site(o.scene.compute)});
    Timer load_timer;
    SessionOptions options = session_options(o.scene, desc);
    options.coherent = options.coherent || !o.dump_paths.empty();
    // Frames: the command line, else the scene's, else the clips' length (one frame without).
    const float fps = desc.animation.fps;
    options.camera = camera_override(o);
    FrameRange range = desc.animation.frames.value_or(FrameRange{0, 0});
    if (frames_flag) range = *frames_flag;
    // The first frame drawn (warm-up included) sets the pose the line mesh is built in.
    options.start_seconds = frame_time(range.first - o.warmup, {range.first - o.warmup, range.last}, fps).seconds;
    SceneSession session(ctx, desc, options);
    if (!frames_flag) range = session.default_frames();
    files.sequence = range.last > range.first || o.warmup > 0 || desc.animation.play ||
                     desc.camera_path.kind != CameraPath::Kind::Fixed;
    std::printf("scene: %s (%zu triangles, loaded in %.0f ms)\n", o.scene.input.c_str(),
                session.scene().mesh.triangle_count(), load_timer.elapsed_ms());
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("size: %dx%d\n", desc.width, desc.height);
    if (const LineMesh* lm = session.renderer().line_mesh())
        std::printf("lines: %zu welded vertices, feature size %.4g\n", lm->mesh.positions.size(), double(lm->feature_size));
    if (files.sequence)
        std::printf("frames: %d to %d%s at %g fps\n", range.first, range.last,
                    o.warmup ? (", after " + std::to_string(o.warmup) + " warm-up frames").c_str() : "", double(fps));

    int start = range.first - o.warmup;
    if (o.resume) {
        const int resumed = resume_point(o.signature, files, range, session);
        if (resumed > range.last) {
            std::printf("all frames %d to %d are already in %s\n", range.first, range.last, o.output.c_str());
            return 0;
        }
        if (resumed > range.first) start = resumed;
    }

    // Ctrl-C finishes the frame in hand, writes it and the state, and stops (exit code 130).
    g_interrupted = 0;
    const auto previous_handler = std::signal(SIGINT, [](int) { g_interrupted = 1; });
    struct RestoreHandler {
        decltype(previous_handler) handler;
        ~RestoreHandler() { std::signal(SIGINT, handler); }
    } restore_handler{previous_handler};

    Progress progress(range.last - start + 1, "frame");
    double total_ms = 0.0;
    for (int f = start; f <= range.last; ++f) {
        const bool write = f >= range.first;
        const Frame frame = session.frame({.when = frame_time(f, range, fps),
                                           .outputs = {.color = write, .depth = write && o.exr},
                                           .seed = uint64_t(f) + 1});
        total_ms += frame.timings.total_ms;
        progress.update(f - start + 1, f, frame.timings.total_ms);
        if (write) {
            write_frame_files(files, session, frame, f);
            if (files.sequence) write_render_state(files.out_dir / ".linework-state", {o.signature, f, session.snapshot().coherence});
            if (!files.sequence) print_frame_report(files, session, frame, f);
        }
        if (g_interrupted && f < range.last) return interrupted(f, range.first);
    }
    if (files.sequence) {
        std::printf("time per frame: %.2f ms (mean of %d)\n", total_ms / std::max(range.last - start + 1, 1),
                    range.last - start + 1);
        std::printf("wrote %s/frame_%04d.png … frame_%04d.png\n", o.output.c_str(), range.first, range.last);
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
    add_scene_options(cmd, o->scene, true);
    cmd->add_option("-o,--output", o->output, "Output folder (created if missing)")->required();
    cmd->add_option("--eye", o->eye, "Camera position x,y,z");
    cmd->add_option("--target", o->target, "Point looked at x,y,z");
    cmd->add_option("--up", o->up, "Up vector x,y,z (default 0,1,0)");
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees (default 40)");
    cmd->add_option("--shading", o->shading, "Surface shading")->check(CLI::IsMember({"flat", "toon", "unlit", "none"}));
    cmd->add_flag("--exr", o->exr, "Also write OUT/frame_0000.exr (RGBA + depth channel Z)");
    cmd->add_flag("--lines-only", o->lines_only, "Draw the lines over the background, without shading");
    cmd->add_flag("--no-lines", o->no_lines, "Shading only, no feature lines");
    cmd->add_option("--svg", o->svg, "Also write the visible lines as SVG (pixel coordinates, one <g> per line set)");
    cmd->add_option("--hidden", o->hidden, "Hidden lines: none (default), dashed or faint")
        ->check(CLI::IsMember({"none", "dashed", "faint"}));
    cmd->add_option("--frames", o->frames,
                    "Render frames A:B (inclusive) to OUT/frame_NNNN.png (default: the scene's, else one frame)");
    cmd->add_option("--warmup", o->warmup, "Render K frames before A without writing them, so a range starts coherent");
    cmd->add_option("--orbit", o->orbit, "Turn the camera DEG degrees about the bounding-box centre over the frames");
    cmd->add_option("--dump-paths", o->dump_paths,
                    "Write DIR/frame_NNNN.json per frame: visible paths, their line set, (ρ, φ), level and samples");
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
