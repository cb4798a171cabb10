// tools/linework/view_input.h — what moves the viewer: GLFW key and scroll callbacks, the
// mouse (orbit, pan, zoom), the replayed script (view_script.h), and the statistics of a
// --benchmark run.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gpu/timestamps.h"
#include "platform/ui_overlay.h"
#include "platform/window.h"
#include "render/frame_renderer.h"
#include "session/scene_session.h"
#include "view_script.h"
#include "view_state.h"

namespace lw::cli {

// What GLFW callbacks see (glfwSetWindowUserPointer).
struct Input {
    ViewerState* state = nullptr;
    bool ui_keyboard = false;  // ImGui has the keyboard: keys are not the viewer's
    double scroll = 0.0;
    glm::dvec2 last_mouse{0.0};
    bool script_minimized = false;  // without a window manager (Xvfb) iconify does nothing
};

// Installs the key and scroll callbacks on the window (before ImGui, which chains to them).
void install_callbacks(Window& window, Input& input);

// Left drag orbits, right or middle drag (or shift + left) pans, the wheel zooms.
void handle_mouse(Window& window, const UiOverlay& ui, Input& input, float height);

// This frame's script commands; `save_view` writes the scene file of the current view.
void play_script(ScriptPlayer& player, Window& window, Input& input, float height, const std::function<void()>& save_view);

// The viewer's state at start: the session's scene, sets and camera; the panel shown or not.
[[nodiscard]] ViewerState initial_state(const SceneSession& session, bool panel, const std::string& output_dir);
// The panel's edits reach the session before the frame.
void apply_edits(ViewerState& s, SceneSession& session);

// The current view as a scene file (F5, the panel, the script's `save`): s.save_path, or a
// numbered file in the output folder for kNumberedFile.
void save_view_file(ViewerState& s, VkExtent2D extent);
// A screenshot to s.screenshot_path (or a numbered file for kNumberedFile).
void write_screenshot(ViewerState& s, const ImageRGBA8& shot);

// Frame times and per-stage sums over the timed frames of --benchmark.
struct ViewStats {
    std::vector<double> frame_ms;
    double render = 0, present = 0, extract = 0, chain = 0, visibility = 0, coherence = 0;
    std::vector<PassTime> gpu;
    void add(const ViewerState& s, const FrameTimings& timings);
    void print(uint32_t width, uint32_t height) const;
};

}  // namespace lw::cli
