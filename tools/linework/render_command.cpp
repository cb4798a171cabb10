// `linework render SCENE.json|MODEL.glb -o DIR` — headless render to PNG (and EXR, SVG, dumps).
//
// A platform over SceneSession: options → scene description → session → the frame loop
// writing files (render_output.h). --resume goes on from OUT/.linework-state.
#include <algorithm>
#include <cmath>
#include <atomic>
#include <csignal>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include <unistd.h>

#include "commands.h"
#include "core/log.h"
#include "core/timer.h"
#include "progress.h"
#include "render_options.h"
#include "render_output.h"
#include "render_state.h"
#include "scene/animation.h"
#include "scene_options.h"

namespace lw::cli {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
// What a second signal says as it stops the render: set before the handler is installed.
const char* volatile g_stopped_message = "";

// Ctrl-C (SIGINT), or a scheduler's SIGTERM (scancel, requeue, pre-emption), finishes the
// frame in hand, writes it and the state, and stops (exit code 130). A second one stops at
// once, as the signal's default would: a frame can take minutes (a ribbon style). Every file
// is written under a temporary name and renamed, so the frames and states there are whole;
// a temporary file may be left (*.partial.*).
// One stop signal can arrive twice within a moment: a kill of a whole cgroup or process tree
// reaches a `farm task`'s render directly and again through the task, which passes its
// signals on. A second one within kRepeatNs of the first is that same stop.
constexpr long long kRepeatNs = 300'000'000;
std::atomic<long long> g_first_stop_ns{0};  // CLOCK_MONOTONIC (lock-free: safe in a handler)
static_assert(std::atomic<long long>::is_always_lock_free);

long long monotonic_ns() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
    return (long long)now.tv_sec * 1'000'000'000LL + now.tv_nsec;
}

void on_stop_signal(int signal) {
    const long long now = monotonic_ns();
    if (g_interrupted && now - g_first_stop_ns.load() < kRepeatNs) return;
    if (g_interrupted) {
        const char* stopped = g_stopped_message;
        [[maybe_unused]] const ssize_t said = ::write(STDERR_FILENO, stopped, std::strlen(stopped));
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    g_interrupted = 1;
    g_first_stop_ns.store(now);
    static const char message[] = "\nlinework: stopping after the frame in hand (again to stop at once)\n";
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, sizeof message - 1);  // async-signal-safe
}

class StopOnSignal {
public:
    explicit StopOnSignal(bool state_only) {
        g_interrupted = 0;
        g_stopped_message = state_only ? "\nlinework: stopped at once; the states written are whole; run the same "
                                         "command with --resume to go on\n"
                                       : "\nlinework: stopped at once; the frames written are whole; run the same "
                                         "command with --resume to go on\n";
        int_ = std::signal(SIGINT, on_stop_signal);
        term_ = std::signal(SIGTERM, on_stop_signal);
    }
    ~StopOnSignal() {
        std::signal(SIGINT, int_);
        std::signal(SIGTERM, term_);
    }
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

private:
    void (*int_)(int) = nullptr;
    void (*term_)(int) = nullptr;
};

void check_range_options(const RenderOptions& o) {
    if (o.warmup < 0) throw usage_error("--warmup: must be 0 or more");
    if (o.chunk < 0) throw usage_error("--chunk: must be 1 or more");
    if (!o.save_states.empty() && o.chunk == 0) throw usage_error("--save-states needs --chunk N, 1 or more frames per chunk");
    if (o.chunk > 0 && o.save_states.empty()) throw usage_error("--chunk is the spacing of --save-states: give both");
    if (o.state_only && o.save_states.empty())
        throw usage_error("--state-only writes nothing but the states: add --save-states DIR --chunk N");
    if (o.state_only && (o.exr || !o.svg.empty())) throw usage_error("--state-only writes no frames: drop --exr and --svg");
    if (!o.start_state.empty() && o.warmup > 0)
        throw usage_error("--start-state and --warmup: the saved state already carries what came before");
    if (o.output.empty() && !o.state_only) throw usage_error("--output (-o) is required");
}

