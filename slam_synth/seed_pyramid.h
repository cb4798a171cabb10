// slam_synth/seed_pyramid.h — the synthesis seeds of a SLAM (Bénard et al. 2010 §3.2.1).
//
// W_source: uniform white noise, `rows` × `length` (Lmax). W_f: W_source filtered along the
// length only by a Gaussian of width 5 texels, its full width at half maximum (σ = 5 /
// (2√(2 ln 2)) ≈ 2.12, taps out to 3σ, periodic: it keeps the seeds from aliasing when they
// are scaled), then histogram-matched back to uniform on
// (0, 1) (rank r of n ↦ (r + ½)/n). W_0.5: W_f scaled to half its length; W_1.0 = [W_0.5 W_0.5];
// W_l = α·W_1.0 + (1 − α)·W_0.5 with α = 2l − 1, both scaled to the level's length. Scaling is
// band-limited (FFT) resampling, so one seed at two lengths is one periodic function (below
// the shorter length's Nyquist frequency) sampled at two rates; linear interpolation would
// blur it by an amount that depends on where the samples fall, a difference between
// adjacent levels that does not shrink with their spacing. Self-similarity and smooth
// variation hold by construction; slam_builder.h synthesizes each A_l from W_l (A_1.0 as
// A_0.5 twice, what that synthesis gives). Deterministic for a given seed.
#pragma once

#include <cstdint>

#include "fft.h"

namespace lw::synth {

// W_f (rows × length).
[[nodiscard]] Plane filtered_seed(int rows, int length, uint32_t seed);

// Periodic linear resampling along the rows: output texel x samples the input at
// x·in.cols/cols (so equal lengths copy exactly, and halving keeps the even texels).
[[nodiscard]] Plane resample_length(const Plane& in, int cols);

// Periodic band-limited resampling along the rows (FFT: spectrum truncated or zero-padded,
// the Nyquist term as scipy.signal.resample treats it). Equal lengths copy exactly.
[[nodiscard]] Plane fourier_resample_length(const Plane& in, int cols);

// [in in]: the rows repeated once along the length.
[[nodiscard]] Plane tile_twice(const Plane& in);

// W_0.5: W_f (rows × length) scaled to length/2.
[[nodiscard]] Plane half_seed(int rows, int length, uint32_t seed);

// W_l at `cols` texels from W_0.5.
[[nodiscard]] Plane seed_level(const Plane& half, double level, int cols);

}  // namespace lw::synth
