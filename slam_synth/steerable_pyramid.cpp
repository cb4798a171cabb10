#include "steerable_pyramid.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace lw::synth {

namespace {

// Signed frequency of DFT index k on an n-point axis: 0, 1, …, n/2 − 1, −n/2, …, −1.
int signed_frequency(int k, int n) { return k < n / 2 ? k : k - n; }
int wrap(int f, int n) { return f < 0 ? f + n : f; }

// Radial transition of the pyramid (textureSynth's rcosFn with width 1, position −1/2):
// 0 for r ≤ 1/2, 1 for r ≥ 1, cos(π/2·log2 r) between.
double high_radial(double r) {
    if (r <= 0.5) return 0.0;
    if (r >= 1.0) return 1.0;
    return std::cos(0.5 * std::numbers::pi * std::log2(r));
}
double low_radial(double r) {
    const double h = high_radial(r);
    return std::sqrt(std::max(0.0, 1.0 - h * h));
}

double power(double x, int n) {
    double p = 1.0;
    for (int i = 0; i < n; ++i) p *= x;
    return p;
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

PyramidGrid make_grid(int rows, int cols, int orientations) {
    PyramidGrid grid;
    grid.rows = rows;
    grid.cols = cols;
    const int n = orientations - 1, half_cols = cols / 2 + 1;
    const double c = std::sqrt(std::pow(2.0, 2 * n) * factorial(n) * factorial(n) / (orientations * factorial(2 * n)));
    grid.band_weight.assign(size_t(orientations), Floats(size_t(rows) * size_t(cols), 0.0f));
    grid.recon_weight.assign(size_t(orientations), Floats(half_size(rows, cols), 0.0f));
    grid.analytic.assign(size_t(orientations), std::vector<int8_t>(size_t(rows) * size_t(cols), 0));
    grid.low.assign(half_size(rows, cols), 0.0f);
    grid.high.assign(half_size(rows, cols), 0.0f);
    for (int ky = 0; ky < rows; ++ky) {
        const int fy = signed_frequency(ky, rows);
        const double uy = fy / (0.5 * rows);
        for (int kx = 0; kx < cols; ++kx) {
            const int fx = signed_frequency(kx, cols);
            const double ux = fx / (0.5 * cols), r = std::sqrt(ux * ux + uy * uy);
            const double band = high_radial(2.0 * r) * low_radial(r);
            const bool nyquist = fy == -rows / 2 || fx == -cols / 2;
            const size_t full = size_t(ky) * size_t(cols) + size_t(kx);
            for (int o = 0; o < orientations; ++o) {
                const double angle = std::numbers::pi * o / orientations;
                // cos(θ − θ_o)·r: the sign decides the lobe; exact zeros on the boundary line
                // matter for the analytic mask's symmetry, hence the tolerance.
                const double dot = ux * std::cos(angle) + uy * std::sin(angle);
                const double cosine = r > 0.0 ? dot / r : 0.0;
                const bool positive = dot > 1e-12, boundary = std::abs(dot) <= 1e-12;
                if (positive) grid.band_weight[size_t(o)][full] = float(2.0 * c * power(cosine, n) * band);
                grid.analytic[size_t(o)][full] = int8_t(nyquist || boundary ? 1 : positive ? 2 : 0);
                if (kx < half_cols) {
                    const size_t half = size_t(ky) * size_t(half_cols) + size_t(kx);
                    grid.recon_weight[size_t(o)][half] = float(c * power(cosine, n) * band);
                }
            }
            if (kx < half_cols) {
                const size_t half = size_t(ky) * size_t(half_cols) + size_t(kx);
                grid.low[half] = float(low_radial(r));
                grid.high[half] = float(high_radial(r));
            }
        }
    }
    return grid;
}

// x(fy, fx) of a real image's half spectrum (rows × cols/2+1), any signed frequency.
cfloat sample_half(const Complexes& x, int rows, int cols, int fy, int fx) {
    const int half_cols = cols / 2 + 1;
    if (fx >= 0) return x[size_t(wrap(fy, rows)) * size_t(half_cols) + size_t(fx)];
    return std::conj(x[size_t(wrap(-fy, rows)) * size_t(half_cols) + size_t(-fx)]);
}

}  // namespace

PyramidGeometry make_pyramid_geometry(int rows, int cols, int scales, int orientations) {
    if (scales < 1) throw Error("steerable pyramid: needs at least one scale, got " + std::to_string(scales));
    if (orientations < 1 || orientations > 8)
        throw Error("steerable pyramid: 1 to 8 orientations, got " + std::to_string(orientations));
    const int unit = 1 << (scales + 1);
    if (rows % unit != 0 || cols % unit != 0)
        throw Error("steerable pyramid: a " + std::to_string(rows) + "x" + std::to_string(cols) + " image with " +
                    std::to_string(scales) + " scales needs sizes divisible by " + std::to_string(unit));
    PyramidGeometry g;
    g.rows = rows;
    g.cols = cols;
    g.scales = scales;
    g.orientations = orientations;
    for (int s = 0; s <= scales; ++s) g.grids.push_back(make_grid(rows >> s, cols >> s, orientations));
    static const cfloat powers[4] = {{1, 0}, {0, -1}, {-1, 0}, {0, 1}};  // (−i)^k
    g.band_factor = powers[(orientations - 1) % 4];
    return g;
}

Complexes real_spectrum(const Plane& image) {
    Complexes x(half_size(image.rows, image.cols));
    fft_forward_real(image.rows, image.cols, image.v.data(), x.data());
    return x;
}

void build_bands(const Complexes& x, const PyramidGeometry& g, Pyramid& out) {
    const float inv_n0 = 1.0f / float(g.grids[0].pixels());
    out.bands.resize(size_t(g.scales * g.orientations));
    Complexes spectrum;
    for (int s = 0; s < g.scales; ++s) {
        const PyramidGrid& grid = g.grids[size_t(s)];
        spectrum.resize(grid.pixels());  // every element is written below
        for (int o = 0; o < g.orientations; ++o) {
            const Floats& w = grid.band_weight[size_t(o)];
            const size_t half_cols = size_t(g.cols / 2 + 1);
            for (int ky = 0; ky < grid.rows; ++ky) {
                const int fy = signed_frequency(ky, grid.rows);
                // Non-negative fx read the half spectrum's row fy, negative fx the conjugate of row −fy.
                const cfloat* positive = &x[size_t(wrap(fy, g.rows)) * half_cols];
                const cfloat* negative = &x[size_t(wrap(-fy, g.rows)) * half_cols];
                const size_t row = size_t(ky) * size_t(grid.cols);
                for (int kx = 0; kx < grid.cols / 2; ++kx)
                    spectrum[row + size_t(kx)] = g.band_factor * (w[row + size_t(kx)] * inv_n0) * positive[kx];
                for (int kx = grid.cols / 2; kx < grid.cols; ++kx)
                    spectrum[row + size_t(kx)] =
                        g.band_factor * (w[row + size_t(kx)] * inv_n0) * std::conj(negative[grid.cols - kx]);
            }
            ComplexPlane& band = out.bands[size_t(s * g.orientations + o)];
            if (band.rows != grid.rows || band.cols != grid.cols) band = ComplexPlane(grid.rows, grid.cols);
            fft_inverse_complex(grid.rows, grid.cols, spectrum.data(), band.v.data());
        }
    }
    const PyramidGrid& low = g.grids[size_t(g.scales)];
    const int half_cols = low.cols / 2 + 1;
    Complexes low_spectrum(half_size(low.rows, low.cols));
    for (int ky = 0; ky < low.rows; ++ky) {
        const int fy = signed_frequency(ky, low.rows);
        for (int kx = 0; kx < half_cols; ++kx) {
            const size_t i = size_t(ky) * size_t(half_cols) + size_t(kx);
            low_spectrum[i] = (low.low[i] * inv_n0) * sample_half(x, g.rows, g.cols, fy, kx);
        }
    }
    out.lowpass = Plane(low.rows, low.cols);
    fft_inverse_real(low.rows, low.cols, low_spectrum.data(), out.lowpass.v.data());
}

Pyramid build_pyramid(const Plane& image, const PyramidGeometry& g) {
    if (image.rows != g.rows || image.cols != g.cols) throw Error("build_pyramid: image size does not match the geometry");
    const Complexes x = real_spectrum(image);
    Pyramid p;
    build_bands(x, g, p);
    Complexes high(x.size());
    const float inv_n0 = 1.0f / float(g.grids[0].pixels());
    for (size_t i = 0; i < x.size(); ++i) high[i] = x[i] * (g.grids[0].high[i] * inv_n0);
    p.highpass = Plane(g.rows, g.cols);
    fft_inverse_real(g.rows, g.cols, high.data(), p.highpass.v.data());
    return p;
}

void expand_spectrum(const Complexes& coarse, int coarse_rows, int coarse_cols, Complexes& fine, float scale) {
    const int fine_rows = 2 * coarse_rows, fine_half = coarse_cols + 1, coarse_half = coarse_cols / 2 + 1;
    for (int ky = 0; ky < coarse_rows; ++ky) {
        const int fy = signed_frequency(ky, coarse_rows);
        const bool nyquist_row = fy == -coarse_rows / 2;
        for (int kx = 0; kx < coarse_half; ++kx) {
            cfloat v = coarse[size_t(ky) * size_t(coarse_half) + size_t(kx)] * scale;
            if (kx == coarse_cols / 2) v *= 0.5f;  // the implicit mirror column takes the other half
            if (nyquist_row) {
                v *= 0.5f;
                fine[size_t(wrap(-fy, fine_rows)) * size_t(fine_half) + size_t(kx)] += v;
            }
            fine[size_t(wrap(fy, fine_rows)) * size_t(fine_half) + size_t(kx)] += v;
        }
    }
}

void add_band_reconstruction(const std::vector<Complexes>& real_band, int s, const PyramidGeometry& g, Complexes& out) {
    const PyramidGrid& grid = g.grids[size_t(s)];
    const cfloat back = std::conj(g.band_factor);
    for (int o = 0; o < g.orientations; ++o) {
        const Floats& w = grid.recon_weight[size_t(o)];
        const Complexes& r = real_band[size_t(o)];
        for (size_t i = 0; i < out.size(); ++i)
            if (w[i] != 0.0f) out[i] += back * (w[i] * r[i]);
    }
}

void expand_analytic(const Complexes& real_band, int s, int o, const PyramidGeometry& g, ComplexPlane& out) {
    const PyramidGrid& coarse = g.grids[size_t(s + 1)];
    const PyramidGrid& fine = g.grids[size_t(s)];
    Complexes spectrum(fine.pixels(), cfloat(0.0f));
    const std::vector<int8_t>& mask = coarse.analytic[size_t(o)];
    // The inverse is on the fine grid but the spectrum came from the coarse one.
    const float scale = 1.0f / float(coarse.pixels());
    for (int ky = 0; ky < coarse.rows; ++ky) {
        const int fy = signed_frequency(ky, coarse.rows);
        const bool nyquist_row = fy == -coarse.rows / 2;
        for (int kx = 0; kx < coarse.cols; ++kx) {
            const int m = mask[size_t(ky) * size_t(coarse.cols) + size_t(kx)];
            if (m == 0) continue;
            const int fx = signed_frequency(kx, coarse.cols);
            const bool nyquist_col = fx == -coarse.cols / 2;
            cfloat v = sample_half(real_band, coarse.rows, coarse.cols, fy, fx) * (float(m) * scale);
            if (nyquist_row) v *= 0.5f;
            if (nyquist_col) v *= 0.5f;
            const int ry[2] = {wrap(fy, fine.rows), wrap(-fy, fine.rows)};
            const int rx[2] = {wrap(fx, fine.cols), wrap(-fx, fine.cols)};
            for (int a = 0; a < (nyquist_row ? 2 : 1); ++a)
                for (int b = 0; b < (nyquist_col ? 2 : 1); ++b)
                    spectrum[size_t(ry[a]) * size_t(fine.cols) + size_t(rx[b])] += v;
        }
    }
    out = ComplexPlane(fine.rows, fine.cols);
    fft_inverse_complex(fine.rows, fine.cols, spectrum.data(), out.v.data());
}

double highpass_variance(const Complexes& x, const PyramidGeometry& g) {
    const PyramidGrid& grid = g.grids[0];
    const int half_cols = grid.cols / 2 + 1;
    double sum = 0.0;
    for (int ky = 0; ky < grid.rows; ++ky)
        for (int kx = 0; kx < half_cols; ++kx) {
            const size_t i = size_t(ky) * size_t(half_cols) + size_t(kx);
            // Columns 1 … cols/2 − 1 stand for their mirrors too.
            const double weight = (kx == 0 || kx == grid.cols / 2) ? 1.0 : 2.0;
            sum += weight * std::norm(x[i] * grid.high[i]);
        }
    const double n = double(grid.pixels());
    return sum / (n * n);
}

Plane collapse_pyramid(const Pyramid& p, const PyramidGeometry& g) {
    const PyramidGrid& low = g.grids[size_t(g.scales)];
    Complexes spectrum = real_spectrum(p.lowpass);
    for (size_t i = 0; i < spectrum.size(); ++i) spectrum[i] *= low.low[i];
    std::vector<Complexes> real_band(static_cast<size_t>(g.orientations));
    for (int s = g.scales - 1; s >= 0; --s) {
        const PyramidGrid& grid = g.grids[size_t(s)];
        Complexes fine(half_size(grid.rows, grid.cols), cfloat(0.0f));
        // Coarse spectra are scaled to this grid's sample count: ×4 per octave.
        expand_spectrum(spectrum, grid.rows / 2, grid.cols / 2, fine, 4.0f);
        Plane re(grid.rows, grid.cols);
        for (int o = 0; o < g.orientations; ++o) {
            const ComplexPlane& band = p.bands[size_t(s * g.orientations + o)];
            for (size_t i = 0; i < re.size(); ++i) re.v[i] = band.v[i].real();
            real_band[size_t(o)] = real_spectrum(re);
        }
        add_band_reconstruction(real_band, s, g, fine);
        spectrum = std::move(fine);
    }
    const Complexes high = real_spectrum(p.highpass);
    for (size_t i = 0; i < spectrum.size(); ++i) spectrum[i] += high[i] * g.grids[0].high[i];
    Plane image(g.rows, g.cols);
    fft_inverse_real(g.rows, g.cols, spectrum.data(), image.v.data());
    const float inv = 1.0f / float(g.grids[0].pixels());
    for (float& v : image.v) v *= inv;
    return image;
}

}  // namespace lw::synth