// The range's chunk start after frame f, when f ends a chunk (state files are named by it).
bool ends_chunk(int f, FrameRange range, int chunk) {
    return chunk > 0 && f + 1 > range.first && f + 1 <= range.last && (f + 1 - range.first) % chunk == 0;
}

// --start-state: read before the session is made, since the line mesh must be built in the
// pose the state was taken with.
std::optional<RenderState> read_start_state(const RenderOptions& o) {
    if (o.start_state.empty()) return std::nullopt;
    if (!std::filesystem::exists(o.start_state))
        throw Error(o.start_state + ": no render state saved here yet (a farm's frames task needs its state phase to "
                                    "have run; `render --save-states` writes them)");
    RenderState state = read_render_state(o.start_state);
    if (state.signature != o.state_signature)
        throw Error(o.start_state + ": saved by a render with other options or inputs (" +
                    signature_difference(state.signature, o.state_signature) +
                    "; the scene, camera, style and line options and the files they name must be the same; only the "
                    "part, output and warm-up options may differ)");
    return state;
}

// --resume with --state-only: the last saved state of the part, restored; past the part when
// every state is there; nothing when none is.
std::optional<int> resume_saved_states(const RenderOptions& o, FrameRange range, FrameRange part, SceneSession& session) {
    for (int f = part.last; f >= part.first; --f) {
        if (!ends_chunk(f, range, o.chunk)) continue;
        const std::filesystem::path file = saved_state_path(o.save_states, f + 1);
        if (!std::filesystem::exists(file)) continue;
        const RenderState state = read_render_state(file);
        if (state.signature != o.state_signature || state.frame != f) continue;  // rewritten below
        if (f == part.last) return f + 1;
        restore_render_state(session, state, range);
        std::printf("resuming at frame %d from %s\n", f + 1, file.string().c_str());
        return f + 1;
    }
    return std::nullopt;
}

struct Shot {
    FrameRange range;  // --frames: the camera path and progress span it
    FrameRange part;   // what this command draws (--part, else the range)
    int start = 0;     // the first frame drawn: warm-up, resume or saved state included
};

// The first frame to draw, with the session's state restored where it starts from saved state.
int first_frame(const RenderOptions& o, const Shot& shot, const FrameFiles& files,
                const std::optional<RenderState>& start_state, SceneSession& session) {
    if (o.resume) {
        const std::optional<int> resumed = o.state_only
                                               ? resume_saved_states(o, shot.range, shot.part, session)
                                               : resume_point(o.signature, files, shot.range, shot.part, session);
        if (resumed) return *resumed;
    }
    if (start_state) {
        if (start_state->frame != shot.part.first - 1)
            throw Error(o.start_state + ": holds the state after frame " + std::to_string(start_state->frame) +
                        ", but this part starts at frame " + std::to_string(shot.part.first));
        restore_render_state(session, *start_state, shot.range);
    }
    return shot.part.first - o.warmup;
}

