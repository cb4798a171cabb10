// `linework view SCENE.json|MODEL.glb` — the interactive viewer (README "linework view").
//
// A platform over SceneSession, the renderer of `linework render`: every frame is the
// session's, drawn into its offscreen target (ribbons written back into it), copied to the
// swapchain with the ImGui panel over it (engine/platform). `--script FILE` replays commands
// (view_script.h) so that the viewer runs without a person; `--benchmark N` times N frames.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <GLFW/glfw3.h>

#include "commands.h"
#include "render_state.h"
#include "core/timer.h"
#include "gpu/render_target.h"
#include "io/image_io.h"
#include "platform/swapchain.h"
#include "scene_options.h"
#include "view_input.h"

namespace lw::cli {

namespace {

struct ViewOptions {
    SceneOptions scene;
    std::string script, output = ".";
    int benchmark = 0, subdivide = 0;
    bool no_vsync = false, no_panel = false;
};

// One frame: the session's, the panel over it, presented; the screenshot asked for. False
// when the swapchain must be made again. `overlap`: the frame is begun and the one before it
// finished and presented, so that the host's work on that one runs while the device draws
// this one's surface (FrameRenderer); the screen shows the state of one frame earlier.
bool draw_and_present(ViewerState& s, SceneSession& session, Swapchain& swapchain, UiOverlay& ui, Input& input,
                      FrameTimings& timings, bool overlap) {
    Timer render_timer;
    session.begin_frame({.when = {.seconds = s.time_s}, .camera = s.camera.view(), .outputs = {.color = false},
                         .ribbons_to_target = true});
    if (overlap && session.frames_in_flight() < 2) return true;  // the first: nothing to show yet
    const Frame frame = session.finish_frame();
    s.render_ms = render_timer.elapsed_ms();
    timings = frame.timings;
    s.gpu = frame.timings.gpu;
    s.extract_ms = frame.timings.extract_ms;
    s.chain_ms = frame.timings.chain_ms;
    s.visibility_ms = frame.timings.visibility_ms;
    s.coherence_ms = frame.timings.coherence_ms;
    s.paths = frame.screen_paths.size();
    ui.begin_frame();
    input.ui_keyboard = ui.wants_keyboard();
    draw_panel(s);
    ui.end_frame();
    Timer present_timer;
    ImageRGBA8 shot;
    const bool want_shot = !s.screenshot_path.empty();
    const bool presented = swapchain.present({.frame = &session.target().color,
                                              .overlay = [&](VkCommandBuffer cmd) { ui.record(cmd); },
                                              .screenshot = want_shot ? &shot : nullptr});
    s.present_ms = present_timer.elapsed_ms();
    if (want_shot && !shot.pixels.empty()) write_screenshot(s, shot);
    return presented;
}

namespace {

// The surface's samples per pixel: the scene's or --samples, else 4, but 1 on a CPU device,
// where 4 cost about 2.2× a frame (docs/BENCHMARKS.md "Antialiasing") and the viewer is for
// moving the camera. A view saved then says "samples": 1, so that it renders as shown.
uint32_t viewer_samples(const SceneDesc& desc, const SceneOptions& o, const Context& ctx) {
    const SurfaceStyle& style = desc.style;
    if (style.samples == 0 && ctx.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        std::printf("surface: 1 sample per pixel on a CPU device (4 would cost about 2.2x a frame; --samples 4, "
                    "the scene's \"samples\" or the panel)\n");
        return 1;
    }
    // Checked now, as render does before its first frame: a count the device cannot draw
    // was refused only when the first frame was made (a script that quit before it, never).
    check_samples_on_device(ctx, o, desc);
    std::printf("surface: %u samples per pixel\n", surface_samples(style));
    return style.samples;
}

}  // namespace

int run_view(const ViewOptions& o) {
    if (o.benchmark < 0) throw usage_error("--benchmark: must be 1 or more frames");
    if (o.subdivide < 0 || o.subdivide > 4) throw usage_error("--subdivide: 0 to 4");
    std::unique_ptr<ScriptPlayer> player;
    if (!o.script.empty()) player = std::make_unique<ScriptPlayer>(read_script(o.script));
    const SceneDesc desc = scene_from_options(o.scene);
    if (desc.models.empty()) throw Error(o.scene.input + ": the viewer needs a 3D model (this scene has layers alone)");
    create_folder(o.output, "screenshot");  // as render makes its -o: a screenshot must not end the session

    Window window({.width = desc.width, .height = desc.height,
                   .title = "linework — " + std::filesystem::path(o.scene.input).filename().string()});
    const bool validation = validation_on(o.scene);
    Context ctx({.device = parse_device_choice(o.scene.device), .validation = validation,
                 .instance_extensions = window.required_instance_extensions(), .swapchain = true,
                 .compute_site = parse_compute_site(o.scene.compute)});
    std::printf("device: %s\n", ctx.info().describe().c_str());
    SceneDesc styled = desc;
    styled.style.samples = viewer_samples(desc, o.scene, ctx);
    const bool fixed_step = player || o.benchmark > 0;  // scripted runs see the same frames every time
    // Everything that records or owns GPU work lives in this scope, so that the validation
    // layer has spoken about its destruction before the exit status is decided.
    {
        Swapchain swapchain(ctx, window, {.vsync = !o.no_vsync && o.benchmark == 0});
        SessionOptions options = session_options(o.scene, desc);
        options.color_format = swapchain.format();  // the frame reaches the window by a copy
        options.subdivide = o.subdivide;
        SceneDesc sized = styled;  // the window's framebuffer may differ from the scene's size
        sized.width = int(swapchain.extent().width);
        sized.height = int(swapchain.extent().height);
        SceneSession session(ctx, sized, options);
        std::printf("scene: %s (%zu triangles)\n", o.scene.input.c_str(), session.scene().mesh.triangle_count());
        if (session.has_model()) print_bounds(session.scene().bounds);
        ViewerState s = initial_state(session, !o.no_panel, o.output);
        s.coherence = session.coherence();
        s.device = ctx.info().describe();
        s.host_compute = ctx.preferred_compute_site() == ComputeSite::Host;
        Input input{.state = &s};
        install_callbacks(window, input);
        UiOverlay ui(ctx, window, swapchain.render_pass(), swapchain.min_image_count(), swapchain.image_count());
        struct IdleOnExit {  // destroyed first: the last presented frame may still read the target
            VkDevice device;
            ~IdleOnExit() { vkDeviceWaitIdle(device); }
        } idle_on_exit{ctx.device()};

        auto save_view = [&] { save_view_file(s, swapchain.extent()); };

        // Frames overlap where the device does not share the host's cores: on lavapipe the
        // surface pass keeps both busy, and host work beside it took 2.3x as long, for no
        // gain in frame time (docs/BENCHMARKS.md "Viewer").
        const bool overlap = !player && ctx.info().type != VK_PHYSICAL_DEVICE_TYPE_CPU;
        bool recreate = false;
        ViewStats stats;
        const int warmup = o.benchmark > 0 ? 10 : 0;
        int frames = 0;
        auto last = std::chrono::steady_clock::now();
        while (!s.quit) {
            glfwPollEvents();
            if (window.should_close()) break;
            const float height = float(swapchain.extent().height);
            if (player) play_script(*player, window, input, height, save_view);
            if (s.quit || (o.benchmark > 0 && frames >= o.benchmark + warmup)) break;
            if (o.benchmark > 0) s.camera.orbit(0.5f, 0.0f);  // a slow orbit: lines change every frame
            handle_mouse(window, ui, input, height);

            // Minimized: nothing to draw into; never make a swapchain of zero size.
            const VkExtent2D fb = window.framebuffer_size();
            if (fb.width == 0 || fb.height == 0 || window.iconified() || input.script_minimized) {
                glfwWaitEventsTimeout(0.01);
                last = std::chrono::steady_clock::now();
                continue;
            }
            if (recreate || fb.width != swapchain.extent().width || fb.height != swapchain.extent().height) {
                if (!swapchain.recreate(fb)) continue;
                recreate = false;
                while (session.frames_in_flight() > 0) (void)session.finish_frame();  // drawn for the old size
                session.resize(swapchain.extent().width, swapchain.extent().height);
            }
            if (s.playing) {
                const double dt = fixed_step ? 1.0 / s.fps
                                             : std::chrono::duration<double>(std::chrono::steady_clock::now() - last).count();
                s.time_s = float(std::fmod(double(s.time_s) + dt, double(std::max(s.duration_s, 1e-3f))));
            }
            apply_edits(s, session);

            FrameTimings timings;
            if (!draw_and_present(s, session, swapchain, ui, input, timings, overlap)) recreate = true;
            if (!s.save_path.empty()) save_view();
            const auto now = std::chrono::steady_clock::now();
            s.frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
            last = now;
            s.history.push_back(float(s.frame_ms));
            if (s.history.size() > 120) s.history.pop_front();
            if (frames++ >= warmup) stats.add(s, timings);
        }
        while (session.frames_in_flight() > 0) (void)session.finish_frame();
        stats.print(swapchain.extent().width, swapchain.extent().height);
        // A benchmark cut short (a script's quit, the window closed) says so: it printed nothing
        // when the warm-up frames were not over.
        if (o.benchmark > 0 && int(stats.frame_ms.size()) < o.benchmark)
            std::printf("benchmark: stopped after %d frame(s), %zu of the %d timed ones (the first %d are warm-up)\n",
                        frames, stats.frame_ms.size(), o.benchmark, warmup);
    }  // GPU objects destroyed
    return exit_code_after_validation(ctx, validation);
}

}  // namespace

Runner add_view_command(CLI::App& app) {
    auto o = std::make_shared<ViewOptions>();
    CLI::App* cmd = app.add_subcommand(
        "view",
        "Open a window on a scene file or a glTF model: orbit (left drag), pan (right drag), zoom (wheel);\n"
        "keys and a panel switch line sets, thresholds, styles and the animation (README \"linework view\").");
    add_scene_options(cmd, o->scene, false);
    cmd->add_option("--script", o->script,
                    "Replay commands from FILE, one a line: wait N, orbit DX DY, zoom F, pan DX DY, key NAME, "
                    "resize W H, minimize, restore, screenshot PATH.png, save PATH.json, quit");
    cmd->add_option("--benchmark", o->benchmark,
                    "Render N frames (after 10 warm-up frames) of a slow orbit without vsync, print the frame "
                    "time and fps, exit")
        ->check(CLI::Range(1, 100000000));
    cmd->add_option("--subdivide", o->subdivide, "Midpoint subdivisions of the model (each ×4 triangles; benchmarks)");
    cmd->add_option("-o,--output", o->output, "Folder of screenshots (F12) and saved views (F5), made if missing")
        ->capture_default_str();
    cmd->add_flag("--no-vsync", o->no_vsync, "Present without waiting for the display (mailbox or immediate)");
    cmd->add_flag("--no-panel", o->no_panel, "Start with the panel hidden (F1 shows it)");
    return [o] { return run_view(*o); };
}

}  // namespace lw::cli
