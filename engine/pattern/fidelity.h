// engine/pattern/fidelity.h — how closely a synthesized pattern follows its reference, in
// numbers (for tests, the benchmark and docs/BENCHMARKS.md).
//
// Input:  the reference analysis, the synthesis, the target frame and the fitting mode.
// Output: two-sample Kolmogorov–Smirnov statistics D between reference and output elements for
//         orientation (relative to the path tangent along a path), length, thickness (box
//         width) and colour (the largest D over r, g, b), and nearest-neighbour distances of
//         the element centres. Output elements are fitted again from the output strokes, so
//         that variation and placement are measured as drawn; values are rounded to 1/100.
#pragma once

#include <vector>

#include "pattern/synthesis.h"

namespace lw {

// sup |F_a − F_b| of the empirical distributions; 0 when either is empty.
[[nodiscard]] double ks_statistic(std::vector<double> a, std::vector<double> b);
// The two-sample critical value at level α = 0.05: 1.358 · √((n + m) / (n m)).
[[nodiscard]] double ks_critical_05(size_t n, size_t m);

struct ElementSample {
    std::vector<double> orientation, length, thickness, red, green, blue;
    std::vector<double> nearest;  // nearest-neighbour distance of each centre
};

struct PatternFidelity {
    ElementSample reference, output;
    double ks_orientation = 0, ks_length = 0, ks_thickness = 0, ks_color = 0, ks_nearest = 0;
    double critical = 0;  // ks_critical_05(N_ref, N_tar)
    double median_nn_reference = 0, median_nn_output = 0;
};

[[nodiscard]] PatternFidelity measure_fidelity(const PatternAnalysis& reference, const PatternSynthesis& synthesis,
                                               const PatternFrame& target, FitMode fit);

}  // namespace lw