void print_header(const RenderOptions& o, const SceneSession& session, const Context& ctx, const Shot& shot,
                  bool sequence, double load_ms) {
    const SceneDesc& desc = session.desc();
    std::printf("scene: %s (%zu triangles, loaded in %.0f ms)\n", o.scene.input.c_str(),
                session.scene().mesh.triangle_count(), load_ms);
    if (!session.scene().mesh.indices.empty()) print_bounds(session.scene().bounds);
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("size: %dx%d\n", desc.width, desc.height);
    if (const LineMesh* lm = session.renderer().line_mesh()) {
        std::printf("lines: %zu welded vertices, feature size %.4g\n", lm->mesh.positions.size(), double(lm->feature_size));
        // What `auto` chose (line_mesh.h, coarse_faces), which the picture alone does not say.
        if (desc.lines.enabled && desc.lines.params.contours == ContourMode::Auto) {
            const size_t faces = lm->face_coarse.size();
            const auto coarse = size_t(std::count(lm->face_coarse.begin(), lm->face_coarse.end(), uint8_t(1)));
            std::printf("contours auto: %s (coarse: a median angle between neighbouring faces over %g degrees)\n",
                        coarse == 0       ? "smooth, no model is coarse"
                        : coarse == faces ? "mesh, the model is coarse"
                                          : ("mesh on the coarse models' " + std::to_string(coarse) + " of " +
                                             std::to_string(faces) + " faces, smooth elsewhere")
                                                .c_str(),
                        double(kCoarseDihedralDeg));
        }
    }
    if (!sequence) return;
    std::printf("frames: %d to %d", shot.range.first, shot.range.last);
    if (shot.part.first != shot.range.first || shot.part.last != shot.range.last)
        std::printf(", this part %d to %d", shot.part.first, shot.part.last);
    if (o.warmup) std::printf(", after %d warm-up frames", o.warmup);
    std::printf(" at %g fps%s\n", double(desc.animation.fps), o.state_only ? " (temporal state only)" : "");
    // Past the clips' end the last pose holds (nothing loops): frames that only repeat it.
    if (session.animated()) {
        // Frame f is at f / fps seconds; the first one past the end only repeats the last pose.
        const double end = double(session.duration_s()) * double(desc.animation.fps);
        const int past = int(std::floor(end + 1e-3)) + 1;
        if (shot.range.last >= past)
            std::printf("animation: the clips end at %.3f s (frame %.4g at %g fps); frames %d to %d repeat the last pose\n",
                        double(session.duration_s()), end, double(desc.animation.fps), std::max(past, shot.range.first),
                        shot.range.last);
    }
}

// Draws shot.start … shot.part.last, writing the part's frames (and their progress state)
// and the states at chunk starts; 0, or 130 when a signal stopped it.
int render_frames(const RenderOptions& o, const Shot& shot, const FrameFiles& files,
                  SceneSession& session) {
    const float fps = session.desc().animation.fps;
    Progress progress(shot.part.last - shot.start + 1, "frame");
    double total_ms = 0.0;
    int states = 0;
    for (int f = shot.start; f <= shot.part.last; ++f) {
        const bool write = f >= shot.part.first && !o.state_only;
        // The state before the part's first frame: from the first PNG on, a state is there
        // for --resume (render_output.h).
        if (write && f == shot.part.first && files.sequence)
            write_render_state(files.progress_state, {o.signature, f - 1, session.snapshot().coherence});
        const Frame frame = session.frame({.when = frame_time(f, shot.range, fps),
                                           .outputs = {.color = write, .depth = write && o.exr, .draw = !o.state_only},
                                           .seed = uint64_t(f) + 1});
        total_ms += frame.timings.total_ms;
        progress.update(f - shot.start + 1, f, frame.timings.total_ms);
        if (write) {
            // A still frame written over a sequence's frame: the sequence's state no longer
            // speaks for every frame there (a sequence rewrites it before its first frame).
            if (!files.sequence && std::filesystem::exists(files.out_dir / frame_name(f, "png"))) {
                std::error_code ec;
                if (std::filesystem::remove(files.progress_state, ec))
                    log_warning(files.progress_state.string() + ": removed: frame " + std::to_string(f) +
                                " of the sequence there is replaced by this still, so --resume can no longer go on "
                                "from it");
            }
            write_frame_files(files, session, frame, f);
            if (files.sequence)
                write_render_state(files.progress_state, {o.signature, f, session.snapshot().coherence});
            else
                print_frame_report(files, session, frame, f);
        }
        if (!o.save_states.empty() && ends_chunk(f, shot.range, o.chunk)) {
            write_render_state(saved_state_path(o.save_states, f + 1),
                               {o.state_signature, f, session.snapshot().coherence});
            ++states;
        }
        if (g_interrupted && f < shot.part.last) {
            if (!o.state_only) return interrupted(f, shot.part.first);
            std::fprintf(stderr, "\nlinework: interrupted after frame %d; the states written stay in %s; run the same "
                                 "command with --resume to go on\n", f, o.save_states.c_str());
            return 130;
        }
    }
    const int drawn = shot.part.last - shot.start + 1;
    if (files.sequence)
        std::printf("time per frame: %.2f ms (mean of %d%s)\n", total_ms / std::max(drawn, 1), drawn,
                    o.warmup ? ", warm-up frames included" : "");
    if (files.sequence && !o.state_only) {
        // The first and last files of each kind written ("a … b", or one name for one frame).
        const auto span = [&](const std::filesystem::path& first, const std::filesystem::path& last) {
            std::printf("wrote %s%s%s\n", first.string().c_str(), first == last ? "" : " … ",
                        first == last ? "" : last.filename().string().c_str());
        };
        const std::filesystem::path out(o.output);
        span(out / frame_name(shot.part.first, "png"), out / frame_name(shot.part.last, "png"));
        if (o.exr) span(out / frame_name(shot.part.first, "exr"), out / frame_name(shot.part.last, "exr"));
        if (!o.svg.empty()) span(svg_path(files, shot.part.first), svg_path(files, shot.part.last));
    }
    if (states > 0) std::printf("wrote %d states to %s\n", states, o.save_states.c_str());
    if (!o.dump_paths.empty() && !o.state_only) std::printf("wrote path dumps to %s\n", o.dump_paths.c_str());
    return 0;
}

