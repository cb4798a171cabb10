// `linework view SCENE.json|MODEL.glb` — the interactive viewer (README "linework view").
//
// Every frame is drawn by FrameRenderer, the renderer of `linework render`, into its
// offscreen target; the swapchain blits that target to the window and draws the ImGui panel
// over it (engine/platform). `--script FILE` replays commands (view_script.h) so that the
// viewer runs without a person; `--benchmark N` times N frames of a slow orbit.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <thread>

#include <GLFW/glfw3.h>

#include "commands.h"
#include "core/error.h"
#include "core/timer.h"
#include "geometry/subdivide.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "platform/swapchain.h"
#include "platform/ui_overlay.h"
#include "platform/window.h"
#include "render/frame_renderer.h"
#include "render_layers.h"
#include "scene/scene.h"
#include "view_keys.h"
#include "view_script.h"
#include "view_state.h"

namespace lw::cli {

namespace {

struct ViewOptions {
    std::string input;
    std::string device = "auto";
    std::string compute = "auto";
    std::string size;
    std::string slam;
    std::string param;
    float stroke_width = 6.0f;
    float splat_radius = 0.0f;
    std::string script;
    int benchmark = 0;
    int subdivide = 0;
    std::string output = ".";
    bool validation = false;
    bool no_vsync = false;
    bool no_panel = false;
};

// What GLFW callbacks see (glfwSetWindowUserPointer).
struct Input {
    ViewerState* state = nullptr;
    bool ui_keyboard = false;  // ImGui has the keyboard: keys are not the viewer's
    double scroll = 0.0;
};

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
    auto* input = static_cast<Input*>(glfwGetWindowUserPointer(window));
    if (!input || input->ui_keyboard) return;
    const bool repeatable = key == GLFW_KEY_LEFT || key == GLFW_KEY_RIGHT || key == GLFW_KEY_UP || key == GLFW_KEY_DOWN ||
                            key == GLFW_KEY_EQUAL || key == GLFW_KEY_MINUS || key == GLFW_KEY_LEFT_BRACKET ||
                            key == GLFW_KEY_RIGHT_BRACKET;
    if (action == GLFW_PRESS || (action == GLFW_REPEAT && repeatable)) apply_key(*input->state, key);
}

void on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
    if (auto* input = static_cast<Input*>(glfwGetWindowUserPointer(window))) input->scroll += dy;
}

