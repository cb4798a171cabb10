// slam_synth/enclosed_ink.h — paper enclosed by ink, as one more statistic of a stroke
// texture.
//
// Input: an ink plane, periodic along its columns (the padded images of the synthesis,
// whose first and last rows are paper). Output: the plane with its basins of enclosed
// paper filled to their spill level (all, or those of at most a given area); the mean of
// what that fill adds (the enclosed deficit); and the step that imposes an exemplar's
// deficit on a synthesized image.
//
// Why (issue 20, docs/research/slam-fidelity.md "Hollow dots"): Portilla–Simoncelli's
// statistics are local and of second order, and a dot with a pale centre has nearly the
// statistics of a solid one, so hollow dots are admissible fixed points of the model: the
// identical dots came out with 10–19 hollow elements over their 17 levels on seeds 1–6,
// and more iterations did not remove them. Whether paper is enclosed is a property of the
// whole element that no band or pixel statistic sees. The deficit is the mean over the
// plane of fill(x) − x in the basins counted (0 elsewhere); the exemplar's is a statistic
// like the others, and the last iteration moves the image toward its fill until its
// deficit is no more than the exemplar's. Dots and dashes (deficit 0) lose their hollow
// centres; scribble and spatter keep small loops of their own (0.0072, 0.0179).
//
// Only basins of at most Na² texels (81, the model's autocorrelation neighbourhood) are
// counted and filled, in the exemplar's figure and in the step alike. Why a bound: a
// basin's fill follows its lowest rim texel, so one texel's change moves the whole basin;
// over all basins, adjacent levels of the brush exemplar differed 5.9 % more
// (RMSE(1)/RMSE(16), seeds 1–8), and within the bound they differ as without the step.
// Why Na²: bounds of 16, 64 and 81 measured the same; from 128 the bound starts to cut
// into the lattice's cells (RMSE ratio 0.377 → 0.381 at 128, 0.474 at 256), so Na² is a
// choice inside the range that measured the same, not a tuned value. A hard bound leaves
// hollows over 81 texels, and a small hollow joined to a larger enclosed area, as they were.
//
// fill is grey-level hole filling (morphological reconstruction by erosion from the first
// and last rows), computed by priority flood (Vincent 1993; Barnes, Lehman & Mulla 2014): a
// texel's fill is the least, over paths from those rows, of the largest ink on the path.
// A basin is a 4-connected set of texels that the fill raises. Paper flows 4-connected and
// ink joins 8-connected, as slam_fidelity counts holes. fill_enclosed commutes with shifts
// along the length and moves no texel by more than the input's largest change (the bound
// adds a jump where a basin crosses it). The exemplar is measured periodic, as the pyramid
// analysis sees it. Input ink must be finite (the flood orders texels by value).
#pragma once

#include "fft.h"

namespace lw::synth {

[[nodiscard]] Plane fill_enclosed(const Plane& ink);

// ink with every basin of at most `max_texels` texels filled (the others as they are).
[[nodiscard]] Plane fill_small_basins(const Plane& ink, int max_texels);

// Mean of fill_small_basins(ink, max_texels) − ink over the plane.
[[nodiscard]] double enclosed_deficit(const Plane& ink, int max_texels);

// Moves the plane toward fill_small_basins until its deficit is at most `target`:
// x + λ (fill − x) with λ = 1 − target / deficit. The result lies between x and its fill,
// with the same basins or pieces of them (rounding may split one), so its deficit is the
// target (to rounding). A plane at or under
// the target, or with non-finite ink, is left as it is.
void impose_enclosed_deficit(Plane& ink, double target, int max_texels);

}  // namespace lw::synth