int run_render(RenderOptions o) {
    check_range_options(o);
    // Plain values and flags (an optional here sets off GCC 12's -Wmaybe-uninitialized).
    const bool frames_given = !o.frames.empty(), part_given = !o.part.empty();
    const FrameRange frames_flag = frames_given ? parse_frames(o.frames) : FrameRange{};
    const FrameRange part_flag = part_given ? parse_frames(o.part, "--part") : FrameRange{};
    SceneDesc desc = scene_from_options(o.scene);
    check_flags_shape_drawn_lines(o.scene, desc.lines);
    apply_frame_overrides(o, desc);
    const std::string inputs = input_files_signature(desc, o.scene.slam);
    o.signature += inputs;
    o.state_signature += inputs;
    FrameFiles files{o.output, o.svg, o.state_only ? std::string() : o.dump_paths, o.exr};
    const std::optional<RenderState> start_state = read_start_state(o);

    const bool validation = validation_on(o.scene);
    Context ctx({.device = parse_device_choice(o.scene.device), .validation = validation,
                 .compute_site = parse_compute_site(o.scene.compute)});
    check_samples_on_device(ctx, o.scene, desc);
    Timer load_timer;
    SessionOptions options = session_options(o.scene, desc);
    options.coherent = options.coherent || !o.dump_paths.empty();
    options.camera = camera_override(o);
    // Frames: the command line, else the scene's, else the clips' length (one frame without).
    Shot shot;
    shot.range = frames_given ? frames_flag : desc.animation.frames.value_or(FrameRange{0, 0});
    SceneSession session(ctx, desc, options);
    if (!frames_given) shot.range = session.default_frames();
    if (!desc.animation.play && shot.range.last > shot.range.first)
        for (const Model& model : session.scene().models)
            if (const std::string w = unplayed_clips_warning(model); !w.empty()) log_warning(w);
    shot.part = part_given ? part_flag : shot.range;
    if (shot.part.first < shot.range.first || shot.part.last > shot.range.last)
        throw usage_error("--part " + o.part + " lies outside the range " + std::to_string(shot.range.first) + ":" +
                          std::to_string(shot.range.last));
    if (part_given && !start_state && o.warmup == 0 && shot.part.first > shot.range.first &&
        session.strokes_carry_state())
        log_warning("--part " + o.part + " without --start-state or --warmup: the strokes' parameterization starts "
                    "afresh at frame " + std::to_string(shot.part.first) + ", where one render of the range carries it "
                    "on from the frames before (--start-state brings it, as a farm's --exact tasks do)");
    if (o.state_only) {
        // Frames after the last chunk start leave no state: not drawn.
        int last = shot.part.last;
        while (last >= shot.part.first && !ends_chunk(last, shot.range, o.chunk)) --last;
        if (last < shot.part.first)
            throw usage_error("--state-only: no chunk of " + std::to_string(o.chunk) + " frames starts within frames " +
                              std::to_string(shot.part.first + 1) + " to " + std::to_string(shot.part.last + 1) +
                              ": there is no state to save");
        shot.part.last = last;
    }
    files.sequence = shot.range.last > shot.range.first || o.warmup > 0 || desc.animation.play ||
                     desc.camera_path.kind != CameraPath::Kind::Fixed;
    files.progress_state = files.out_dir / (part_given ? ".linework-state-" + std::to_string(shot.part.first) + "-" +
                                                            std::to_string(shot.part.last)
                                                      : std::string(".linework-state"));
    // Made once the scene has loaded, so that a scene that fails to load leaves no empty folders.
    if (!o.state_only) create_folders(files);
    if (!o.save_states.empty()) create_folder(o.save_states, "the --save-states");
    // From the header on, a signal stops after the frame in hand (render_frames reads it).
    const StopOnSignal stop(o.state_only);
    print_header(o, session, ctx, shot, files.sequence, load_timer.elapsed_ms());

    shot.start = first_frame(o, shot, files, start_state, session);
    if (shot.start > shot.part.last) {
        if (o.state_only)
            std::printf("all states of frames %d to %d are already in %s\n", shot.part.first, shot.part.last,
                        o.save_states.c_str());
        else
            std::printf("all frames %d to %d are already in %s\n", shot.part.first, shot.part.last, o.output.c_str());
        return 0;
    }
    const int stopped = render_frames(o, shot, files, session);
    if (stopped != 0) return stopped;
    return exit_code_after_validation(ctx, validation);
}

}  // namespace

