// engine/hatch/kl2.h — the a-priori Kullback–Leibler divergence KL2 of Jodoin et al. 2002 (§2.3,
// §2.4) between a training sample and a generated one.
//
// Input:  two samples of d-dimensional vectors (row-major), already scaled to unit variance
//         per dimension (as eq. 17 assumes; engine/hatch/stroke_vector.h does it with the
//         training set's spread).
// Output: KL2 = KL(P_t ‖ P_g) = ∫ P_t ln(P_t / P_g), each density a Gaussian Parzen window
//         estimate (eq. 16) with Silverman's smoothing h = (4 / (d + 2))^(1/(d+4)) n^(−1/(d+4))
//         for its own n (Silverman 1986, eq. 4.14; the text of eq. 17 in papers/ reads 2d + 1,
//         which agrees at d = 1), and the integral the Monte-Carlo mean over the training
//         points: KL2 ≈ (1/n_t) Σ_x∈Z_t [ln P̂_t(x) − ln P̂_g(x)]. Both estimates include the
//         point itself, so a sample against itself gives exactly 0. Log-sum-exp keeps far
//         points finite.
#pragma once

#include <cstddef>
#include <vector>

namespace lw {

struct Samples {
    int dim = 1;
    std::vector<double> values;  // size() × dim
    size_t size() const { return dim > 0 ? values.size() / size_t(dim) : 0; }
    const double* row(size_t i) const { return values.data() + i * size_t(dim); }
};

[[nodiscard]] double silverman_h(int dim, size_t n);
// ln P̂(x) for the Parzen estimate of `sample` with window h.
[[nodiscard]] double parzen_log_density(const Samples& sample, double h, const double* x);
// KL2(training ‖ generated); both non-empty, same dim.
[[nodiscard]] double kl2_divergence(const Samples& training, const Samples& generated);

}  // namespace lw
