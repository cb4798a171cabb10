// slam_synth/steerable_pyramid.h — the complex steerable pyramid of Portilla & Simoncelli
// (2000, §2; textureSynth's buildSCFpyr), built in the Fourier domain with periodic
// boundaries.
//
// Input: a real image rows × cols, both divisible by 2^(scales+1). Output: a real high-pass
// residual (rows × cols), `scales` × `orientations` complex oriented bands (scale s is
// rows/2^s × cols/2^s) and a real low-pass residual (rows/2^scales × cols/2^scales).
// Radial filters (r: frequency normalized to 1 at Nyquist along each axis, local to a scale's
// grid): H(r) = cos(π/2·log2 r) on [1/2, 1] (1 above, 0 below), L(r) = √(1 − H²); band
// B(r) = H(2r)·L(r). Angular: A_o(θ) = c·cos^n(θ − πo/N), n = N − 1, c² = 2^2n (n!)² /
// (N (2n)!); the complex band keeps one lobe (2·A_o where cos(θ − πo/N) > 0) times (−i)^n, so
// its real part is the real steerable band. The frame is tight: collapse ∘ build = identity.
//
// Amplitude convention: every band holds the values of the full-resolution filtered image at
// its own samples (textureSynth instead scales scale s by 4^s). So a spectrum computed by a
// forward FFT on a grid of N samples gives back pixels through an inverse FFT divided by N,
// even when it is placed on a finer grid first (see expand_spectrum).
#pragma once

#include <cstdint>
#include <vector>

#include "fft.h"

namespace lw::synth {

// The filters of one grid (scale s: rows/2^s × cols/2^s), sampled once per size.
struct PyramidGrid {
    int rows = 0, cols = 0;
    std::vector<Floats> band_weight;   // [o], full layout rows × cols: 2·A_o·B where cos(θ − θ_o) > 0
    std::vector<Floats> recon_weight;  // [o], half layout: A_o·B (both lobes)
    std::vector<std::vector<int8_t>> analytic;  // [o], full layout: 2, 1 or 0 (one-sided mask)
    Floats low;   // half layout: L(r)
    Floats high;  // half layout: H(r)
    size_t pixels() const { return size_t(rows) * size_t(cols); }
};

struct PyramidGeometry {
    int rows = 0, cols = 0, scales = 0, orientations = 0;
    std::vector<PyramidGrid> grids;  // scales + 1; grids[scales] is the low-pass residual's
    cfloat band_factor{1.0f, 0.0f};  // (−i)^(orientations − 1)
};

// Throws lw::Error when rows or cols are not divisible by 2^(scales+1), or scales < 1,
// or orientations outside 1..8.
[[nodiscard]] PyramidGeometry make_pyramid_geometry(int rows, int cols, int scales, int orientations);

struct Pyramid {
    Plane highpass;
    std::vector<ComplexPlane> bands;  // [s * orientations + o]
    Plane lowpass;
};

// r2c of a real image (half layout).
[[nodiscard]] Complexes real_spectrum(const Plane& image);

// The oriented bands and the low-pass residual from the image's half spectrum `x` (grid 0).
void build_bands(const Complexes& x, const PyramidGeometry& g, Pyramid& out);
[[nodiscard]] Pyramid build_pyramid(const Plane& image, const PyramidGeometry& g);
[[nodiscard]] Plane collapse_pyramid(const Pyramid& pyramid, const PyramidGeometry& g);

// Adds `scale` × the half spectrum `coarse` (grid c) to `fine` (grid c − 1, twice the size
// both ways), zero-padding in frequency; Nyquist rows and columns are split between the
// positive and negative frequencies so that a real image stays real. With scale = 4 the
// result is the expanded image's spectrum in this file's amplitude convention.
void expand_spectrum(const Complexes& coarse, int coarse_rows, int coarse_cols, Complexes& fine, float scale);

// Adds the reconstruction of scale s from the half spectra of its real bands (`real_band`,
// one per orientation, each r2c of Re(band)) to `out` (half layout, grid s).
void add_band_reconstruction(const std::vector<Complexes>& real_band, int s, const PyramidGeometry& g, Complexes& out);

// The analytic (complex) band of orientation o rebuilt from its real part's half spectrum
// on grid s + 1 (textureSynth's one-sided mask), expanded to grid s: the "parent" of scale s.
void expand_analytic(const Complexes& real_band, int s, int o, const PyramidGeometry& g, ComplexPlane& out);

// Mean of hp² for the high-pass residual whose half spectrum is `x`·H on grid 0 (Parseval).
[[nodiscard]] double highpass_variance(const Complexes& x, const PyramidGeometry& g);

}  // namespace lw::synth
