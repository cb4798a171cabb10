// tools/linework/view_panel.cpp — the viewer's camera, keys and Dear ImGui panel.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include "view_state.h"

namespace lw::cli {

OrbitCamera OrbitCamera::from(const ViewCamera& c) {
    OrbitCamera o;
    o.target = c.target;
    o.offset = c.eye - c.target;
    o.up = glm::length(c.up) > 0.0f ? glm::normalize(c.up) : glm::vec3(0.0f, 1.0f, 0.0f);
    o.fov_deg = c.fov_deg;
    o.znear = c.znear;
    o.zfar = c.zfar;
    o.min_distance = 1e-4f * glm::length(o.offset);
    o.max_distance = 1e4f * glm::length(o.offset);
    return o;
}

ViewCamera OrbitCamera::view() const {
    return ViewCamera{.eye = target + offset, .target = target, .up = up, .fov_deg = fov_deg, .znear = znear, .zfar = zfar};
}

void OrbitCamera::orbit(float dx_deg, float dy_deg) {
    offset = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(dx_deg), up) * glm::vec4(offset, 0.0f));
    const glm::vec3 right = glm::cross(-offset, up);
    if (glm::length(right) < 1e-8f) return;
    const glm::vec3 turned =
        glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(-dy_deg), glm::normalize(right)) * glm::vec4(offset, 0.0f));
    // Not over the pole: the eye stays at least 1° from the up axis.
    const float cos_to_up = glm::dot(glm::normalize(turned), up);
    if (std::abs(cos_to_up) < std::cos(glm::radians(1.0f))) offset = turned;
}

void OrbitCamera::zoom(float factor) {
    if (!(factor > 0.0f)) return;
    const float distance = glm::length(offset);
    offset *= std::clamp(distance / factor, min_distance, max_distance) / distance;
}

void OrbitCamera::pan(float dx_px, float dy_px, float height) {
    const float distance = glm::length(offset);
    const float px = 2.0f * distance * std::tan(glm::radians(fov_deg) * 0.5f) / std::max(height, 1.0f);
    const glm::vec3 forward = glm::normalize(-offset);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const glm::vec3 screen_up = glm::cross(right, forward);
    const glm::vec3 move = (-dx_px * right + dy_px * screen_up) * px;  // the scene follows the mouse
    target += move;
}

namespace {

void toggle_type(LineParams& p, LineType type) { set_line_type_enabled(p, type, !line_type_enabled(p, type)); }

void toggle_strokes(ViewerState& s, size_t set) {
    if (set >= s.has_slam.size() || !s.has_slam[set]) {
        s.message = set < s.set_names.size() ? "no SLAM for " + s.set_names[set] + " (--slam or the scene's \"slam\")"
                                             : "no line set " + std::to_string(set + 1);
        return;
    }
    s.strokes[set] = !s.strokes[set];
    s.slams_changed = true;
}

// A line set's switch: the shorthand's is its type's, an explicit set's its "enabled".
bool* set_switch(LinesDesc& lines, size_t set) {
    if (!lines.sets.empty()) return &lines.sets[set].enabled;
    return set < size_t(kLineTypeCount) ? line_type_switch(lines.params, LineType(set)) : nullptr;
}

void line_set_controls(ViewerState& s, size_t i) {
    LinesDesc& lines = s.desc.lines;
    const bool shorthand = lines.sets.empty();
    float* width = shorthand ? &lines.styles[i].width : &lines.sets[i].style.width;
    float* color = shorthand ? &lines.styles[i].color.x : &lines.sets[i].style.color.x;
    ImGui::PushID(int(i));
    ImGui::Checkbox(s.set_names[i].c_str(), set_switch(lines, i));
    if (s.ribbon[i]) {
        ImGui::SameLine();
        ImGui::TextDisabled("ribbon: offline speed");
    }
    ImGui::SliderFloat("width", width, 0.5f, 16.0f, "%.1f px");
    ImGui::ColorEdit3("colour", color, ImGuiColorEditFlags_NoInputs);
    if (s.has_slam[i]) {
        ImGui::SameLine();
        bool on = s.strokes[i];
        if (ImGui::Checkbox("SLAM strokes", &on)) {
            s.strokes[i] = on;
            s.slams_changed = true;
        }
        if (shorthand) ImGui::SliderFloat("taper", &lines.styles[i].taper_px, 0.0f, 64.0f, "%.0f px");
    }
    ImGui::PopID();
}

void step_time(ViewerState& s, float frames) {
    if (!s.animated) return;
    s.playing = false;
    s.time_s = std::clamp(s.time_s + frames / s.fps, 0.0f, s.duration_s);
    s.time_changed = true;
}

}  // namespace

