// engine/stroke/modifiers.h — a line set's style on the CPU: chaining options, geometry
// modifiers, dashes and per-sample attributes (Blender Freestyle's line-style model,
// types/line_set.h), then the stroke with caps and joins (stroke/stroke_geometry.h).
//
// Order for one line set (as Freestyle's: chaining → splitting → geometry → thickness,
// colour, alpha → stroke):
//   1. apply_chaining_options — before parameterization, on the selected runs;
//   2. apply_geometry_modifiers — on each parameterized path, in the set's order;
//   3. dash_path — pieces laid along the parameterization;
//   4. evaluate_attributes — width, alpha and colour per sample of each piece;
//   5. append_stroke (attributes, caps, joins).
// append_styled_stroke does 2–5 for one path.
//
// The coherent parameter in pixels. Everything that should stick to the surface while the
// view moves (sinus, noise, dashes) is a function of
//     x = (ρ·s + φ) · period_px,   period_px = Lmax / κ (one texture period in pixels),
// never of the frame's pixels: in a still frame with the tiling (arclength) policy
// ρ = 1/period_px, so x = s + φ·period_px. A parameterization with ρ·period_px = 0 has no x:
// dashes then fall back to x = s.
//
// Lengths: sample.s is the parameter's arclength and is kept as it was (later stages use its
// differences), also where a stage cuts or extends a path; "length" in chaining, tip removal
// and backbone stretch is the polyline's pixel arclength, which equals the difference of s
// until a displacement bends the path.
#pragma once

#include <cstdint>
#include <vector>

#include "stroke/stroke_geometry.h"
#include "types/line_set.h"
#include "types/screen_path.h"

namespace lw {

// A sample between a and b at t: position, depth, s, fade and width interpolated; face and
// surface point of the nearer one.
[[nodiscard]] ScreenSample lerp_sample(const ScreenSample& a, const ScreenSample& b, float t);

// Where on the segment a–b (0 at a, 1 at b) the point nearest p lies.
[[nodiscard]] float nearest_on_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b);

// Splits, cuts and drops runs per `options` (Freestyle's "split by angle", "max 2D length",
// "min 2D length", in that order), after joining them into outlines when `options.outline`
// (stroke/outline.h: the set's runs become the closed outer outline of each drawing):
//   - a sample where the polyline turns by more than split_angle_deg (the angle between the
//     directions of its two segments; 180: never) ends one piece and starts the next;
//   - pieces longer than max_length_px (> 0) are cut into the fewest pieces of equal length,
//     each ≤ max_length_px, with interpolated samples at the cuts;
//   - pieces shorter than min_length_px are dropped.
// A closed loop that is split or cut becomes open, starting at its first split sample (or at
// sample 0), and its wrapped samples' s continue past the loop length. Input paths with
// fewer than two samples pass through unless min_length_px > 0.
std::vector<ScreenPath> apply_chaining_options(std::vector<ScreenPath> paths, const ChainingOptions& options);

// Geometry modifiers in order (Freestyle's sinus displacement, Perlin noise 1D, backbone
// stretcher, tip remover, polygonization-like simplification):
//   Sinus     displaces along the unit normal (−dy, dx) by amplitude·sin(2π(x/λ + phase));
//   Noise     displaces along the normal by amplitude·gradient_noise(seed, x/λ);
//   BackboneStretch adds a sample length_px beyond each open end along its end tangent, s
//             continuing (s0 − length_px before the start);
//   TipRemove cuts length_px of pixel arclength off each open end at interpolated samples;
//             a run no longer than 2·length_px is emptied (0 samples: callers skip paths
//             with < 2 samples);
//   Simplify  is Douglas–Peucker with tolerance_px: endpoints and the s of kept samples stay.
// Closed paths are displaced and simplified but have no ends to stretch or cut. Normals are
// taken before each displacing modifier from the polyline as it is then.
void apply_geometry_modifiers(ScreenPath& path, const StrokeParams& param, float period_px,
                              const std::vector<GeometryModifier>& mods);

