// engine/render/line_sets.h — which lines each line set takes, and how it is parameterized.
//
// Input:  the scene's `LinesDesc` (explicit "line_sets", or the per-type shorthand), the
//         visible and hidden runs of the frame (lines/visibility.h) and, for "models" and
//         "materials" selections, the face groups of the mesh (scene/triangle_mesh.h).
// Output: per set, its own copy of the runs it selects, cut by its chaining options; the
//         coherence parameters the set's tracker runs with (its SLAM's length, its κ, its
//         policy and spacing: one set's texture never sets another's period); the union of
//         line types the extraction must find.
//
// Freestyle's model (its "line sets" and "line styles"): selection by edge type,
// visibility, object and material; each set drawn in order with its own style.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "coherence/coherence.h"
#include "scene/style.h"
#include "stroke/slam.h"
#include "types/line_set.h"
#include "types/screen_path.h"

namespace lw {

// The sets a frame draws: `lines.sets` when the scene has "line_sets", else one set per
// line type (silhouette, suggestive, crease, border — always four, in that order, so that
// set index = type index), each with its type's LineStyle, enabled as the type is.
[[nodiscard]] std::vector<LineSetDesc> effective_line_sets(const LinesDesc& lines);

// The extraction switches: a type is extracted when an enabled set selects it (and, for the
// shorthand, when the type is on). Thresholds are the scene's.
[[nodiscard]] LineParams extraction_params(const LinesDesc& lines, const std::vector<LineSetDesc>& sets);

// What a face belongs to, for "models" and "materials" selections: per welded face, the
// index of its group; per group, the model's file name and the material's name ("" for
// none).
struct FaceGroups {
    std::vector<uint32_t> face_group;
    std::vector<std::string> model_names, material_names;  // per group
};

// The runs a set selects (types, visibility, models, materials), then its chaining options.
[[nodiscard]] std::vector<ScreenPath> select_line_set(const std::vector<ScreenPath>& runs, const LineSetDesc& set,
                                                      const FaceGroups* groups);

// Sets that are drawn as plain flat strokes (the line pass): no SLAM, dashes, tapers,
// modifiers, or caps and joins other than the line pass's own.
[[nodiscard]] bool is_plain_line_set(const LineSetStyle& style);

// Sets drawn once through a coverage layer (gpu/coverage_layer.h), so that their own overlaps
// do not blend twice: translucent ones (alpha under 1, or alpha modifiers).
[[nodiscard]] bool draws_once(const LineSetStyle& style);

// Sets whose look depends on a parameter along the stroke (SLAM, dashes, sinus, noise).
[[nodiscard]] bool needs_parameterization(const LineSetStyle& style);

// The coherence parameters of one set: `base` (policy, splat radius, RANSAC, fragment
// length) with the set's SLAM length, κ (default: square texels, the SLAM's height over the
// stroke width), policy and spacing. Sets without a SLAM count T in texture lengths of
// `base.slam_length_px` pixels.
[[nodiscard]] CoherenceParams line_set_coherence(const CoherenceParams& base, const LineSetDesc& set,
                                                 const Slam* slam, float scene_spacing_px);

// The on-screen length of one unit of T at the tiling scale: Lmax / κ.
inline float period_px(const CoherenceParams& params) { return params.slam_length_px / params.length_scale; }

// The tiling parameterization (T = s·κ/Lmax) of every path: sets that need a parameter in a
// frame rendered without coherence.
[[nodiscard]] std::vector<PathParam> tiling_params(const std::vector<ScreenPath>& paths, const CoherenceParams& params);

}  // namespace lw