bool apply_key(ViewerState& s, int key) {
    LineParams& p = s.desc.lines.params;
    // The per-type keys switch the "lines" shorthand; with line sets they would flip switches
    // the sets do not read (and a saved view would carry them): said instead.
    const bool type_key = key == GLFW_KEY_L || key == GLFW_KEY_S || key == GLFW_KEY_C || key == GLFW_KEY_B ||
                          key == GLFW_KEY_H;
    if (type_key && !s.desc.lines.sets.empty()) {
        s.message = "this scene's line sets choose their types and hidden lines: switch the sets in the panel (F1)";
        std::printf("%s\n", s.message.c_str());
        return true;
    }
    switch (key) {
        case GLFW_KEY_L: toggle_type(p, LineType::Silhouette); break;
        case GLFW_KEY_S: toggle_type(p, LineType::Suggestive); break;
        case GLFW_KEY_C: toggle_type(p, LineType::Crease); break;
        case GLFW_KEY_B: toggle_type(p, LineType::Border); break;
        case GLFW_KEY_1: case GLFW_KEY_2: case GLFW_KEY_3: case GLFW_KEY_4: toggle_strokes(s, size_t(key - GLFW_KEY_1)); break;
        case GLFW_KEY_P:
            s.coherence.policy = ParamPolicy((int(s.coherence.policy) + 1) % 3);
            s.message = std::string("parameterization: ") + param_policy_name(s.coherence.policy);
            break;
        case GLFW_KEY_T: {
            SurfaceStyle& st = s.desc.style;
            if (!st.draw_surface) {
                st.draw_surface = true;
                st.shading = Shading::Toon;
            } else if (st.shading == Shading::Toon) {
                st.shading = Shading::Flat;
            } else if (st.shading == Shading::Flat) {
                st.shading = Shading::Unlit;
            } else {
                st.draw_surface = false;
            }
            break;
        }
        case GLFW_KEY_H: s.desc.lines.hidden = HiddenLines((int(s.desc.lines.hidden) + 1) % 3); break;
        case GLFW_KEY_R: s.camera = s.home; break;
        case GLFW_KEY_Q: case GLFW_KEY_ESCAPE: s.quit = true; break;
        case GLFW_KEY_SPACE:
            if (s.animated) s.playing = !s.playing;
            break;
        case GLFW_KEY_LEFT_BRACKET: step_time(s, -1.0f); break;
        case GLFW_KEY_RIGHT_BRACKET: step_time(s, 1.0f); break;
        case GLFW_KEY_LEFT: s.camera.orbit(-5.0f, 0.0f); break;
        case GLFW_KEY_RIGHT: s.camera.orbit(5.0f, 0.0f); break;
        case GLFW_KEY_UP: s.camera.orbit(0.0f, 5.0f); break;
        case GLFW_KEY_DOWN: s.camera.orbit(0.0f, -5.0f); break;
        case GLFW_KEY_EQUAL: s.camera.zoom(1.1f); break;
        case GLFW_KEY_MINUS: s.camera.zoom(1.0f / 1.1f); break;
        case GLFW_KEY_F1: s.panel = !s.panel; break;
        case GLFW_KEY_F5: s.save_path = kNumberedFile; break;
        case GLFW_KEY_F12: s.screenshot_path = kNumberedFile; break;
        default: return false;
    }
    return true;
}

