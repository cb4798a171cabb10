// slam_synth/texture_statistics.h — the statistics of the Portilla–Simoncelli texture model
// (2000, §3; textureSynth's textureAnalysis), gathered from one image, and how close two
// sets are (textureSynth's per-group signal-to-noise ratios).
//
// Input: a real image whose size suits the pyramid geometry (steerable_pyramid.h). Output:
// - pixel marginals: mean, variance, skewness, kurtosis, min, max; and per row mean and
//   variance (the 1.5D statistics of Bénard et al. 2010 §3.2.2);
// - per scale s = scales … 0 of the partially reconstructed low-pass image (low-pass
//   residual plus the bands of scales ≥ s): skewness, kurtosis and central autocorrelation,
//   and its per-row mean and variance (1.5D, imposed with the low-pass image's
//   autocorrelation, texture_synthesis.h);
// - per band: the mean of the magnitudes and the central autocorrelation of the
//   mean-removed magnitudes;
// - per scale: the cross-orientation correlation of magnitudes; the cross-scale correlation
//   of magnitudes with the parents (the coarser scale's bands expanded to this grid, phase
//   doubled), and of the real parts with the parents' real and imaginary parts;
// - the high-pass residual's variance.
// Autocorrelations are (2h+1)² with h = min((Na − 1)/2, what the grid allows,
// adjustments.h). The statistics that textureSynth computes but never imposes (real
// cross-orientation correlations, the low-pass band's phase statistics) are left out.
#pragma once

#include <string>
#include <vector>

#include "adjustments.h"
#include "element_sizes.h"
#include "small_linalg.h"
#include "steerable_pyramid.h"

namespace lw::synth {

struct TextureStatistics {
    int scales = 0, orientations = 0, neighborhood = 0;  // Na
    Moments pixel;
    std::vector<double> row_mean, row_variance;  // [row]
    std::vector<double> lowpass_skewness, lowpass_kurtosis;  // [scale], scales + 1
    std::vector<Autocorrelation> lowpass_autocorrelation;    // [scale], scales + 1
    std::vector<std::vector<double>> lowpass_row_mean, lowpass_row_variance;  // [scale][row of that grid]
    std::vector<double> magnitude_means;                     // [s * orientations + o]
    std::vector<Autocorrelation> magnitude_autocorrelation;  // [s * orientations + o]
    std::vector<Matrix> cross_orientation;  // [s], orientations²
    std::vector<Matrix> parent_magnitude;   // [s], s < scales − 1: orientations × orientations
    std::vector<Matrix> parent_real;        // [s], s < scales − 1: orientations × 2·orientations
    double highpass_variance = 0;
    double enclosed_deficit = 0;  // enclosed_ink.h: paper enclosed by ink, basins of at most Na² texels
    ElementSizes elements;        // element_sizes.h: the smallest and largest element
};

// The largest basin of enclosed paper that the statistic counts (enclosed_ink.h says why).
constexpr int enclosed_basin_texels(int neighborhood) { return neighborhood * neighborhood; }

[[nodiscard]] TextureStatistics analyze_texture(const Plane& image, const PyramidGeometry& g, int neighborhood = 9);

// The parents of scale s from the half spectra of the real parts of scale s + 1's bands:
// magnitudes (mean removed) and the real and imaginary parts of the phase-doubled bands
// (z²/|z|), each a column of grid s.
struct Parents {
    std::vector<Floats> magnitude;  // [o]
    std::vector<Floats> real;       // [2 · orientations]: Re then Im
};
[[nodiscard]] Parents make_parents(const std::vector<Complexes>& coarse_real_spectra, int s, const PyramidGeometry& g);

// Per-row mean and variance of an image.
void row_moments(const Plane& image, std::vector<double>& mean, std::vector<double>& variance);

// textureSynth reports, per statistic group, SNR = 20·log10(‖target‖ / ‖target − value‖) dB.
struct StatisticGroup {
    std::string name;
    double snr_db = 0;  // +inf when equal
};
inline constexpr const char* kStatisticGroups[] = {
    "pixel marginals", "row mean/variance", "low-pass skew/kurtosis", "low-pass autocorrelation",
    "magnitude means", "magnitude autocorrelation", "cross-orientation magnitude", "cross-scale magnitude",
    "cross-scale phase", "high-pass variance"};
// Throws lw::Error when the two sets come from different models or row counts.
[[nodiscard]] std::vector<StatisticGroup> compare_statistics(const TextureStatistics& target,
                                                             const TextureStatistics& value);

}  // namespace lw::synth