// 1D gradient (Perlin) noise in [−1, 1]: a pseudo-random gradient in [−1, 1] at each integer
// lattice point, from a hash of (seed, lattice point) only, blended by Perlin's quintic fade.
// Zero at lattice points; the same for the same inputs on every run, thread and platform
// with IEEE floats.
float gradient_noise(uint64_t seed, double t);

// The dashes of `path` for `pattern` = [dash, gap, dash, gap, ...] pixels along x (above),
// repeated modulo the pattern's total, so the dashes move with the parameterization and do
// not slide when the view moves. An odd-length pattern is repeated twice (SVG
// stroke-dasharray). Each dash is an open piece with interpolated samples exactly at its
// ends; a dash of length 0 gives a piece of two coincident samples (a dot with round caps).
// A closed path whose first and last dashes meet at sample 0 gives them as one piece. An
// empty pattern, one with a negative entry, or a total < 1e-3 px returns { path }.
// Precondition: s nondecreasing along the path (every stage here keeps it so).
std::vector<ScreenPath> dash_path(const ScreenPath& path, const StrokeParams& param, float period_px,
                                  const std::vector<float>& pattern);

// A piecewise-linear ramp at x: flat beyond its first and last points. Precondition: the
// ramp has at least one point (an empty ramp means "no modifier" to evaluate_attributes).
float ramp_value(const Ramp& ramp, float x);
glm::vec3 ramp_value(const ColorRamp& ramp, float x);

// Per-sample width (pixels), alpha and colour of one path (vectors of its sample count):
//   width  = style.width · sample.width, then the width modifiers in order, then · taper
//            (so that ends taper whatever the modifiers replace); clamped to ≥ 0;
//   alpha  = style.alpha · (style.fade ? sample.alpha : 1), then the alpha modifiers,
//            clamped to [0, 1];
//   colour = style.color, then each colour modifier mixes towards its ramp by influence.
// A scalar modifier's ramp value r blends as value·r (Multiply), r (Replace) or value + r
// (Add). A modifier with an empty ramp changes nothing, whatever its blend.
// Inputs mapped to [0, 1] before the ramp (types/line_set.h):
//   Along      (s − s0)/L, L = s_last − s0 (+ the closing segment of a closed path);
//   Distance   (depth − range_min)/(range_max − range_min), clamped (a step at range_min
//              when the range is empty);
//   Curvature  |turn angle| / mean length of the two adjacent segments (1/px), mapped by the
//              range the same way; the ends of an open path take their neighbour's value.
// Taper: linear from 0 at the end to 1 at taper_in_px (start) / taper_out_px (end) of s; the
// two multiply where they overlap; closed paths have none.
StrokeAttributes evaluate_attributes(const ScreenPath& path, const LineSetStyle& style);

// The stroke a piece was cut from: along and taper are measured on it, so that a dashed
// stroke's width ramp and taper run over the whole stroke, not over each dash (as in
// Freestyle, whose dashed-line shader hides parts of one stroke).
struct StrokeSpan {
    float s_begin = 0.0f, s_end = 0.0f;  // s at the start and end (closed: + the closing segment)
    bool closed = false;                 // no taper
};
StrokeSpan stroke_span(const ScreenPath& path);
StrokeAttributes evaluate_attributes(const ScreenPath& piece, const LineSetStyle& style, const StrokeSpan& whole);

// A set's whole style for one parameterized path: geometry modifiers → dashes → attributes
// (over the whole modified path's span) → stroke with the style's caps and joins. Of `param` it reads ρ, φ, the fold
// and the mitre limit (width, colour and taper come from `style`). Pieces left with no samples (tip removal) are
// skipped; a piece of one sample, or of at most a pixel, becomes a dot with round or square caps (append_stroke above),
// which is what dashes of length 0 rely on.
void append_styled_stroke(const ScreenPath& path, const StrokeParams& param, const LineSetStyle& style,
                          float period_px, std::vector<StrokeVertex>& out);

}  // namespace lw