std::string numbered(const std::string& dir, const char* stem, int n, const char* ext) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%04d.%s", stem, n, ext);
    return (std::filesystem::path(dir) / name).string();
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int run_view(const ViewOptions& o) {
    if (o.benchmark < 0) throw usage_error("--benchmark: must be 0 or more frames");
    if (o.subdivide < 0 || o.subdivide > 4) throw usage_error("--subdivide: 0 to 4");
    const std::filesystem::path input(o.input);
    if (!std::filesystem::exists(input)) throw Error(o.input + ": no such file");
    std::unique_ptr<ScriptPlayer> player;
    if (!o.script.empty()) player = std::make_unique<ScriptPlayer>(read_script(o.script));

    ViewerState s;
    s.desc = is_model_path(input) ? scene_for_model(input) : load_scene_file(input);
    SceneDesc& desc = s.desc;
    if (!o.size.empty()) {
        const glm::ivec2 size = parse_size(o.size, "--size");
        desc.width = size.x;
        desc.height = size.y;
    }
    if (!o.slam.empty()) use_slam_strokes(desc.lines, o.slam, o.stroke_width);
    for (LineStyle& style : desc.lines.styles)
        if (!style.ribbon.empty()) {
            std::printf("view: ribbon styles are drawn as plain lines (ribbons are synthesized after readback: "
                        "linework render)\n");
            style.ribbon.clear();
        }
    if (desc.models.empty()) throw Error(o.input + ": the viewer needs a 3D model (this scene has layers alone)");

    LoadedScene scene = load_scene(desc);
    if (o.subdivide > 0) scene.mesh = subdivide_midpoint(scene.mesh, o.subdivide);
    std::printf("scene: %s (%zu triangles)\n", o.input.c_str(), scene.mesh.triangle_count());
    for (int t = 0; t < kLineTypeCount; ++t) {
        const std::string& file = desc.lines.styles[size_t(t)].slam;
        if (file.empty()) continue;
        for (int u = 0; u < t; ++u)
            if (s.slams[size_t(u)] && desc.lines.styles[size_t(u)].slam == file) s.slams[size_t(t)] = s.slams[size_t(u)];
        if (!s.slams[size_t(t)]) s.slams[size_t(t)] = read_slam(file);
        s.strokes[size_t(t)] = true;
        s.coherence.slam_length_px = float(s.slams[size_t(t)]->length);
        s.coherence.length_scale = float(s.slams[size_t(t)]->height) / desc.lines.styles[size_t(t)].width;
    }
    if (o.param == "arclength") s.coherence.policy = ParamPolicy::Arclength;
    if (o.param == "stretch") s.coherence.policy = ParamPolicy::Stretch;
    s.coherence.splat_radius_px = o.splat_radius > 0.0f ? o.splat_radius : desc.lines.sample_spacing_px * 2.0f;
    SceneLayers layers = load_scene_layers(desc);
    for (LayerStyle& style : layers.styles) {
        style.coherence.policy = s.coherence.policy;
        style.coherence.splat_radius_px = s.coherence.splat_radius_px;
    }
    s.camera = s.home = OrbitCamera::from(scene.camera);
    s.animated = desc.animation.play && animation_duration(scene) > 0.0f;
    s.duration_s = s.animated ? animation_duration(scene) : 0.0f;
    s.fps = desc.animation.fps;
    s.playing = s.animated;
    s.panel = !o.no_panel;
    s.output_dir = o.output;
    s.triangles = scene.mesh.triangle_count();
    const bool fixed_step = player || o.benchmark > 0;  // scripted runs see the same frames every time

    Window window({.width = desc.width, .height = desc.height, .title = "linework — " + input.filename().string()});
    const bool validation = o.validation || validation_from_environment();
    Context ctx({.device = parse_device_choice(o.device),
                 .validation = validation,
                 .instance_extensions = window.required_instance_extensions(),
                 .swapchain = true,
                 .compute_site = parse_compute_site(o.compute, "--compute")});
    s.device = ctx.info().describe();
    s.host_compute = ctx.preferred_compute_site() == ComputeSite::Host;
    std::printf("device: %s\n", s.device.c_str());
    // Everything that records or owns GPU work lives in this scope, so that the validation
    // layer has spoken about its destruction before the exit status is decided.
    {
        Swapchain swapchain(ctx, window, {.vsync = !o.no_vsync && o.benchmark == 0});
        Input input_state{.state = &s};
        glfwSetWindowUserPointer(window.get(), &input_state);
        glfwSetKeyCallback(window.get(), &on_key);  // before ImGui, which chains to them
        glfwSetScrollCallback(window.get(), &on_scroll);
        UiOverlay ui(ctx, window, swapchain.render_pass(), swapchain.min_image_count(), swapchain.image_count());

        // The frame in the swapchain's format: it reaches the window by a copy, not a blit.
        FrameRenderer renderer(ctx, swapchain.extent().width, swapchain.extent().height, swapchain.format());
        TriangleMesh posed = s.animated ? pose_scene(scene, 0.0f) : scene.mesh;
        renderer.set_mesh(posed, desc.lines.enabled, desc.lines.params.crease_angle_deg);
        if (!layers.descs.empty()) renderer.set_layers(layers.styles);
        // Destroyed first: the last presented frame may still read the renderer's target.
        struct IdleOnExit {
            VkDevice device;
            ~IdleOnExit() { vkDeviceWaitIdle(device); }
        } idle_on_exit{ctx.device()};
        const bool layer_slams =
            std::any_of(layers.styles.begin(), layers.styles.end(), [](const LayerStyle& l) { return l.slam.has_value(); });

        // The current view as a scene file (F5, the panel, or the script's `save`).
        auto save_view = [&] {
            const std::string path =
                s.save_path == "*" ? numbered(s.output_dir, "linework_view", s.saves_done, "json") : s.save_path;
            SceneDesc saved = desc;
            saved.width = int(swapchain.extent().width);
            saved.height = int(swapchain.extent().height);
            std::ofstream out(path, std::ios::binary);
            out << scene_json(saved, s.camera.view(), std::filesystem::path(path).parent_path());
            if (!out.flush()) throw Error(path + ": cannot write");
            ++s.saves_done;
            s.message = "wrote " + path;
            std::printf("%s\n", s.message.c_str());
            s.save_path.clear();
        };

        bool recreate = false, script_minimized = false;
        glm::dvec2 last_mouse{0.0};
        glfwGetCursorPos(window.get(), &last_mouse.x, &last_mouse.y);
        std::vector<double> frame_times;
        struct {
            double render = 0, present = 0, extract = 0, chain = 0, visibility = 0, coherence = 0;
            std::vector<PassTime> gpu;
        } sums;  // over the timed frames
        const int warmup = o.benchmark > 0 ? 10 : 0;
        int frames = 0;
        auto last = std::chrono::steady_clock::now();
        while (!s.quit) {
            glfwPollEvents();
            if (window.should_close()) break;
            if (player) {
                for (const ScriptCommand& c : player->next_frame()) switch (c.kind) {
                        case ScriptCommand::Kind::Orbit: s.camera.orbit(c.a, c.b); break;
                        case ScriptCommand::Kind::Zoom: s.camera.zoom(c.a); break;
                        case ScriptCommand::Kind::Pan: s.camera.pan(c.a, c.b, float(swapchain.extent().height)); break;
                        case ScriptCommand::Kind::Key: apply_key(s, key_from_name(c.text)); break;
                        case ScriptCommand::Kind::Resize: glfwSetWindowSize(window.get(), int(c.a), int(c.b)); break;
                        case ScriptCommand::Kind::Minimize:
                            glfwIconifyWindow(window.get());
                            script_minimized = true;  // without a window manager (Xvfb) iconify does nothing
                            break;
                        case ScriptCommand::Kind::Restore:
                            glfwRestoreWindow(window.get());
                            script_minimized = false;
                            break;
                        case ScriptCommand::Kind::Screenshot: s.screenshot_path = c.text; break;
                        case ScriptCommand::Kind::Save:
                            s.save_path = c.text;
                            save_view();
                            break;
                        case ScriptCommand::Kind::Quit: s.quit = true; break;
                        case ScriptCommand::Kind::Wait: break;
                    }
                if (s.quit) break;
            }
            if (o.benchmark > 0) {
                if (frames >= o.benchmark + warmup) break;
                s.camera.orbit(0.5f, 0.0f);  // a slow orbit: lines and strokes change every frame
            }

            // Mouse: left drag orbits, right or middle drag (or shift + left) pans, the wheel zooms.
            glm::dvec2 mouse;
            glfwGetCursorPos(window.get(), &mouse.x, &mouse.y);
            const glm::dvec2 delta = mouse - last_mouse;
            last_mouse = mouse;
            if (!ui.wants_mouse()) {
                const bool left = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
                const bool shift = glfwGetKey(window.get(), GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
                const bool pan = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                                 glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS || (left && shift);
                if (pan && (delta.x != 0.0 || delta.y != 0.0))
                    s.camera.pan(float(delta.x), float(delta.y), float(swapchain.extent().height));
                else if (left && (delta.x != 0.0 || delta.y != 0.0))
                    s.camera.orbit(-0.3f * float(delta.x), 0.3f * float(delta.y));
                if (input_state.scroll != 0.0) s.camera.zoom(float(std::pow(1.1, input_state.scroll)));
            }
            input_state.scroll = 0.0;

            // Minimized: nothing to draw into; never make a swapchain of zero size.
            const VkExtent2D fb = window.framebuffer_size();
            if (fb.width == 0 || fb.height == 0 || window.iconified() || script_minimized) {
                glfwWaitEventsTimeout(0.01);
                last = std::chrono::steady_clock::now();
                continue;
            }
            if (recreate || fb.width != swapchain.extent().width || fb.height != swapchain.extent().height) {
                if (!swapchain.recreate(fb)) continue;
                recreate = false;
                renderer.resize(swapchain.extent().width, swapchain.extent().height);
            }

            // Changes that reach beyond the next frame's parameters.
            if (s.playing) {
                const double dt = fixed_step ? 1.0 / s.fps
                                             : std::chrono::duration<double>(std::chrono::steady_clock::now() - last).count();
                s.time_s = float(std::fmod(double(s.time_s) + dt, double(std::max(s.duration_s, 1e-3f))));
                s.time_changed = true;
            }
            if (s.time_changed && s.animated) {
                posed = pose_scene(scene, s.time_s);
                renderer.deform(posed);
                s.time_changed = false;
            }
            if (s.crease_changed) {
                renderer.set_mesh(posed, desc.lines.enabled, desc.lines.params.crease_angle_deg);
                s.crease_changed = false;
            }
            if (s.slams_changed) {
                for (int t = 0; t < kLineTypeCount; ++t)
                    if (s.slams[size_t(t)] && s.strokes[size_t(t)])
                        renderer.set_slam(LineType(t), *s.slams[size_t(t)]);
                    else
                        renderer.clear_slam(LineType(t));
                s.slams_changed = false;
            }

            // The frame: the same renderer as `linework render`, no colour readback.
            Timer render_timer;
            const VkExtent2D extent = swapchain.extent();
            const ViewCamera view = s.camera.view();
            const CameraMatrices camera = camera_matrices(view, float(extent.width) / float(extent.height), scene.bounds);
            const bool strokes = std::any_of(s.strokes.begin(), s.strokes.end(), [](bool b) { return b; });
            const bool coherent = (desc.lines.enabled && strokes) || layer_slams;
            std::vector<LayerFrame> layer_frames = scene_layer_frames(
                layers, s.time_s, glm::vec2(extent.width, extent.height), desc.lines.sample_spacing_px);
            const Frame frame = renderer.render(camera, view.eye, desc.style, desc.lines, {.color = false},
                                                coherent ? &s.coherence : nullptr,
                                                layers.descs.empty() ? nullptr : &layer_frames);
            s.render_ms = render_timer.elapsed_ms();
            s.gpu = frame.timings.gpu;
            s.extract_ms = frame.timings.extract_ms;
            s.chain_ms = frame.timings.chain_ms;
            s.visibility_ms = frame.timings.visibility_ms;
            s.coherence_ms = frame.timings.coherence_ms;
            s.paths = frame.screen_paths.size();

            ui.begin_frame();
            input_state.ui_keyboard = ui.wants_keyboard();
            draw_panel(s);
            ui.end_frame();

            Timer present_timer;
            ImageRGBA8 shot;
            const bool want_shot = !s.screenshot_path.empty();
            if (!swapchain.present({.frame = &renderer.target().color,
                                    .overlay = [&](VkCommandBuffer cmd) { ui.record(cmd); },
                                    .screenshot = want_shot ? &shot : nullptr}))
                recreate = true;
            s.present_ms = present_timer.elapsed_ms();
            if (want_shot && !shot.pixels.empty()) {
                const std::string path = s.screenshot_path == "*" ? numbered(s.output_dir, "linework_view", s.screenshots_taken, "png")
                                                                  : s.screenshot_path;
                write_png(path, shot);
                ++s.screenshots_taken;
                s.message = "wrote " + path;
                std::printf("%s\n", s.message.c_str());
                s.screenshot_path.clear();
            }
            if (!s.save_path.empty()) save_view();
            const auto now = std::chrono::steady_clock::now();
            s.frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
            last = now;
            s.history.push_back(float(s.frame_ms));
            if (s.history.size() > 120) s.history.pop_front();
            if (frames >= warmup) {
                frame_times.push_back(s.frame_ms);
                sums.render += s.render_ms;
                sums.present += s.present_ms;
                sums.extract += frame.timings.extract_ms;
                sums.chain += frame.timings.chain_ms;
                sums.visibility += frame.timings.visibility_ms;
                sums.coherence += frame.timings.coherence_ms;
                if (sums.gpu.size() != s.gpu.size()) {  // the passes of the first timed frame
                    sums.gpu = s.gpu;
                    for (PassTime& t : sums.gpu) t.ms = 0.0;
                }
                for (size_t i = 0; i < sums.gpu.size(); ++i) sums.gpu[i].ms += s.gpu[i].ms;
            }
            ++frames;
        }

        if (!frame_times.empty()) {
            const double mean = std::accumulate(frame_times.begin(), frame_times.end(), 0.0) / double(frame_times.size());
            const double med = median(frame_times);
            std::printf("frames: %zu at %ux%u, frame time mean %.2f ms, median %.2f ms, %.1f fps (median)\n",
                        frame_times.size(), swapchain.extent().width, swapchain.extent().height, mean, med,
                        med > 0.0 ? 1000.0 / med : 0.0);
            const double n = double(frame_times.size());
            std::printf("mean per frame: render %.2f ms (host extraction %.2f, chain %.2f, visibility %.2f, coherence %.2f), "
                        "present %.2f ms\n",
                        sums.render / n, sums.extract / n, sums.chain / n, sums.visibility / n, sums.coherence / n,
                        sums.present / n);
            for (const PassTime& t : sums.gpu)
                if (t.ms >= 0.0) std::printf("  GPU %s: %.3f ms\n", t.name.c_str(), t.ms / n);
        }
    }  // GPU objects destroyed

    return exit_code_after_validation(ctx, validation);
}

}  // namespace