void draw_panel(ViewerState& s) {
    if (!s.panel) return;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("linework (F1 hides)");
    ImGui::Text("%s", s.device.c_str());
    ImGui::Text("frame %.1f ms (%.1f fps), render %.1f, present %.1f", s.frame_ms, s.frame_ms > 0 ? 1000.0 / s.frame_ms : 0.0,
                s.render_ms, s.present_ms);
    if (!s.history.empty()) {
        std::vector<float> h(s.history.begin(), s.history.end());
        ImGui::PlotLines("##frametimes", h.data(), int(h.size()), 0, "frame ms", 0.0f, 100.0f, ImVec2(0, 40));
    }
    if (ImGui::TreeNodeEx("GPU time per pass", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const PassTime& t : s.gpu)
            if (t.ms >= 0.0)
                ImGui::Text("%-14s %7.3f ms", t.name.c_str(), t.ms);
            else
                ImGui::Text("%-14s (no timestamps)", t.name.c_str());
        ImGui::TreePop();
    }
    if (ImGui::TreeNodeEx("Host time per stage", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (s.host_compute) ImGui::Text("%-14s %7.3f ms", "extraction", s.extract_ms);
        ImGui::Text("%-14s %7.3f ms", "chaining", s.chain_ms);
        ImGui::Text("%-14s %7.3f ms", "visibility", s.visibility_ms);
        ImGui::Text("%-14s %7.3f ms", "coherence", s.coherence_ms);
        ImGui::TreePop();
    }
    ImGui::Text("%zu triangles, %zu paths", s.triangles, s.paths);

    LinesDesc& lines = s.desc.lines;
    if (ImGui::CollapsingHeader("Lines", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (lines.sets.empty()) {  // the shorthand's sets are the types (explicit sets: below)
            ImGui::Checkbox("silhouettes (l)", &lines.params.silhouettes);
            ImGui::SameLine(170);
            ImGui::Checkbox("suggestive (s)", &lines.params.suggestive);
            ImGui::Checkbox("creases (c)", &lines.params.creases);
            ImGui::SameLine(170);
            ImGui::Checkbox("borders (b)", &lines.params.borders);
            // rtsc's other lines (off by default, as in rtsc).
            ImGui::Checkbox("ridges", &lines.params.ridges);
            ImGui::SameLine(170);
            ImGui::Checkbox("valleys", &lines.params.valleys);
            ImGui::Checkbox("apparent ridges", &lines.params.apparent_ridges);
            ImGui::Checkbox("sugg. highlights", &lines.params.suggestive_highlights);
            ImGui::SameLine(170);
            ImGui::Checkbox("princ. highlights", &lines.params.principal_highlights);
            ImGui::Checkbox("material boundaries", &lines.params.material_boundaries);
            ImGui::SameLine(170);
            ImGui::Checkbox("intersections", &lines.params.intersections);
        }
        ImGui::SliderFloat("suggestive thr.", &lines.params.sug_thresh, 0.0f, 0.2f, "%.3f");
        if (lines.params.ridges || lines.params.valleys)
            ImGui::SliderFloat("ridge/valley thr.", &lines.params.rv_thresh, 0.0f, 1.0f, "%.3f");
        if (lines.params.apparent_ridges) ImGui::SliderFloat("apparent ridge thr.", &lines.params.ar_thresh, 0.0f, 1.0f, "%.3f");
        if (lines.params.suggestive_highlights)
            ImGui::SliderFloat("sugg. highlight thr.", &lines.params.sh_thresh, 0.0f, 0.2f, "%.3f");
        if (lines.params.principal_highlights)
            ImGui::SliderFloat("princ. highlight thr.", &lines.params.ph_thresh, 0.0f, 0.4f, "%.3f");
        ImGui::SliderFloat("crease angle", &lines.params.crease_angle_deg, 1.0f, 179.0f, "%.0f°");
        if (ImGui::IsItemDeactivatedAfterEdit()) s.crease_changed = true;
        ImGui::SliderFloat("sample spacing px", &lines.sample_spacing_px, 0.5f, 16.0f, "%.1f");
        if (!lines.sets.empty()) {
            ImGui::TextDisabled("hidden lines: each line set's own");
        } else {
            int hidden = int(lines.hidden);
            if (ImGui::Combo("hidden (h)", &hidden, "none\0dashed\0faint\0")) lines.hidden = HiddenLines(hidden);
            if (lines.hidden != HiddenLines::None) {
                // Levels are counted by a ray per hidden sample (lines/occlusion.h): tens of ms a frame.
                int levels = int(lines.hidden_levels);
                if (ImGui::SliderInt("hidden levels (0: all)", &levels, 0, 8)) lines.hidden_levels = uint32_t(levels);
            }
        }
    }
    if (ImGui::CollapsingHeader("Strokes", ImGuiTreeNodeFlags_DefaultOpen)) {
        int policy = int(s.coherence.policy);
        if (ImGui::Combo("policy (p)", &policy, "coherent\0arclength\0stretch\0")) s.coherence.policy = ParamPolicy(policy);
        ImGui::SliderFloat("splat radius", &s.coherence.splat_radius_px, 0.5f, 32.0f, "%.1f px");
    }
    if (ImGui::CollapsingHeader("Line sets (drawn in order)", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (size_t i = 0; i < s.set_names.size(); ++i) line_set_controls(s, i);
    }
    if (ImGui::CollapsingHeader("Surface")) {
        int shading = s.desc.style.draw_surface ? int(s.desc.style.shading) : 3;
        if (ImGui::Combo("shading (t)", &shading, "flat\0toon\0unlit\0none\0")) {
            s.desc.style.draw_surface = shading != 3;
            if (shading != 3) s.desc.style.shading = Shading(shading);
        }
        ImGui::Checkbox("materials", &s.desc.style.materials);
        ImGui::SameLine();
        ImGui::ColorEdit3("surface", &s.desc.style.color.x, ImGuiColorEditFlags_NoInputs);
        ImGui::SameLine();
        ImGui::ColorEdit3("background", &s.desc.style.background.x, ImGuiColorEditFlags_NoInputs);
        // 1 and 4 are the counts every Vulkan device renders (8: the scene key or --samples).
        int msaa = surface_samples(s.desc.style) == 1 ? 0 : 1;
        if (surface_samples(s.desc.style) != 8 && ImGui::Combo("samples", &msaa, "1 (fastest)\0" "4 (antialiased)\0"))
            s.desc.style.samples = msaa == 0 ? 1u : 4u;
    }
    if (s.animated && ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::Button(s.playing ? "pause (space)" : "play (space)")) s.playing = !s.playing;
        if (ImGui::SliderFloat("time", &s.time_s, 0.0f, s.duration_s, "%.2f s")) {
            s.playing = false;
            s.time_changed = true;
        }
    }
    if (ImGui::Button("screenshot (F12)")) s.screenshot_path = kNumberedFile;
    ImGui::SameLine();
    if (ImGui::Button("save view (F5)")) s.save_path = kNumberedFile;
    ImGui::SameLine();
    if (ImGui::Button("reset camera (r)")) s.camera = s.home;
    if (!s.message.empty()) ImGui::TextWrapped("%s", s.message.c_str());
    ImGui::End();
}

}  // namespace lw::cli
