// engine/scene/style.h — how a scene is drawn, as plain data read from scene files.
#pragma once

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
};

enum class HiddenLines { None, Dashed, Faint };

}  // namespace lw
