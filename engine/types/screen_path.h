// engine/types/screen_path.h — a brush path as the screen sees it: what the visibility stage
// makes and every later stage (coherence, strokes, line sets, layers, ribbons, dumps) reads.
//
// A `ScreenPath` is one run of equal visibility of a chained path, resampled every δ pixels
// of screen arc length; vector layers make them from 2D strokes too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "types/line_type.h"

namespace lw {

struct ScreenSample {
    glm::vec2 pixel;     // x right, y down
    float depth;         // eye depth (distance along the view axis)
    float s;             // screen arc length from the path's start, pixels
    glm::vec3 position;  // world
    uint32_t face;       // of the nearest path vertex
    glm::vec3 bary;
    float alpha;         // the fade alpha of the line (suggestive contours fade in)
    float width = 1.0f;  // stroke width multiplier: the per-point widths of vector strokes
    uint32_t other_face = kNoFace;  // intersection lines: the other surface's face (the
                                    // line lies on both, and belongs to both's models)
};

struct ScreenPath {
    LineType type = LineType::Silhouette;
    bool closed = false;   // a whole loop, entirely visible
    bool visible = true;
    // Occlusion level: 0 when visible; when hidden, the number of surfaces in front where
    // the visibility stage was asked to count them (lines/occlusion.h), else 1 (at least one).
    uint32_t qi = 0;
    size_t source = 0;     // index of the LinePath it came from
    std::vector<ScreenSample> samples;
};

}  // namespace lw
