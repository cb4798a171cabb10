// engine/scene/style.h — how a scene is drawn, as plain data read from scene files.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "types/line_set.h"
#include "types/line_type.h"

namespace lw {

// Values match SHADING_* in shaders/surface_shared.glsl.
enum class Shading { Flat = 0, Toon = 1, Unlit = 2 };

struct SurfaceStyle {
    Shading shading = Shading::Toon;
    glm::vec3 color{0.82f, 0.84f, 0.88f};     // surface colour, 0..1 as written (sRGB), of faces without a material
    // The models' materials (scene key "materials"): glTF base colours and textures colour
    // the surface, MASK cuts holes lines show through, BLEND is composited (scene/material.h).
    // Off: every face takes `color` and is opaque.
    bool materials = true;
    glm::vec3 background{1.0f, 1.0f, 1.0f};
    // The background's alpha is 0: the frame is premultiplied RGBA over nothing (the lines
    // and strokes blend with `over`, so compositing it over a colour gives the render over
    // that colour), and PNGs are written with straight alpha.
    bool transparent = false;
    bool draw_surface = true;  // false: depth only, the surface takes the background colour
    // Samples per pixel of the surface pass (MSAA: 1, 4 or 8; scene key "samples"); 0: not
    // set, kDefaultSamples (the viewer takes 1 on a CPU device, where 4 costs ×2.2 a frame).
    // Lines and strokes are antialiased by their own coverage whatever this is.
    uint32_t samples = 0;
};

constexpr uint32_t kDefaultSamples = 4;
inline uint32_t surface_samples(const SurfaceStyle& style) { return style.samples ? style.samples : kDefaultSamples; }

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

// Everything about lines a scene file sets.
struct LinesDesc {
    bool enabled = true;  // extract and draw lines at all
    LineParams params;
    // Per LineType. rtsc's widths for its lines (ridges, valleys and principal highlights 2,
    // apparent ridges and suggestive highlights 2.5; highlights grey as rtsc draws them on
    // white); material boundaries as creases; intersections as wide as ridges, black.
    std::array<LineStyle, kLineTypeCount> styles{
        LineStyle{2.5f, glm::vec3(0.0f), "", 0.0f},  LineStyle{2.5f, glm::vec3(0.0f), "", 0.0f},
        LineStyle{1.5f, glm::vec3(0.15f), "", 0.0f}, LineStyle{1.5f, glm::vec3(0.15f), "", 0.0f},
        LineStyle{2.0f, glm::vec3(0.0f), "", 0.0f},  LineStyle{2.0f, glm::vec3(0.0f), "", 0.0f},
        LineStyle{2.5f, glm::vec3(0.0f), "", 0.0f},  LineStyle{2.5f, glm::vec3(0.3f), "", 0.0f},
        LineStyle{2.0f, glm::vec3(0.0f), "", 0.0f},  LineStyle{1.5f, glm::vec3(0.15f), "", 0.0f},
        LineStyle{2.0f, glm::vec3(0.0f), "", 0.0f}};
    HiddenLines hidden = HiddenLines::None;
    // With hidden lines drawn: only those behind at most this many surfaces (0: all). Counts
    // them exactly (lines/occlusion.h): 1 shows the first hidden level only.
    uint32_t hidden_levels = 0;
    float sample_spacing_px = 2.0f;  // δ of the visibility stage
    // "line_sets" of the scene file, drawn in order. Empty: `styles` and `params` are the
    // per-type shorthand, one set per type (render/line_sets.h, effective_line_sets).
    std::vector<LineSetDesc> sets;
    float length_scale = 0.0f;  // κ of the shorthand's sets (0: square texels)
};

}  // namespace lw
