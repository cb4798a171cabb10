// tools/bench/stats.h — median, min and max of a benchmark's samples.
#pragma once

#include <algorithm>
#include <vector>

namespace lw::bench {

struct Stats {
    double median = 0, min = 0, max = 0;
};

inline Stats stats(std::vector<double> v) {
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

}  // namespace lw::bench
