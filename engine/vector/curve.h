// engine/vector/curve.h — a 2D curve read from a file, parameterized by arc length: what a
// ribbon pattern follows (`linework ribbon --curve`), what a stroke pattern fills
// (`linework pattern --path/--region`) and what hatching runs along (`linework hatch --along`).
//
// Input:  a polyline in output pixels (x right, y down), open or closed, from
//         - JSON: {"points": [[x, y], ...], "closed": bool}  ("closed" optional, default false;
//           any other key is an error naming it), or
//         - SVG: one drawn element, read as the stroke reader reads a drawing
//           (vector/svg_reader.cpp: groups, transforms, <use>, a <path> of commands
//           M/L/H/V/C/S/Q/T/Z and their relative forms with Béziers flattened to pieces under
//           1 px of chord, or a basic shape), paint aside, hidden elements and text left out,
//           and the root's viewBox mapped onto its width and height (the page a renderer
//           draws); a file of several curves (elements or subpaths) or none is an error.
// Output: `Curve2D`; `ArclengthCurve` evaluates C(x), x ∈ [0, L], and the unit tangent, as
//         the paper assumes (Zhou et al. 2013, §1.1: "a curve parameterized in arc length").
//
// Errors are `lw::Error`s (exit code 1) whose message starts with the file name.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

struct Curve2D {
    std::vector<glm::vec2> points;
    bool closed = false;  // the last point connects back to the first
    glm::vec2 page{0.0f};  // an SVG's page (width, height) the curve was drawn on; 0: none (JSON)
};

// Reads a .json or .svg curve (chosen by extension; anything else is read as JSON).
[[nodiscard]] Curve2D load_curve(const std::filesystem::path& path);
// The same from text; `where` names the source in error messages.
[[nodiscard]] Curve2D parse_curve_json(const std::string& text, const std::string& where);
[[nodiscard]] Curve2D parse_curve_svg(const std::string& svg_text, const std::string& where);  // svg_reader.cpp
// Parses one SVG path's `d` attribute that holds exactly one subpath.
[[nodiscard]] Curve2D parse_svg_path_data(const std::string& d, const std::string& where);
// Every subpath of a `d` attribute (M starts one; Z closes it; drawing on after Z starts a new
// one at the same point, as SVG does). Also used by the stroke reader (vector/stroke_io.h).
// `stretch`: the largest factor a transform applied afterwards stretches lengths by, so that
// curves are flattened to ~1 px chords in the output (the SVG stroke reader's transforms).
[[nodiscard]] std::vector<Curve2D> parse_svg_subpaths(const std::string& d, const std::string& where,
                                                      double stretch = 1.0);

class ArclengthCurve {
public:
    // Drops consecutive duplicate points (and a closing point equal to the first);
    // throws lw::Error when fewer than two distinct points remain.
    explicit ArclengthCurve(const Curve2D& curve);

    float length() const { return length_; }
    bool closed() const { return closed_; }
    const std::vector<glm::vec2>& points() const { return points_; }

    // C(x): open curves clamp x to [0, L]; closed curves wrap it.
    glm::vec2 point_at(float x) const;
    // Unit tangent at x from the chord C(x + h) − C(x − h): on a circle the chord is the exact
    // tangent, and at a polyline corner it is the bisector.
    glm::vec2 tangent_at(float x, float h) const;

private:
    std::vector<glm::vec2> points_;
    std::vector<double> cumulative_;  // arc length at each point; closed: one more for the closing segment
    float length_ = 0.0f;
    bool closed_ = false;
};

// Points every `spacing` px of arc length (the last spacing shortened so that both ends are
// kept on an open curve; a closed curve gets round(L / spacing) evenly spaced points).
[[nodiscard]] std::vector<glm::vec2> resample_arclength(const ArclengthCurve& curve, float spacing);

}  // namespace lw
