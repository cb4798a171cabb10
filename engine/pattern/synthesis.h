// engine/pattern/synthesis.h — stroke patterns by example along a path (1D) or in a region
// (2D): Barla, Breslav, Thollot, Sillion & Markosian 2006, "Stroke Pattern Analysis and
// Synthesis".
//
// Input:  reference strokes, the reference's frame (its path or region; by default its
//         bounding box: the box's long midline for 1D, the box for 2D), the target frame, and
//         `PatternDesc` (ε, rings k, variation, seed).
// Output: `PatternSynthesis`: the target strokes — copies of reference elements, moved,
//         turned with the path in 1D, and varied on request — and, per target element, the
//         reference element it copies.
//
// Stages (the paper's sections):
//   analyze_pattern    — elements by clustering at ε (§2.1, §2.2); the distribution: chain or
//                        unskewed Delaunay, shift vectors (§2.3); the pairwise measures of
//                        §3.1 between reference elements, in the frame's orientation (the
//                        target elements are copies of reference elements, so every measure
//                        the synthesis needs is one of these N_ref² values).
//   synthesize_pattern — seeds by Lloyd, N_tar = N_ref·A_tar/A_ref (§3.2); the target
//                        distribution; elements assigned growing outward from the centre
//                        seed (Algorithm 1), each by partial k-ring neighbourhood matching
//                        (§3.1, §3.2) and a random pick among the matching reference
//                        neighbourhoods; the variation post-process (§3.3).
//
// Neighbourhood matching (§3.1): the k-ring of the target seed, restricted to the elements
// already synthesized, against the k-ring of each reference element; positions relative to the
// centre element; pairs are mutual nearest neighbours. shape (symmetric Hausdorff between
// the centred boxes), par (angle between principal axes), ov (ratio of principal lengths),
// sup (difference of widths — the box's extent along B; the authors' jot-lib code uses the
// long axis here, the paper the width) and col (RGB distance) are averaged over the pairs and
// tested against σ_shape = 0.1 L, σ_par = π/20, σ_ov = 1.5, σ_sup = 0.1 L, σ_col = 0.15 (L the
// mean reference element length): a neighbourhood matches iff col ∧ (shape ∨ (par ∧ ov ∧ sup)).
// The score max(col/σ_col, min(shape/σ_shape, max(par/σ_par, (ov−1)/(σ_ov−1), sup/σ_sup)))
// is below 1 exactly then; when no reference neighbourhood matches (the paper: "it can happen
// that no pairing is found") the lowest score is taken, and counted.
// The paper does not say which reference element seeds the growth; ours is the one nearest
// the reference's centre, so that a target as large as the reference copies its gradients in
// place.
#pragma once

#include <vector>

#include "pattern/cluster.h"
#include "pattern/distribution.h"
#include "vector/curve.h"
#include "vector/stroke.h"

namespace lw {

struct PatternThresholds {
    float shape = 0.1f;  // × L
    float par = 0.15707963f;  // π/20
    float ov = 1.5f;
    float sup = 0.1f;  // × L
    float col = 0.15f;
};

struct PatternDesc {
    float epsilon = 0.0f;  // clustering scale ε, drawing units; ≤ 0: twice the median stroke width
    FitMode fit = FitMode::Contour;
    int rings = 0;           // neighbourhood size k; ≤ 0: 3 along a path, 2 in a region
    float variation = 0.0f;  // [0, 1]: the §3.3 post-process (0: none)
    uint64_t seed = 1;
    int lloyd_iterations = 30;
    PatternThresholds sigma;
};

// Where a pattern lives: along a path (1D) or inside a region (2D, the curve's points as a
// polygon; it is closed whatever the file says).
struct PatternFrame {
    bool along_path = false;
    Curve2D curve;
};
// The default reference frame: the strokes' bounding box, or its long midline for a path.
[[nodiscard]] PatternFrame bounding_frame(const std::vector<Stroke>& strokes, bool along_path);
// Length of the path or area of the region; throws lw::Error for a region that crosses
// itself (polygon_is_simple).
[[nodiscard]] float frame_measure(const PatternFrame& frame);

struct PatternAnalysis {
    std::vector<Stroke> strokes;
    std::vector<Element> elements;  // drawing coordinates
    std::vector<Element> local;     // the same centred at 0 and turned into the frame (1D: by −tangent)
    std::vector<float> frame_angle; // 1D: the path's tangent angle at each element; 2D: 0
    Distribution distribution;      // frame coordinates: 2D (x, y); 1D (s, t)
    PatternFrame frame;
    float measure = 0.0f;           // A_ref: path length or region area
    float epsilon = 0.0f;
    float mean_length = 0.0f;       // L
    int start = 0;                  // the element nearest the reference's centre
    // §3.1 measures between reference elements i and j at [i * N + j].
    std::vector<float> shape, par, ov, sup, col;
};

[[nodiscard]] PatternAnalysis analyze_pattern(std::vector<Stroke> strokes, const PatternFrame& frame,
                                              const PatternDesc& desc);

// What a caller should say of an analysis whose strokes all fell into one element (a scale ε
// as large as the drawing): there is no arrangement to follow, and the synthesis copies the
// whole reference once per seed. Empty when there is nothing to say. The caller names the file.
[[nodiscard]] std::string pattern_analysis_warning(const PatternAnalysis& analysis);

struct PatternSynthesis {
    StrokeSet strokes;
    std::vector<int> source;            // per target element, the reference element it copies
    std::vector<glm::vec2> centers;     // per target element, its centre in drawing coordinates
    std::vector<size_t> first_stroke;   // target element e owns strokes [first_stroke[e], first_stroke[e + 1])
    Distribution target;                // seeds and their graph, frame coordinates (before variation)
    int rings = 0;
    int matched = 0, fallback = 0;      // elements with a matching neighbourhood / the best non-matching one
    double lloyd_ms = 0.0, match_ms = 0.0, total_ms = 0.0;
};

// Throws lw::Error when the target has no length or area.
[[nodiscard]] PatternSynthesis synthesize_pattern(const PatternAnalysis& reference, const PatternFrame& target,
                                                  const PatternDesc& desc);

}  // namespace lw
