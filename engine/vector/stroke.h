// engine/vector/stroke.h — 2D strokes: what the stroke-pattern and hatching synthesizers read
// and write, and what vector-art layers draw.
//
// A stroke is a polyline (x right, y down, in drawing units: output pixels unless a layer
// scales it) with one width per point and one colour (RGB in [0, 1], as written in the file).
// A `StrokeSet` is a drawing: strokes in drawing order, plus the drawing's extent when the
// file states one (SVG viewBox, JSON "size").
//
// Files (engine/vector/stroke_io.cpp):
//   JSON  {"size": [w, h], "strokes": [{"points": [[x, y], ...], "width": w | "widths": [...],
//          "color": [r, g, b] | "#rrggbb", "closed": bool}, ...]}
//   SVG   through pugixml (vector/svg_reader.cpp): <path d> (each subpath one stroke),
//         <polyline>, <polygon>, <line>, <rect>, <circle>, <ellipse>; nested <g> with inherited
//         stroke and stroke-width (attributes or `style`), transforms, <use>, CSS units;
//         per-point widths in our own `data-widths` attribute (the writer's round trip).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

struct Stroke {
    std::vector<glm::vec2> points;
    std::vector<float> widths;  // one per point (same size as points)
    glm::vec3 color{0.0f};      // RGB in [0, 1]
    bool closed = false;        // the last point connects back to the first
};

struct StrokeSet {
    std::vector<Stroke> strokes;
    glm::vec2 origin{0.0f};  // the drawing's extent: [origin, origin + size]; size 0 = not stated
    glm::vec2 size{0.0f};
};

// A stroke of constant width.
[[nodiscard]] Stroke make_stroke(std::vector<glm::vec2> points, float width, glm::vec3 color, bool closed = false);

struct Box2 {
    glm::vec2 lo{0.0f}, hi{0.0f};
    glm::vec2 center() const { return 0.5f * (lo + hi); }
    glm::vec2 extent() const { return hi - lo; }
};
// Bounds of the stroke skeletons (widths not included); {0, 0} for an empty set.
[[nodiscard]] Box2 stroke_bounds(const std::vector<Stroke>& strokes);

// Polyline length (closing segment included for closed strokes).
[[nodiscard]] float stroke_length(const Stroke& s);
// Length-weighted mean width (the plain mean for a single point).
[[nodiscard]] float mean_width(const Stroke& s);

// p ↦ R(angle)·(p − pivot)·scale + pivot + offset, per point; widths scale with |scale| too.
void transform_stroke(Stroke& s, glm::vec2 pivot, float angle, glm::vec2 offset, float scale = 1.0f);

}  // namespace lw
