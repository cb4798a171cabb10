// tools/linework/view_state.h — what `linework view` lets a person change, in one place.
//
// The render loop (view_command.cpp) reads it every frame; keys, the script and the ImGui
// panel (view_panel.cpp) change it. Changes that need more than the next frame's
// parameters (a crease angle: the line mesh is built again; a SLAM switched: the stroke
// pass) are flagged and applied by the loop between frames.
#pragma once

#include <array>
#include <cmath>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "coherence/coherence.h"
#include "gpu/timestamps.h"
#include "scene/scene.h"

namespace lw::cli {

// A camera turning about its target: the eye is target + offset.
struct OrbitCamera {
    glm::vec3 target{0.0f};
    glm::vec3 offset{0.0f, 0.0f, 5.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_deg = 40.0f;
    float znear = 0.0f, zfar = 0.0f;
    // How near and far zoom goes: 10^-4 and 10^4 times the first distance (a script's zoom 1e30
    // put the eye on the target, which ends the viewer with an error).
    float min_distance = 0.0f, max_distance = INFINITY;

    static OrbitCamera from(const ViewCamera& camera);
    [[nodiscard]] ViewCamera view() const;
    // DX > 0 moves the eye to the right about the up axis, DY > 0 moves it up (stops 1°
    // short of the poles).
    void orbit(float dx_deg, float dy_deg);
    void zoom(float factor);  // distance × 1 / factor
    // Moves eye and target by (dx, dy) pixels of an image `height` pixels high (right, down).
    void pan(float dx_px, float dy_px, float height);
};

// A screenshot or saved view asked for without a path (a key, the panel): the next numbered
// file in the output folder.
inline const std::string kNumberedFile = "*";

struct ViewerState {
    SceneDesc desc;                       // lines, styles and surface as edited
    OrbitCamera camera, home;             // home: `r` goes back to it
    CoherenceParams coherence;
    // Per line set (render/line_sets.h, effective_line_sets: for the per-type shorthand,
    // set i is line type i): its name, whether it has a SLAM, draws it, or is a ribbon
    // (synthesized on the host after readback: an offline-speed style).
    std::vector<std::string> set_names;
    std::vector<bool> has_slam, strokes, ribbon;
    bool slams_changed = true;
    bool crease_changed = false;          // rebuild the line mesh
    bool panel = true;
    bool quit = false;
    // Animation clock.
    bool animated = false;
    bool playing = false;
    float time_s = 0.0f, duration_s = 0.0f, fps = 24.0f;
    bool time_changed = false;
    // Requests the loop carries out after this frame is drawn: a path, or kNumberedFile.
    std::string screenshot_path, save_path;
    std::string output_dir = ".";
    int next_screenshot = 0, next_save = 0;  // where the numbered files' search starts
    // Statistics for the panel.
    double frame_ms = 0.0, render_ms = 0.0, present_ms = 0.0;
    std::vector<PassTime> gpu;
    double extract_ms = 0.0, chain_ms = 0.0, visibility_ms = 0.0, coherence_ms = 0.0;  // host stages
    bool host_compute = false;  // extraction, splat and RANSAC on the host (ComputeSite)
    size_t triangles = 0, paths = 0;
    std::string device;
    std::deque<float> history;            // recent frame times, ms
    std::string message;                  // last action ("wrote shot.png")
};

// The action of a key (GLFW key code); returns false for keys the viewer does not use.
bool apply_key(ViewerState& s, int key);

// The ImGui panel (view_panel.cpp); call between UiOverlay::begin_frame and end_frame.
void draw_panel(ViewerState& s);

}  // namespace lw::cli
