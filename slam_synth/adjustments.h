// slam_synth/adjustments.h — the projections of Portilla & Simoncelli (2000, §4 and its
// appendix): each changes an image or a set of bands as little as it can so that one group of
// statistics takes a target value. The synthesis loop (texture_synthesis.h) applies them in
// textureSynth's order.
//
// - moments and per-row moments of a set of samples;
// - impose_skewness / impose_kurtosis: x + λ·q(x) with q orthogonal to 1 and x (textureSynth's
//   modskew, modkurt), λ the smallest root found by a bracketing search rather than by
//   polynomial roots, saturating at the nearest extremum when the target cannot be reached;
// - central autocorrelation from a spectrum, impose_autocorrelation (modacor22: solve for the
//   autocorrelation of a zero-phase filter, apply its square-root spectrum; the solve is
//   Tikhonov-regularized, see the .cpp);
// - impose_correlation (adjustCorr1s) and impose_correlation_with (adjustCorr2s): linear
//   recombination of columns so that their Gram matrix, and their cross-correlation with
//   fixed columns, match targets.
#pragma once

#include <cstddef>
#include <vector>

#include "fft.h"
#include "small_linalg.h"

namespace lw::synth {

struct Moments {
    double mean = 0, variance = 0, skewness = 0, kurtosis = 3, min = 0, max = 0;
};
[[nodiscard]] Moments moments(const float* x, size_t n);

// A central autocorrelation: values at lags (dy, dx) ∈ [−half, half]², row-major.
struct Autocorrelation {
    int half = 0;
    std::vector<double> values;
    int side() const { return 2 * half + 1; }
    double at(int dy, int dx) const { return values[size_t((dy + half) * side() + dx + half)]; }
    double center() const { return values.empty() ? 0.0 : at(0, 0); }
};

// The largest autocorrelation half-width that modacor can impose on a rows × cols grid
// (it needs lags up to 2·half to stay under half the grid), capped by `limit`.
[[nodiscard]] int autocorrelation_half(int rows, int cols, int limit);

// (1/N)·Σ_t y(t)·y(t + τ) of the real image whose half spectrum (unnormalized) is `spectrum`.
[[nodiscard]] Autocorrelation central_autocorrelation(const Complexes& spectrum, int rows, int cols, int half);

// Filters the image with half spectrum `spectrum` (consumed) so that its central
// autocorrelation becomes `target`; writes the result (rows × cols) to `out`. When the
// linear system is singular the image is returned unfiltered.
void impose_autocorrelation(Complexes& spectrum, int rows, int cols, const Autocorrelation& target, float* out);

void impose_skewness(float* x, size_t n, double target);
void impose_kurtosis(float* x, size_t n, double target);

// Gram matrix (1/n)·XᵀY of columns of length n.
[[nodiscard]] Matrix gram(const std::vector<const float*>& x, const std::vector<const float*>& y, size_t n);

// X ← X·M with M = C^(−1/2)·T^(1/2) (C = XᵀX/n, T = target).
void impose_correlation(const std::vector<float*>& x, size_t n, const Matrix& target);

// Columns Y that a correlation adjustment leaves alone, with the pseudo-inverse of YᵀY/n
// (computed once, shared by the adjustments of several X against the same Y).
struct FixedColumns {
    std::vector<const float*> columns;
    Matrix inverse_gram;
};
[[nodiscard]] FixedColumns fixed_columns(std::vector<const float*> columns, size_t n);

// X ← X·Mx + Y·My so that XᵀX/n = target_xx and XᵀY/n = target_xy, Y fixed.
void impose_correlation_with(const std::vector<float*>& x, const FixedColumns& y, size_t n, const Matrix& target_xx,
                             const Matrix& target_xy);

}  // namespace lw::synth
