#include "slam_conditions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "seed_pyramid.h"

namespace lw::synth {

double top_level_periodicity(const Plane& top) {
    const int half = top.cols / 2;
    double worst = 0.0;
    for (int r = 0; r < top.rows; ++r)
        for (int x = 0; x < half; ++x) worst = std::max(worst, double(std::abs(top.at(r, x) - top.at(r, x + half))));
    return worst;
}

namespace {

// Mean of f(A_{i+d} − A_i) over texels and every pair (i, i + d) of stored levels.
template <class F>
double mean_over_level_pairs(const Slam& slam, int d, F f) {
    double sum = 0.0;
    size_t count = 0;
    for (int i = 0; i + d < slam.levels; ++i)
        for (int r = 0; r < slam.height; ++r)
            for (int x = 0; x < slam.length; ++x, ++count) sum += f(double(slam.at(i + d, r, x)) - double(slam.at(i, r, x)));
    return count ? sum / double(count) : 0.0;
}

}  // namespace

double mean_level_step(const Slam& slam) {
    return mean_over_level_pairs(slam, 1, [](double e) { return std::abs(e); });
}

double level_rmse(const Slam& slam, int d) {
    return std::sqrt(mean_over_level_pairs(slam, d, [](double e) { return e * e; }));
}

SlamConditions measure_slam_conditions(const SlamSynthesis& s) {
    const Slam& slam = s.slam;
    SlamConditions c;
    c.top_periodicity = top_level_periodicity(s.levels.back());
    c.self_similarity = slam_self_similarity_error(slam);
    c.mean_level_step = mean_level_step(slam);
    c.rmse_adjacent = level_rmse(slam, 1);
    c.rmse_ends = level_rmse(slam, slam.levels - 1);
    std::vector<double> step(static_cast<size_t>(slam.length), 0.0);  // d(x), x + 1 taken modulo L
    for (int i = 0; i < slam.levels; ++i)
        for (int r = 0; r < slam.height; ++r)
            for (int x = 0; x < slam.length; ++x)
                step[size_t(x)] += std::abs(slam.at(i, r, (x + 1) % slam.length) - slam.at(i, r, x));
    const double rows = double(slam.levels) * slam.height;
    for (double& d : step) d /= rows;
    c.wrap_difference = step.back();
    size_t smaller = 0;
    for (int x = 0; x + 1 < slam.length; ++x) {
        c.interior_difference += step[size_t(x)];
        c.interior_max = std::max(c.interior_max, step[size_t(x)]);
        smaller += step[size_t(x)] < c.wrap_difference;
    }
    c.interior_difference /= double(slam.length - 1);
    c.wrap_rank = double(smaller) / double(slam.length - 1);
    return c;
}

LevelStatisticsReport level_statistics_report(const SlamSynthesis& s, const SlamSynthesisDesc& desc, int index) {
    const SlamModel& m = s.model;
    const Plane& level = s.levels[size_t(index)];
    const PyramidGeometry g = make_pyramid_geometry(m.padded_rows, level.cols, s.target.scales, s.target.orientations);
    const Plane half = half_seed(m.padded_rows, desc.length, desc.seed);
    const Plane seed = seed_level(half, s.slam.level_value(index), level.cols);
    Plane seed_rows(m.exemplar_rows, level.cols);
    for (int r = 0; r < m.exemplar_rows; ++r)
        for (int x = 0; x < level.cols; ++x) seed_rows.at(r, x) = seed.at(r + m.pad_top, x);
    auto analyze = [&](const Plane& rows) {
        return analyze_texture(pad_exemplar(rows, m, rows.cols), g, s.target.neighborhood);
    };
    return {compare_statistics(s.target, analyze(seed_rows)), compare_statistics(s.target, analyze(level))};
}

}  // namespace lw::synth
