// slam_synth/slam_conditions.h — the SLAM conditions of Bénard et al. 2010 §3.2, measured.
//
// - top_periodicity: largest |A_1.0(x) − A_1.0(x + n/2)| of the top level as synthesized
//   (n texels, before resampling or quantization). Its seed is [W_0.5 W_0.5], and circular
//   pyramids and global statistics commute with the half-length shift, so this is float
//   rounding only.
// - self_similarity: largest |A_1.0[x] − A_0.5[2x mod L]| in the stored Slam
//   (slam_self_similarity_error): A_1.0 = [A_0.5 A_0.5] up to rounding.
// - mean_level_step: mean |A_{i+1} − A_i| over texels and adjacent pairs of stored levels
//   (smooth variation; it should halve when the level count doubles).
// - wrap_difference vs interior_difference: the column step d(x) = mean over levels and rows
//   of |A[x+1] − A[x]|, at the wrap (x = L − 1, next column 0) against its mean over the
//   interior, and where the wrap ranks among the interior's columns (seamless tiling: the
//   wrap is an ordinary column, not the largest). Every seed W_l takes the same value at
//   x = 0, so the wrap is one location seen by all levels: compare it with the interior's
//   spread (its largest column step), not only with its mean.
// - level_rmse(d): the RMS difference between stored levels d apart, over texels and every
//   pair (i, i + d). Smooth variation is rmse(1) small against rmse(N − 1), the distance from
//   A_0.5 to A_1.0: their ratio normalizes rmse(1) for how far apart the synthesis puts
//   the levels overall (a synthesis that moves every level further from its seed raises
//   both, and the ratio only if adjacent levels drift apart faster).
#pragma once

#include "slam_builder.h"

namespace lw::synth {

struct SlamConditions {
    double top_periodicity = 0;
    double self_similarity = 0;
    double mean_level_step = 0;
    double wrap_difference = 0, interior_difference = 0, interior_max = 0;
    double wrap_rank = 0;  // share of interior columns with a smaller step than the wrap
    double rmse_adjacent = 0, rmse_ends = 0;  // level_rmse(1), level_rmse(N − 1)
};

[[nodiscard]] double top_level_periodicity(const Plane& top);
[[nodiscard]] double mean_level_step(const Slam& slam);
[[nodiscard]] double level_rmse(const Slam& slam, int d);
[[nodiscard]] SlamConditions measure_slam_conditions(const SlamSynthesis& s);

// How close level `index` and its seed come to the exemplar's statistics, per group
// (texture_statistics.h): both cropped to the exemplar's rows and padded as the exemplar
// was, then analyzed. `desc` must be the one the SLAM was made with (the seed is remade).
struct LevelStatisticsReport {
    std::vector<StatisticGroup> seed, synthesized;
};
[[nodiscard]] LevelStatisticsReport level_statistics_report(const SlamSynthesis& s, const SlamSynthesisDesc& desc,
                                                            int index);

}  // namespace lw::synth
