// engine/stroke/stroke_geometry.h — textured quads along screen paths.
//
// Input:  visible `ScreenPath`s, the parameterization of each (T(s) = ρs + φ and its SLAM
//         fold), and a width, colour and taper per path.
// Output: a triangle list of `StrokeVertex`: two vertices per sample (left and right of the
//         path), consecutive samples joined without cracks. Joins are mitred along the
//         bisector of the two segments, the mitre clamped to `mitre_limit` half widths so
//         that sharp turns do not spike; ends taper linearly over `taper_px`.
// Texture coordinates: u = fold.scale · T(s) along (periods of the sampled level), v across
// (0 left … 1 right), w = the level coordinate 2l − 1.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "lines/visibility.h"
#include "stroke/slam_level.h"

namespace lw {

struct StrokeVertex {
    glm::vec2 pixel;
    glm::vec3 tex;    // u, v, w
    glm::vec4 color;  // rgb, alpha (the path's fade alpha)
};

struct StrokeParams {
    float rho = 0.0f, phi = 0.0f;
    SlamFold fold;
    float width = 2.0f;
    glm::vec3 color{0.0f};
    float taper_px = 0.0f;     // 0: no taper
    float mitre_limit = 2.0f;  // in half widths
};

void append_stroke(const ScreenPath& path, const StrokeParams& params, std::vector<StrokeVertex>& out);

}  // namespace lw
