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

// A path with `path`'s type, visibility, occlusion level and source and no samples: open
// unless `closed` (a piece of a path, or a path rebuilt from it).
inline ScreenPath empty_like(const ScreenPath& path, bool closed = false) {
    return ScreenPath{.type = path.type, .closed = closed, .visible = path.visible, .qi = path.qi, .source = path.source};
}

// The screen length of a loop's closing segment, from its last sample back to its first (0
// for an open path).
inline float closing_length(const ScreenPath& path) {
    const auto& s = path.samples;
    return path.closed && s.size() > 1 ? glm::length(s.front().pixel - s.back().pixel) : 0.0f;
}

// A closed loop opened at sample k: samples k … n−1, 0 … k (an open path of n + 1 samples),
// the wrapped ones' s continued past the loop length so that s stays increasing.
inline ScreenPath open_loop_at(const ScreenPath& path, size_t k) {
    const auto& s = path.samples;
    const size_t n = s.size();
    const float loop = s.back().s - s.front().s + closing_length(path);
    ScreenPath open = empty_like(path);
    open.samples.reserve(n + 1);
    for (size_t i = k; i < n; ++i) open.samples.push_back(s[i]);
    for (size_t i = 0; i <= k; ++i) {
        open.samples.push_back(s[i]);
        open.samples.back().s += loop;
    }
    return open;
}

// A loop as an open path from sample 0 round to a copy of it; an open path as it is.
inline ScreenPath opened(const ScreenPath& path) {
    return path.closed && path.samples.size() > 1 ? open_loop_at(path, 0) : path;
}

}  // namespace lw
