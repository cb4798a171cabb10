#include "texture_synthesis.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "enclosed_ink.h"

namespace lw::synth {

namespace {

// Scales whose low-pass variance is this small against the image's are only rescaled
// (textureSynth's 1e-4 guard on the autocorrelation and marginal adjustments).
constexpr double kNegligibleVariance = 1e-4;

void scale_to_variance(float* x, size_t n, double variance) {
    const Moments m = moments(x, n);
    if (m.variance <= 0.0) return;
    const float f = float(std::sqrt(variance / m.variance));
    for (size_t i = 0; i < n; ++i) x[i] *= f;
}

// Per row r: an affine map to mean[r] and variance[r] (the 1.5D statistics, Bénard et al.
// 2010 §3.2.2). A row without variance takes the target mean.
void impose_row_statistics(Plane& im, const std::vector<double>& target_mean, const std::vector<double>& target_variance) {
    for (int r = 0; r < im.rows; ++r) {
        float* row = &im.v[size_t(r) * size_t(im.cols)];
        double sum = 0.0, squares = 0.0;
#pragma omp simd reduction(+ : sum, squares)
        for (int x = 0; x < im.cols; ++x) {
            sum += double(row[x]);
            squares += double(row[x]) * double(row[x]);
        }
        const double mean = sum / im.cols, variance = std::max(0.0, squares / im.cols - mean * mean);
        const double f = variance > 1e-20 ? std::sqrt(target_variance[size_t(r)] / variance) : 0.0;
        const float scale = float(f), offset = float(target_mean[size_t(r)] - mean * f);
        for (int x = 0; x < im.cols; ++x) row[x] = row[x] * scale + offset;
    }
}

// The low-pass image of one scale from its spectrum (consumed): autocorrelation, then
// skewness and kurtosis, as textureSynth does at every scale. For 1.5D the image's rows then
// take the exemplar's per-row mean and variance at this scale: the paper's "mean and
// variance per row" applied where the model imposes a variance (the autocorrelation's
// centre), not only at the last pixel step. Rows that the exemplar leaves empty or solid
// then stay so at every scale; measured, adjacent levels differ less against the ends
// (RMSE(1)/RMSE(16): dashes 0.353 → 0.241, spatter 0.246 → 0.200, brush equal within seed
// noise, docs/research/slam-fidelity.md) and the identical dots come out more even.
void impose_lowpass(Complexes& spectrum, int s, const TextureStatistics& t, const PyramidGeometry& g, StatisticsScope scope,
                    Plane& im) {
    const PyramidGrid& grid = g.grids[size_t(s)];
    im = Plane(grid.rows, grid.cols);
    const Autocorrelation& target = t.lowpass_autocorrelation[size_t(s)];
    const bool significant = target.center() / t.pixel.variance > kNegligibleVariance;
    if (significant) {
        impose_autocorrelation(spectrum, grid.rows, grid.cols, target, im.v.data());
        impose_skewness(im.v.data(), im.size(), t.lowpass_skewness[size_t(s)]);
        impose_kurtosis(im.v.data(), im.size(), t.lowpass_kurtosis[size_t(s)]);
        if (scope == StatisticsScope::Rows)
            impose_row_statistics(im, t.lowpass_row_mean[size_t(s)], t.lowpass_row_variance[size_t(s)]);
    } else {
        fft_inverse_real(grid.rows, grid.cols, spectrum.data(), im.v.data());
        scale_to_variance(im.v.data(), im.size(), target.center());
    }
}

// The final pixel step, as the authors' code does it: mean and variance (globally, or per
// row for 1.5D), then skewness, kurtosis and range globally. For 1.5D the global steps move
// the rows' means and variances by up to 10 % on inky exemplars (the range clamp most), so
// three alternations of range and per-row mean/variance follow, ending on the rows (within
// 5 % of the exemplar's, measured in tests/test_slam_synth.cpp; on the last iteration one
// enclosed fill comes after, below); the last clamp is left to
// the caller (slam_builder stores ink clamped to [0, 1]). On the last iteration whole
// elements join the alternations, after each clamp: first their sizes (element_sizes.h:
// fragments erased, merged pairs split, thin hooks trimmed), then the enclosed paper
// (enclosed_ink.h), which fills any pocket a cut or an erasure closed. The rows then put
// back the means these move (by a fifth on the sparse edge rows of a row of dots), and
// the next fill closes what a row step reopened (2 hollow dashes on one seed of six with
// the fill taken once, 0 this way).
void impose_pixel_statistics(Plane& im, const TextureStatistics& t, StatisticsScope scope, bool last) {
    const auto clamp_range = [&] {
        for (float& v : im.v) v = std::clamp(v, float(t.pixel.min), float(t.pixel.max));
    };
    if (scope == StatisticsScope::Global) {
        const Moments m = moments(im.v.data(), im.size());
        const double f = m.variance > 0.0 ? std::sqrt(t.pixel.variance / m.variance) : 0.0;
        for (float& v : im.v) v = float((v - m.mean) * f + t.pixel.mean);
    } else {
        impose_row_statistics(im, t.row_mean, t.row_variance);
    }
    impose_skewness(im.v.data(), im.size(), t.pixel.skewness);
    impose_kurtosis(im.v.data(), im.size(), t.pixel.kurtosis);
    const auto enclosed_fill = [&] { impose_enclosed_deficit(im, t.enclosed_deficit, enclosed_basin_texels(t.neighborhood)); };
    const auto whole_elements = [&] {
        if (!last) return;
        impose_element_sizes(im, t.elements, float(t.pixel.min), t.neighborhood / 2);
        enclosed_fill();
    };
    clamp_range();
    whole_elements();
    if (scope == StatisticsScope::Rows)
        for (int k = 0; k < 3; ++k) {
            if (k > 0) {
                clamp_range();
                whole_elements();
            }
            impose_row_statistics(im, t.row_mean, t.row_variance);
        }
    // The last row step can leave a basin a hair under the element threshold: once more the
    // fill (a few texels by ~0.01; the rows stay within 5 %). Seed 4 of the identical dots had
    // one such pocket of three texels at 0.495 (a hole by the measure), and none since.
    if (last && scope == StatisticsScope::Rows) enclosed_fill();
}

std::vector<const float*> pointers(const std::vector<Floats>& columns) {
    std::vector<const float*> out;
    for (const Floats& c : columns) out.push_back(c.data());
    return out;
}

// The high-pass residual of the image whose spectrum is `x`, added to `result`: only
// lowered to the target variance, never raised (textureSynth), and reconstructed through H
// once more, as every band is (the pyramid's residual is X·H, its share of the image X·H²;
// X·H alone let the image through with a gain of L² + H > 1 in the transition band, so
// even the exemplar was not a fixed point).
void add_highpass(const Complexes& x, const TextureStatistics& t, const PyramidGeometry& g, Complexes& result) {
    const double hp = highpass_variance(x, g);
    const float hp_scale = hp > t.highpass_variance ? float(std::sqrt(t.highpass_variance / hp)) : 1.0f;
    const Floats& high = g.grids[0].high;
    for (size_t i = 0; i < result.size(); ++i) result[i] += x[i] * (high[i] * high[i] * hp_scale);
}

// One iteration (textureSynth's main loop body). The last one keeps the high-pass residual
// and imposes the enclosed paper (texture_synthesis.h says why).
void iterate(Plane& im, const TextureStatistics& t, const PyramidGeometry& g, StatisticsScope scope, bool last) {
    const int scales = g.scales, n = g.orientations;
    const Complexes x = real_spectrum(im);
    Pyramid pyr;
    build_bands(x, g, pyr);

    // Coarsest scale: the low-pass residual without its mean, filtered by L.
    const Moments low = moments(pyr.lowpass.v.data(), pyr.lowpass.size());
    for (float& v : pyr.lowpass.v) v -= float(low.mean);
    Complexes spectrum = real_spectrum(pyr.lowpass);
    for (size_t i = 0; i < spectrum.size(); ++i) spectrum[i] *= g.grids[size_t(scales)].low[i];
    Plane lowpass;
    impose_lowpass(spectrum, scales, t, g, scope, lowpass);

    // Magnitudes without their current means (the targets' means are put back below).
    std::vector<Floats> magnitude(static_cast<size_t>(scales * n));
    for (int b = 0; b < scales * n; ++b) {
        const ComplexPlane& band = pyr.bands[size_t(b)];
        Floats& mag = magnitude[size_t(b)];
        mag.resize(band.size());
        double sum = 0.0;
        for (size_t i = 0; i < band.size(); ++i) sum += mag[i] = magnitude_of(band.v[i]);
        const float mean = float(sum / double(band.size()));
        for (float& v : mag) v -= mean;
    }

    Parents parents;
    std::vector<Complexes> real_spectra(static_cast<size_t>(n));
    for (int s = scales - 1; s >= 0; --s) {
        const PyramidGrid& grid = g.grids[size_t(s)];
        const size_t count = grid.pixels();
        // Magnitudes: correlations across orientations (and with the parents), then each
        // band's autocorrelation; the band keeps its phase and takes the new magnitude.
        std::vector<float*> mags;
        for (int o = 0; o < n; ++o) mags.push_back(magnitude[size_t(s * n + o)].data());
        if (s == scales - 1)
            impose_correlation(mags, count, t.cross_orientation[size_t(s)]);
        else
            impose_correlation_with(mags, fixed_columns(pointers(parents.magnitude), count), count,
                                    t.cross_orientation[size_t(s)], t.parent_magnitude[size_t(s)]);
        std::vector<Floats> real_parts(static_cast<size_t>(n));
        for (int o = 0; o < n; ++o) {
            const int b = s * n + o;
            Floats& mag = magnitude[size_t(b)];
            Complexes mag_spectrum(half_size(grid.rows, grid.cols));
            fft_forward_real(grid.rows, grid.cols, mag.data(), mag_spectrum.data());
            impose_autocorrelation(mag_spectrum, grid.rows, grid.cols, t.magnitude_autocorrelation[size_t(b)], mag.data());
            ComplexPlane& band = pyr.bands[size_t(b)];
            Floats& re = real_parts[size_t(o)];
            re.resize(count);
            const float mean = float(t.magnitude_means[size_t(b)]);
            for (size_t i = 0; i < count; ++i) {
                const float target = std::max(0.0f, mag[i] + mean), current = magnitude_of(band.v[i]);
                band.v[i] *= target / (current < 1e-20f ? 1.0f : current);
                re[i] = band.v[i].real();
            }
        }
        // Real parts: cross-scale phase statistics, each orientation on its own (its own
        // variance kept, only its correlation with the parents imposed).
        if (s < scales - 1) {
            const FixedColumns pr = fixed_columns(pointers(parents.real), count);
            for (int o = 0; o < n; ++o) {
                const Matrix own = gram({real_parts[size_t(o)].data()}, {real_parts[size_t(o)].data()}, count);
                Matrix cross(1, 2 * n);
                for (int j = 0; j < 2 * n; ++j) cross(0, j) = t.parent_real[size_t(s)](o, j);
                impose_correlation_with({real_parts[size_t(o)].data()}, pr, count, own, cross);
            }
        }
        for (int o = 0; o < n; ++o) {
            real_spectra[size_t(o)].resize(half_size(grid.rows, grid.cols));
            fft_forward_real(grid.rows, grid.cols, real_parts[size_t(o)].data(), real_spectra[size_t(o)].data());
        }
        // This scale's low-pass image: the coarser one expanded plus the new bands.
        Complexes coarse = real_spectrum(lowpass);
        Complexes fine(half_size(grid.rows, grid.cols), cfloat(0.0f));
        expand_spectrum(coarse, lowpass.rows, lowpass.cols, fine, 4.0f);
        add_band_reconstruction(real_spectra, s, g, fine);
        impose_lowpass(fine, s, t, g, scope, lowpass);
        // The analytic bands rebuilt from the new real parts, as parents of the next scale.
        if (s > 0) parents = make_parents(real_spectra, s - 1, g);
    }

    Complexes result = real_spectrum(lowpass);
    if (last) add_highpass(x, t, g, result);
    fft_inverse_real(g.rows, g.cols, result.data(), im.v.data());
    const float inv = 1.0f / float(g.grids[0].pixels());
    for (float& v : im.v) v *= inv;
    impose_pixel_statistics(im, t, scope, last);
}

}  // namespace

Plane synthesize_texture(const TextureStatistics& target, const Plane& seed, const PyramidGeometry& g,
                         const SynthesisDesc& desc) {
    if (seed.rows != g.rows || seed.cols != g.cols) throw Error("synthesize_texture: seed size does not match the geometry");
    if (target.scales != g.scales || target.orientations != g.orientations)
        throw Error("synthesize_texture: statistics and pyramid have different scales or orientations");
    if (desc.scope == StatisticsScope::Rows) {
        bool rows_match = int(target.row_mean.size()) == seed.rows && int(target.lowpass_row_mean.size()) == g.scales + 1;
        for (int s = 0; rows_match && s <= g.scales; ++s)
            rows_match = int(target.lowpass_row_mean[size_t(s)].size()) == g.grids[size_t(s)].rows;
        if (!rows_match) throw Error("synthesize_texture: per-row statistics need the exemplar's row count");
    }
    Plane im = seed;
    for (int i = 0; i < desc.iterations; ++i) {
        iterate(im, target, g, desc.scope, i + 1 == desc.iterations);
        if (desc.on_iteration) desc.on_iteration(i, im);
    }
    return im;
}

}  // namespace lw::synth
