#include "seed_pyramid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

namespace lw::synth {

Plane filtered_seed(int rows, int length, uint32_t seed) {
    // mt19937's output sequence is fixed by the standard; the float conversion is ours
    // (std::uniform_real_distribution may differ between library versions).
    std::mt19937 rng(seed);
    Plane source(rows, length);
    for (float& v : source.v) v = float(rng() >> 8) * (1.0f / 16777216.0f);
    // Gaussian of width 5 (full width at half maximum) along the length only, periodic. Read
    // as σ = 1 (5 taps), W_0.5 kept white noise up to its Nyquist frequency, above what the
    // exemplar's bands hold; measured, the wider reading gives the same grain and adjacent
    // levels closer against the ends on the smooth exemplars (docs/research/slam-fidelity.md).
    const double sigma = 5.0 / (2.0 * std::sqrt(2.0 * std::numbers::ln2));
    const int reach = int(std::ceil(3.0 * sigma));
    std::vector<double> weight(size_t(2 * reach + 1));
    double total = 0.0;
    for (int k = -reach; k <= reach; ++k) total += weight[size_t(k + reach)] = std::exp(-0.5 * k * k / (sigma * sigma));
    Plane filtered(rows, length);
    for (int r = 0; r < rows; ++r)
        for (int x = 0; x < length; ++x) {
            double sum = 0.0;
            for (int k = -reach; k <= reach; ++k)
                sum += weight[size_t(k + reach)] * source.at(r, ((x + k) % length + length) % length);
            filtered.at(r, x) = float(sum / total);
        }
    // Histogram matching to uniform: the value of rank i becomes (i + ½)/n (ties by index).
    std::vector<size_t> order(filtered.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return filtered.v[a] < filtered.v[b]; });
    const double n = double(order.size());
    for (size_t i = 0; i < order.size(); ++i) filtered.v[order[i]] = float((double(i) + 0.5) / n);
    return filtered;
}

Plane resample_length(const Plane& in, int cols) {
    Plane out(in.rows, cols);
    for (int x = 0; x < cols; ++x) {
        // Exact rational position x·in.cols/cols: integer part and remainder.
        const long long num = (long long)x * in.cols;
        const int i0 = int(num / cols);
        const float f = float(num % cols) / float(cols);
        const int i1 = (i0 + 1) % in.cols;
        for (int r = 0; r < in.rows; ++r) out.at(r, x) = f == 0.0f ? in.at(r, i0) : (1.0f - f) * in.at(r, i0) + f * in.at(r, i1);
    }
    return out;
}

Plane fourier_resample_length(const Plane& in, int cols) {
    const int n = in.cols;
    if (cols == n) return in;
    // Each row as the periodic band-limited function its samples define: its spectrum
    // truncated (shorter) or zero-padded (longer). At the shorter grid's Nyquist frequency
    // (even lengths) the longer grid has a ±shared pair and the shorter one bin, which the
    // inverse counts once: growing, the bin's value is split over the pair (½ each);
    // shrinking, the pair folds into it (2·Re), as scipy.signal.resample does.
    const int shared = std::min(n, cols) / 2;
    Floats source(static_cast<size_t>(n)), row(static_cast<size_t>(cols));  // fftwf_malloc ones only (fft.h)
    Complexes from(size_t(n / 2 + 1)), to(size_t(cols / 2 + 1));
    Plane out(in.rows, cols);
    for (int r = 0; r < in.rows; ++r) {
        std::copy_n(in.v.begin() + std::ptrdiff_t(size_t(r) * size_t(n)), n, source.begin());
        fft_forward_real(1, n, source.data(), from.data());
        std::fill(to.begin(), to.end(), cfloat(0.0f));
        for (int k = 0; k < shared; ++k) to[size_t(k)] = from[size_t(k)];
        const cfloat last = from[size_t(shared)];
        if (std::min(n, cols) % 2 != 0) to[size_t(shared)] = last;  // no Nyquist bin: a full pair
        else to[size_t(shared)] = n < cols ? 0.5f * last : cfloat(2.0f * last.real(), 0.0f);
        fft_inverse_real(1, cols, to.data(), row.data());
        for (int x = 0; x < cols; ++x) out.at(r, x) = row[size_t(x)] / float(n);
    }
    return out;
}

Plane tile_twice(const Plane& in) {
    Plane out(in.rows, 2 * in.cols);
    for (int r = 0; r < in.rows; ++r)
        for (int x = 0; x < out.cols; ++x) out.at(r, x) = in.at(r, x % in.cols);
    return out;
}

Plane half_seed(int rows, int length, uint32_t seed) {
    return fourier_resample_length(filtered_seed(rows, length, seed), length / 2);
}

Plane seed_level(const Plane& half, double level, int cols) {
    const float alpha = float(2.0 * level - 1.0);
    // W_1.0 = [W_0.5 W_0.5], scaled to `cols`.
    const Plane a = fourier_resample_length(half, cols), b = fourier_resample_length(tile_twice(half), cols);
    Plane out(half.rows, cols);
    for (size_t i = 0; i < out.size(); ++i) {
        if (alpha == 0.0f) out.v[i] = a.v[i];
        else if (alpha == 1.0f) out.v[i] = b.v[i];
        else out.v[i] = alpha * b.v[i] + (1.0f - alpha) * a.v[i];
    }
    return out;
}

}  // namespace lw::synth
