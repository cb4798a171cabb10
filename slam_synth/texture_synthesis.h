// slam_synth/texture_synthesis.h — Portilla–Simoncelli synthesis (2000, §4; textureSynth's
// textureSynthesis): starting from a seed image, each iteration builds the pyramid and
// imposes the target statistics coarse to fine, then the pixel statistics.
//
// Input: target statistics (texture_statistics.h, from an exemplar of any length but the same
// row count and model), a seed of the geometry's size, and the iteration count. Output: the
// synthesized image, the seed's size.
//
// Three departures from textureSynth, each measured (docs/research/slam-fidelity.md):
// - The high-pass residual takes part in the last iteration only. The model constrains it
//   by its variance alone, from above; carried from iteration to iteration it keeps what
//   the pixel steps' clamps and polynomials leave above the bands (ringing, period-2
//   speckle), which the next pixel step amplifies, and the levels came out grainy (2–3×
//   the exemplar's second differences along the length on thin strokes). Synthesizing the
//   band-limited image and restoring the residual once, from the image's own high
//   frequencies lowered to the target variance, keeps the residual within its constraint
//   (at most the target; it ends below it, softer edges) and gives 0.76–1.31× the
//   exemplar's grain at level 1.0 (at most 1.40× over all levels).
// - The last iteration also bounds the paper that ink encloses, in basins of at most Na²
//   texels, by the exemplar's (enclosed_ink.h), in each of the pixel step's range/row
//   alternations: hollow dots are fixed points of the model's statistics,
//   and no number of iterations removed them (10–19 over 17 levels of identical dots,
//   seeds 1–6; now 0). Only the last iteration, and only small basins, because a basin's
//   fill follows its lowest rim texel: taken every iteration the unbounded step raised the
//   brush exemplar's RMSE(1)/RMSE(16) by 30 % (seed 1), on the last alone by 5.9 % (seeds
//   1–8); bounded to Na² texels it leaves it as it was (0.1910 against 0.1913).
// - The last iteration also holds the elements of an exemplar of like elements (a row of
//   identical dots) to the exemplar's range of sizes (element_sizes.h), before the enclosed
//   paper in each alternation: specks erased, merged pairs split, thin hooks trimmed. The
//   identical dots' area CV at level 1.0 went from 0.08–0.31 to 0.07–0.12 over seeds 1–6
//   (mean over the levels 0.20–0.25 → 0.10–0.12); exemplars of unlike elements, lines and
//   nets take no part. After the last row step the enclosed fill runs once more (a pocket a
//   hair under the element threshold; a few texels on other exemplars).
// - No accelerator (textureSynth's x + 0.8 (x − x_prev) between iterations): it converges
//   faster, but each level then moves further from its seed and adjacent levels differ
//   up to twice as much against the ends (RMSE(1)/RMSE(16)): the smooth variation the SLAM
//   needs (§3.2) matters more here than the last dB of statistics.
//
// Scope (Bénard et al. 2010 §3.2.2): `Global` imposes every statistic per texture (the
// model as published, the 1D case of the paper, with the departures above). `Rows` is the paper's 1.5D modification: the
// mean and variance per row, at each scale's low-pass image and at the final mean/variance
// step (so rows keep the exemplar's profile across the stroke, and the zero padding stays
// empty); skewness,
// kurtosis and range are then still imposed globally — followed here by three alternations
// of range and per-row mean/variance, which keep every row within 5 % of the exemplar's
// (the range clamp alone moves inky rows by up to 10 %). The output is then not clamped to
// the exemplar's range by its last step; callers clamp (slam_builder does, to [0, 1]).
#pragma once

#include <functional>

#include "steerable_pyramid.h"
#include "texture_statistics.h"

namespace lw::synth {

enum class StatisticsScope { Global, Rows };

struct SynthesisDesc {
    int iterations = 50;  // textureSynth's default; the authors' SLAM code runs 15 per level
    StatisticsScope scope = StatisticsScope::Rows;
    // Called after each iteration with its index and the current image (for reports).
    std::function<void(int iteration, const Plane& image)> on_iteration;
};

[[nodiscard]] Plane synthesize_texture(const TextureStatistics& target, const Plane& seed, const PyramidGeometry& g,
                                       const SynthesisDesc& desc = {});

}  // namespace lw::synth
