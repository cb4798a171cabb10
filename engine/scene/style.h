// engine/scene/style.h — how a scene is drawn, as plain data read from scene files.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace lw {

// Values match SHADING_* in shaders/surface_shared.glsl.
enum class Shading { Flat = 0, Toon = 1, Unlit = 2 };

struct SurfaceStyle {
    Shading shading = Shading::Toon;
    glm::vec3 color{0.82f, 0.84f, 0.88f};     // surface colour, linear 0..1
    glm::vec3 background{1.0f, 1.0f, 1.0f};
    bool draw_surface = true;  // false: depth only, the surface takes the background colour
};

}  // namespace lw

namespace lw {

// How one line type is drawn (width in pixels, linear colour 0..1).
struct LineStyle {
    float width = 2.0f;
    glm::vec3 color{0.0f};
    std::string slam;      // SLAM file: draw this type as textured strokes (empty: plain lines)
    float taper_px = 0.0f; // strokes: width tapers to the ends over this length
    std::string ribbon;    // ribbon exemplar (RGBA image): draw this type as a structured
                           // pattern along each path, `width` pixels wide (engine/ribbon)
    float ribbon_scale = 0.0f;  // exemplar pixels across the ribbon (0: the exemplar's default)
};

enum class HiddenLines { None, Dashed, Faint };

}  // namespace lw

namespace lw {

enum class LineType : uint32_t { Silhouette = 0, Suggestive = 1, Crease = 2, Border = 3 };
constexpr int kLineTypeCount = 4;

// "silhouette", "suggestive", "crease", "border": SVG group ids and scene-file keys.
inline const char* line_type_name(LineType type) {
    constexpr const char* names[kLineTypeCount] = {"silhouette", "suggestive", "crease", "border"};
    return names[static_cast<uint32_t>(type) % kLineTypeCount];
}

// Thresholds and switches of the feature-line extraction, as rtsc defines them
// (DESIGN.md "Line extraction as rtsc does it"; docs/research/rtsc-lines.md).
struct LineParams {
    bool silhouettes = true;
    bool suggestive = true;
    bool creases = true;
    bool borders = true;
    float sug_thresh = 0.01f;        // tanθ·DwKr threshold, scaled by 1 / feature_size²
    bool fade = true;                // fade suggestive contours in as the test grows
    float fade_thresh = 0.03f;       // alpha = t / (t + fade_thresh / fs²)
    float crease_angle_deg = 45.0f;  // creases where face normals turn by more than this
};

inline bool line_type_enabled(const LineParams& p, LineType type) {
    switch (type) {
        case LineType::Silhouette: return p.silhouettes;
        case LineType::Suggestive: return p.suggestive;
        case LineType::Crease: return p.creases;
        case LineType::Border: return p.borders;
    }
    return false;
}

inline void disable_line_type(LineParams& p, LineType type) {
    switch (type) {
        case LineType::Silhouette: p.silhouettes = false; break;
        case LineType::Suggestive: p.suggestive = false; break;
        case LineType::Crease: p.creases = false; break;
        case LineType::Border: p.borders = false; break;
    }
}

// Everything about lines a scene file sets.
struct LinesDesc {
    bool enabled = true;  // extract and draw lines at all
    LineParams params;
    std::array<LineStyle, kLineTypeCount> styles{
        LineStyle{2.5f, glm::vec3(0.0f), "", 0.0f}, LineStyle{2.5f, glm::vec3(0.0f), "", 0.0f},
        LineStyle{1.5f, glm::vec3(0.15f), "", 0.0f}, LineStyle{1.5f, glm::vec3(0.15f), "", 0.0f}};
    HiddenLines hidden = HiddenLines::None;
    float sample_spacing_px = 2.0f;  // δ of the visibility stage
};

}  // namespace lw