Runner add_view_command(CLI::App& app) {
    auto o = std::make_shared<ViewOptions>();
    CLI::App* cmd = app.add_subcommand(
        "view",
        "Open a window on a scene file or a glTF model: orbit (left drag), pan (right drag), zoom (wheel);\n"
        "keys and a panel switch line types, thresholds, styles and the animation (README \"linework view\").");
    cmd->add_option("input", o->input, "Scene file (.json) or model (.gltf/.glb)")->required();
    cmd->add_option("--device", o->device, "auto, cpu, gpu, or an index from `linework devices`")->capture_default_str();
    cmd->add_option("--compute", o->compute, kComputeSiteHelp)->capture_default_str();
    cmd->add_option("--size", o->size, "Window size WxH (default: the scene's, else 960x720)");
    cmd->add_option("--slam", o->slam, "Draw silhouettes and suggestive contours as strokes textured by this SLAM (.exr)");
    cmd->add_option("--stroke-width", o->stroke_width, "Width of SLAM strokes in pixels (default 6)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--param", o->param, "Stroke parameterization: coherent (default), arclength or stretch")
        ->check(CLI::IsMember({"coherent", "arclength", "stretch"}));
    cmd->add_option("--splat-radius", o->splat_radius, "δ of the parameterization sprites, pixels (default 2 × spacing)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--script", o->script,
                    "Replay commands from FILE, one a line: wait N, orbit DX DY, zoom F, pan DX DY, key NAME, "
                    "resize W H, minimize, restore, screenshot PATH.png, save PATH.json, quit");
    cmd->add_option("--benchmark", o->benchmark,
                    "Render N frames (after 10 warm-up frames) of a slow orbit without vsync, print the frame "
                    "time and fps, exit");
    cmd->add_option("--subdivide", o->subdivide, "Midpoint subdivisions of the model (each ×4 triangles; benchmarks)");
    cmd->add_option("-o,--output", o->output, "Folder of screenshots (F12) and saved views (F5)")->capture_default_str();
    cmd->add_flag("--no-vsync", o->no_vsync, "Present without waiting for the display (mailbox or immediate)");
    cmd->add_flag("--no-panel", o->no_panel, "Start with the panel hidden (F1 shows it)");
    cmd->add_flag("--validation", o->validation,
                  "Enable the Khronos validation layer; any warning or error fails the run (also LINEWORK_VALIDATION=1)");
    return [o] { return run_view(*o); };
}

}  // namespace lw::cli
