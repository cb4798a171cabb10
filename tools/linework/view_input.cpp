#include "view_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>

#include <GLFW/glfw3.h>

#include "core/error.h"
#include "io/image_io.h"
#include "view_keys.h"

namespace lw::cli {

namespace {

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

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The next numbered file (F12, F5, the panel's buttons) from `next` on that is not there yet:
// a second viewer session in the same folder goes on after the first's files instead of
// writing over them. Files the script names take no number.
std::string numbered(const std::string& dir, const char* stem, int& next, const char* ext) {
    for (;; ++next) {
        char name[64];
        std::snprintf(name, sizeof name, "%s_%04d.%s", stem, next, ext);
        const std::filesystem::path path = std::filesystem::path(dir) / name;
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            ++next;
            return path.string();
        }
    }
}

}  // namespace

void save_view_file(ViewerState& s, VkExtent2D extent) {
    const std::string path =
        s.save_path == kNumberedFile ? numbered(s.output_dir, "linework_view", s.next_save, "json") : s.save_path;
    SceneDesc saved = s.desc;
    saved.width = int(extent.width);
    saved.height = int(extent.height);
    // A set whose SLAM strokes are switched off is saved without its SLAM, as it is drawn.
    for (size_t i = 0; i < s.strokes.size() && i < s.has_slam.size(); ++i) {
        if (!s.has_slam[i] || s.strokes[i]) continue;
        if (saved.lines.sets.empty()) saved.lines.styles[i].slam.clear();
        else if (i < saved.lines.sets.size()) saved.lines.sets[i].style.slam.clear();
    }
    // The parameterization on screen (the panel's policy and splat radius, or the flags'),
    // where it is not what the saved scene would give anyway.
    const SessionOptions would_be = default_session_options(saved);
    if (s.coherence.policy != would_be.coherence.policy || saved.coherence.policy)
        saved.coherence.policy = s.coherence.policy;
    if (s.coherence.splat_radius_px != would_be.coherence.splat_radius_px)
        saved.coherence.splat_radius_px = s.coherence.splat_radius_px;
    std::ofstream out(path, std::ios::binary);
    out << scene_json(saved, s.camera.view(), std::filesystem::path(path).parent_path());
    if (!out.flush()) throw Error(path + ": cannot write");
    s.message = "wrote " + path;
    // What the file cannot hold, said: the frame of an animation on screen (the file keeps
    // the scene's range).
    if (s.animated)
        s.message += " (frame " + std::to_string(int(std::lround(s.time_s * s.fps))) +
                     " is on screen: linework render " + path + " --frames N:N draws it)";
    std::printf("%s\n", s.message.c_str());
    s.save_path.clear();
}

void write_screenshot(ViewerState& s, const ImageRGBA8& shot) {
    const std::string path =
        s.screenshot_path == kNumberedFile ? numbered(s.output_dir, "linework_view", s.next_screenshot, "png") : s.screenshot_path;
    write_png(path, shot);
    s.message = "wrote " + path;
    std::printf("%s\n", s.message.c_str());
    s.screenshot_path.clear();
}

void install_callbacks(Window& window, Input& input) {
    glfwSetWindowUserPointer(window.get(), &input);
    glfwSetKeyCallback(window.get(), &on_key);
    glfwSetScrollCallback(window.get(), &on_scroll);
    glfwGetCursorPos(window.get(), &input.last_mouse.x, &input.last_mouse.y);
}

void handle_mouse(Window& window, const UiOverlay& ui, Input& input, float height) {
    ViewerState& s = *input.state;
    glm::dvec2 mouse;
    glfwGetCursorPos(window.get(), &mouse.x, &mouse.y);
    const glm::dvec2 delta = mouse - input.last_mouse;
    input.last_mouse = mouse;
    if (!ui.wants_mouse()) {
        const bool left = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        const bool shift = glfwGetKey(window.get(), GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
        const bool pan = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                         glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS || (left && shift);
        if (pan && (delta.x != 0.0 || delta.y != 0.0))
            s.camera.pan(float(delta.x), float(delta.y), height);
        else if (left && (delta.x != 0.0 || delta.y != 0.0))
            s.camera.orbit(-0.3f * float(delta.x), 0.3f * float(delta.y));
        if (input.scroll != 0.0) s.camera.zoom(float(std::pow(1.1, input.scroll)));
    }
    input.scroll = 0.0;
}

void play_script(ScriptPlayer& player, Window& window, Input& input, float height, const std::function<void()>& save_view) {
    ViewerState& s = *input.state;
    for (const ScriptCommand& c : player.next_frame()) switch (c.kind) {
            case ScriptCommand::Kind::Orbit: s.camera.orbit(c.a, c.b); break;
            case ScriptCommand::Kind::Zoom: s.camera.zoom(c.a); break;
            case ScriptCommand::Kind::Pan: s.camera.pan(c.a, c.b, height); break;
            case ScriptCommand::Kind::Key: apply_key(s, key_from_name(c.text)); break;
            case ScriptCommand::Kind::Resize: glfwSetWindowSize(window.get(), int(c.a), int(c.b)); break;
            case ScriptCommand::Kind::Minimize:
                glfwIconifyWindow(window.get());
                input.script_minimized = true;
                break;
            case ScriptCommand::Kind::Restore:
                glfwRestoreWindow(window.get());
                input.script_minimized = false;
                break;
            case ScriptCommand::Kind::Screenshot: s.screenshot_path = c.text; break;
            case ScriptCommand::Kind::Save:
                s.save_path = c.text;
                save_view();
                break;
            case ScriptCommand::Kind::Quit: s.quit = true; break;
            case ScriptCommand::Kind::Wait: break;
        }
}

void ViewStats::add(const ViewerState& s, const FrameTimings& timings) {
    frame_ms.push_back(s.frame_ms);
    render += s.render_ms;
    present += s.present_ms;
    extract += timings.extract_ms;
    chain += timings.chain_ms;
    visibility += timings.visibility_ms;
    coherence += timings.coherence_ms;
    if (gpu.size() != s.gpu.size()) {  // the passes of the first timed frame
        gpu = s.gpu;
        for (PassTime& t : gpu) t.ms = 0.0;
    }
    for (size_t i = 0; i < gpu.size(); ++i) gpu[i].ms += s.gpu[i].ms;
}

void ViewStats::print(uint32_t width, uint32_t height) const {
    if (frame_ms.empty()) return;
    const double n = double(frame_ms.size());
    const double mean = std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0) / n;
    const double med = median(frame_ms);
    std::printf("frames: %zu at %ux%u, frame time mean %.2f ms, median %.2f ms, %.1f fps (median)\n", frame_ms.size(),
                width, height, mean, med, med > 0.0 ? 1000.0 / med : 0.0);
    std::printf("mean per frame: render %.2f ms (host extraction %.2f, chain %.2f, visibility %.2f, coherence %.2f), "
                "present %.2f ms\n",
                render / n, extract / n, chain / n, visibility / n, coherence / n, present / n);
    for (const PassTime& t : gpu)
        if (t.ms >= 0.0) std::printf("  GPU %s: %.3f ms\n", t.name.c_str(), t.ms / n);
}

ViewerState initial_state(const SceneSession& session, bool panel, const std::string& output_dir) {
    ViewerState s;
    s.desc = session.desc();
    for (size_t i = 0; i < session.line_sets().size(); ++i) {
        s.set_names.push_back(session.line_sets()[i].name);
        s.has_slam.push_back(session.line_set_has_slam(i));
        s.strokes.push_back(session.line_set_has_slam(i));
        s.ribbon.push_back(!session.line_sets()[i].style.ribbon.empty());
    }
    s.camera = s.home = OrbitCamera::from(session.scene().camera);
    s.animated = session.animated();
    s.duration_s = s.animated ? session.duration_s() : 0.0f;
    s.fps = s.desc.animation.fps;
    s.playing = s.animated;
    s.panel = panel;
    s.output_dir = output_dir;
    s.triangles = session.scene().mesh.triangle_count();
    return s;
}

// The panel's edits reach the session before the frame.
void apply_edits(ViewerState& s, SceneSession& session) {
    session.lines() = s.desc.lines;
    session.surface() = s.desc.style;
    session.coherence().policy = s.coherence.policy;
    session.coherence().splat_radius_px = s.coherence.splat_radius_px;
    if (s.crease_changed) session.rebuild_lines();
    if (s.slams_changed)
        for (size_t i = 0; i < s.strokes.size(); ++i) session.set_line_set_textured(i, s.strokes[i]);
    s.crease_changed = s.slams_changed = false;
}

}  // namespace lw::cli
