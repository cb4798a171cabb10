#include "texture_statistics.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "enclosed_ink.h"

namespace lw::synth {

namespace {

// Skewness and kurtosis of a low-pass image, neutral when its variance is negligible
// against the image's (textureSynth's 1e-6 guard).
void lowpass_marginals(const Plane& im, double image_variance, double& skewness, double& kurtosis) {
    const Moments m = moments(im.v.data(), im.size());
    const bool significant = image_variance > 0.0 && m.variance / image_variance > 1e-6;
    skewness = significant ? m.skewness : 0.0;
    kurtosis = significant ? m.kurtosis : 3.0;
}

Plane inverse(Complexes spectrum, int rows, int cols) {
    Plane im(rows, cols);
    fft_inverse_real(rows, cols, spectrum.data(), im.v.data());
    const float inv = 1.0f / (float(rows) * float(cols));
    for (float& v : im.v) v *= inv;
    return im;
}

}  // namespace

void row_moments(const Plane& image, std::vector<double>& mean, std::vector<double>& variance) {
    mean.assign(size_t(image.rows), 0.0);
    variance.assign(size_t(image.rows), 0.0);
    for (int r = 0; r < image.rows; ++r) {
        const Moments m = moments(&image.v[size_t(r) * size_t(image.cols)], size_t(image.cols));
        mean[size_t(r)] = m.mean;
        variance[size_t(r)] = m.variance;
    }
}

Parents make_parents(const std::vector<Complexes>& coarse_real_spectra, int s, const PyramidGeometry& g) {
    const int n = g.orientations;
    Parents p;
    p.magnitude.resize(size_t(n));
    p.real.resize(size_t(2 * n));
    ComplexPlane parent;
    for (int o = 0; o < n; ++o) {
        expand_analytic(coarse_real_spectra[size_t(o)], s, o, g, parent);
        Floats& mag = p.magnitude[size_t(o)];
        Floats& re = p.real[size_t(o)];
        Floats& im = p.real[size_t(n + o)];
        mag.resize(parent.size());
        re.resize(parent.size());
        im.resize(parent.size());
        double sum = 0.0;
        for (size_t i = 0; i < parent.size(); ++i) {
            // Phase doubling, z²/|z|: the parent's phase then varies as fast as the child's.
            const float a = parent.v[i].real(), b = parent.v[i].imag(), m = std::sqrt(a * a + b * b);
            const float inv = m > 0.0f ? 1.0f / m : 0.0f;
            mag[i] = m;
            sum += m;
            re[i] = (a * a - b * b) * inv;
            im[i] = 2.0f * a * b * inv;
        }
        const float mean = float(sum / double(parent.size()));
        for (float& v : mag) v -= mean;
    }
    return p;
}

TextureStatistics analyze_texture(const Plane& image, const PyramidGeometry& g, int neighborhood) {
    if (image.rows != g.rows || image.cols != g.cols) throw Error("analyze_texture: image size does not match the geometry");
    const int scales = g.scales, n = g.orientations, limit = (neighborhood - 1) / 2;
    TextureStatistics t;
    t.scales = scales;
    t.orientations = n;
    t.neighborhood = neighborhood;
    t.pixel = moments(image.v.data(), image.size());
    row_moments(image, t.row_mean, t.row_variance);
    t.enclosed_deficit = enclosed_deficit(image, enclosed_basin_texels(neighborhood));
    t.elements = element_sizes(image);

    const Complexes x = real_spectrum(image);
    Pyramid pyr;
    build_bands(x, g, pyr);
    t.highpass_variance = highpass_variance(x, g);

    // Low-pass residual without its mean, filtered once more by L (its reconstruction filter).
    const Moments low = moments(pyr.lowpass.v.data(), pyr.lowpass.size());
    for (float& v : pyr.lowpass.v) v -= float(low.mean);
    const PyramidGrid& lowest = g.grids[size_t(scales)];
    Complexes spectrum = real_spectrum(pyr.lowpass);
    for (size_t i = 0; i < spectrum.size(); ++i) spectrum[i] *= lowest.low[i];

    t.lowpass_skewness.assign(size_t(scales) + 1, 0.0);
    t.lowpass_kurtosis.assign(size_t(scales) + 1, 3.0);
    t.lowpass_autocorrelation.resize(size_t(scales) + 1);
    t.lowpass_row_mean.resize(size_t(scales) + 1);
    t.lowpass_row_variance.resize(size_t(scales) + 1);
    auto lowpass_statistics = [&](int s) {
        const PyramidGrid& grid = g.grids[size_t(s)];
        t.lowpass_autocorrelation[size_t(s)] =
            central_autocorrelation(spectrum, grid.rows, grid.cols, autocorrelation_half(grid.rows, grid.cols, limit));
        const Plane lowpass = inverse(spectrum, grid.rows, grid.cols);
        row_moments(lowpass, t.lowpass_row_mean[size_t(s)], t.lowpass_row_variance[size_t(s)]);
        lowpass_marginals(lowpass, t.pixel.variance, t.lowpass_skewness[size_t(s)], t.lowpass_kurtosis[size_t(s)]);
    };
    lowpass_statistics(scales);

    // Magnitudes without their means.
    std::vector<Floats> magnitude(static_cast<size_t>(scales * n));
    t.magnitude_means.resize(size_t(scales * n));
    t.magnitude_autocorrelation.resize(size_t(scales * n));
    for (int b = 0; b < scales * n; ++b) {
        const ComplexPlane& band = pyr.bands[size_t(b)];
        Plane mag(band.rows, band.cols);
        double sum = 0.0;
        for (size_t i = 0; i < band.size(); ++i) sum += mag.v[i] = magnitude_of(band.v[i]);
        const double mean = sum / double(band.size());
        for (float& v : mag.v) v -= float(mean);
        t.magnitude_means[size_t(b)] = mean;
        t.magnitude_autocorrelation[size_t(b)] = central_autocorrelation(
            real_spectrum(mag), band.rows, band.cols, autocorrelation_half(band.rows, band.cols, limit));
        magnitude[size_t(b)] = std::move(mag.v);
    }

    t.cross_orientation.resize(size_t(scales));
    t.parent_magnitude.resize(size_t(scales));
    t.parent_real.resize(size_t(scales));
    std::vector<Complexes> real_spectra(static_cast<size_t>(n)), coarser_real_spectra;
    for (int s = scales - 1; s >= 0; --s) {
        const PyramidGrid& grid = g.grids[size_t(s)];
        const size_t count = grid.pixels();
        std::vector<const float*> mags, reals;
        std::vector<Floats> real_parts(static_cast<size_t>(n));
        for (int o = 0; o < n; ++o) {
            const ComplexPlane& band = pyr.bands[size_t(s * n + o)];
            Plane re(band.rows, band.cols);
            for (size_t i = 0; i < band.size(); ++i) re.v[i] = band.v[i].real();
            real_spectra[size_t(o)] = real_spectrum(re);
            real_parts[size_t(o)] = std::move(re.v);
            mags.push_back(magnitude[size_t(s * n + o)].data());
            reals.push_back(real_parts[size_t(o)].data());
        }
        t.cross_orientation[size_t(s)] = gram(mags, mags, count);
        if (s < scales - 1) {
            const Parents parents = make_parents(coarser_real_spectra, s, g);
            std::vector<const float*> pm, pr;
            for (const Floats& f : parents.magnitude) pm.push_back(f.data());
            for (const Floats& f : parents.real) pr.push_back(f.data());
            t.parent_magnitude[size_t(s)] = gram(mags, pm, count);
            t.parent_real[size_t(s)] = gram(reals, pr, count);
        }
        Complexes fine(half_size(grid.rows, grid.cols), cfloat(0.0f));
        expand_spectrum(spectrum, grid.rows / 2, grid.cols / 2, fine, 4.0f);
        add_band_reconstruction(real_spectra, s, g, fine);
        spectrum = std::move(fine);
        lowpass_statistics(s);
        coarser_real_spectra = real_spectra;
    }
    return t;
}

namespace {

// Accumulates Σ target² and Σ (target − value)² of one group.
struct Energy {
    double signal = 0, noise = 0;
    void add(double target, double value) {
        signal += target * target;
        noise += (target - value) * (target - value);
    }
    void add(const std::vector<double>& target, const std::vector<double>& value) {
        if (target.size() != value.size()) throw Error("compare_statistics: statistics of different sizes");
        for (size_t i = 0; i < target.size(); ++i) add(target[i], value[i]);
    }
    double snr_db() const {
        if (noise == 0.0) return std::numeric_limits<double>::infinity();
        return 10.0 * std::log10(signal / noise);
    }
};

}  // namespace

std::vector<StatisticGroup> compare_statistics(const TextureStatistics& t, const TextureStatistics& v) {
    if (t.scales != v.scales || t.orientations != v.orientations || t.neighborhood != v.neighborhood ||
        t.row_mean.size() != v.row_mean.size())
        throw Error("compare_statistics: the two textures were analyzed with different models or heights");
    Energy e[10];
    const Moments& a = t.pixel;
    const Moments& b = v.pixel;
    e[0].add({a.mean, a.variance, a.skewness, a.kurtosis, a.min, a.max},
             {b.mean, b.variance, b.skewness, b.kurtosis, b.min, b.max});
    e[1].add(t.row_mean, v.row_mean);
    e[1].add(t.row_variance, v.row_variance);
    e[2].add(t.lowpass_skewness, v.lowpass_skewness);
    e[2].add(t.lowpass_kurtosis, v.lowpass_kurtosis);
    for (size_t s = 0; s < t.lowpass_autocorrelation.size(); ++s)
        e[3].add(t.lowpass_autocorrelation[s].values, v.lowpass_autocorrelation[s].values);
    e[4].add(t.magnitude_means, v.magnitude_means);
    for (size_t b2 = 0; b2 < t.magnitude_autocorrelation.size(); ++b2)
        e[5].add(t.magnitude_autocorrelation[b2].values, v.magnitude_autocorrelation[b2].values);
    for (size_t s = 0; s < t.cross_orientation.size(); ++s) {
        e[6].add(t.cross_orientation[s].a, v.cross_orientation[s].a);
        e[7].add(t.parent_magnitude[s].a, v.parent_magnitude[s].a);
        e[8].add(t.parent_real[s].a, v.parent_real[s].a);
    }
    e[9].add(t.highpass_variance, v.highpass_variance);
    std::vector<StatisticGroup> groups;
    for (int i = 0; i < 10; ++i) groups.push_back({kStatisticGroups[i], e[i].snr_db()});
    return groups;
}

}  // namespace lw::synth
