// tests/test_slam_support.h — a check shared by the SLAM synthesis tests.
#pragma once

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "slam_synth/texture_statistics.h"

namespace lw::test {

// Every row of `image` keeps the target's per-row mean and variance (the 1.5D statistics)
// within 5 % of the row's own value, or of the largest row's for rows with almost no ink.
inline void expect_rows_within_5_percent(const synth::Plane& image, const synth::TextureStatistics& target) {
    std::vector<double> mean, variance;
    synth::row_moments(image, mean, variance);
    const double peak_mean = *std::max_element(target.row_mean.begin(), target.row_mean.end());
    const double peak_variance = *std::max_element(target.row_variance.begin(), target.row_variance.end());
    for (int r = 0; r < image.rows; ++r) {
        const double tm = target.row_mean[size_t(r)], tv = target.row_variance[size_t(r)];
        EXPECT_NEAR(mean[size_t(r)], tm, 0.05 * std::max(tm, 0.1 * peak_mean)) << "row " << r;
        EXPECT_NEAR(variance[size_t(r)], tv, 0.05 * std::max(tv, 0.1 * peak_variance)) << "row " << r;
    }
}

}  // namespace lw::test