Runner add_render_command(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Render a scene file or a glTF model headlessly to OUT/frame_0000.png.\n"
        "Without a camera in the scene (or --eye/--target), the camera frames the bounding box.");
    add_frame_options(cmd, *o);
    cmd->add_option("-o,--output", o->output, "Output folder, created if missing (required, but not with --state-only)");
    cmd->add_option("--frames", o->frames,
                    "Render frames A:B (inclusive) to OUT/frame_NNNN.png (default: the scene's, else one frame)");
    cmd->add_option("--warmup", o->warmup, "Render K frames before A (or the part) without writing them, so it starts "
                                           "coherent");
    cmd->add_flag("--resume", o->resume,
                  "Go on with an interrupted sequence: skip the frames already in the output folder and "
                  "restore the parameterization from its .linework-state");
    // A farm task's options (docs: README "Render farm").
    cmd->add_option("--part", o->part,
                    "Render only frames C:D of the --frames range; the camera path and clip still span the range "
                    "(a farm task)");
    cmd->add_option("--save-states", o->save_states,
                    "Write DIR/state_NNNN.lwstate, the temporal state a render of frames NNNN… starts from, at "
                    "every chunk start NNNN = A+N, A+2N … of the range (with --chunk N)");
    cmd->add_option("--chunk", o->chunk, "Frames per chunk for --save-states");
    cmd->add_flag("--state-only", o->state_only,
                  "Run only what the temporal state needs (lines, visibility, votes, RANSAC, splat): no "
                  "shading, strokes or frame files; with --save-states");
    cmd->add_option("--start-state", o->start_state,
                    "Start the part (or range) from a state written by --save-states: frames identical to a "
                    "render of the whole range");
    return [o, cmd] {
        o->signature = given_options_signature(*cmd, {"--resume"});
        o->state_signature = given_options_signature(*cmd, kRangeOptions, {"--dump-paths"});
        return run_render(*o);
    };
}

}  // namespace lw::cli
