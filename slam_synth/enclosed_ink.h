// slam_synth/enclosed_ink.h — paper enclosed by ink, as one more statistic of a stroke
// texture.
//
// Input: an ink plane, periodic along its columns (the padded images of the synthesis,
// whose first and last rows are paper). Output: the plane with every basin of paper that
// ink encloses filled to its spill level; the mean of what that fill adds (the enclosed
// deficit); and the step that imposes an exemplar's deficit on a synthesized image.
//
// Why (issue 20, docs/research/slam-fidelity.md "Hollow dots"): Portilla–Simoncelli's
// statistics are local and of second order, and a dot with a pale centre has nearly the
// statistics of a solid one, so hollow dots are admissible fixed points of the model: the
// identical dots came out with 0–2 hollow elements on 11 of 17 levels whatever the seed,
// and more iterations did not remove them. Whether paper is enclosed is a property of the
// whole element that no band or pixel statistic sees. The deficit is the mean over the
// texture of fill(x) − x; the exemplar's is a statistic like the others, and the last
// iteration moves the image toward its fill until its deficit is no more than the
// exemplar's (an upper bound, as the high-pass variance is). Exemplars with enclosed paper
// of their own (a lattice, spatter, a scribble) keep theirs; dots and dashes lose their
// hollow centres.
//
// fill is grey-level hole filling (morphological reconstruction by erosion from the first
// and last rows), computed by priority flood (Vincent 1993; Barnes, Lehman & Mulla 2014): a
// texel's fill is the least, over paths from those rows, of the largest ink on the path.
// Paper flows 4-connected (ink 8-connected), as slam_fidelity counts holes. The fill is
// monotone and moves no texel by more than the largest change of the input, so adjacent
// levels stay as close as they were (smooth variation, Bénard et al. 2010 §3.2); it commutes
// with shifts along the length, so the tiled top level stays A_0.5 twice. The exemplar is
// measured periodic too, as the pyramid analysis sees it.
#pragma once

#include "fft.h"

namespace lw::synth {

[[nodiscard]] Plane fill_enclosed(const Plane& ink);

// Mean of fill_enclosed(ink) − ink over the plane.
[[nodiscard]] double enclosed_deficit(const Plane& ink);

// Moves the plane toward its fill until its deficit is at most `target`: x + λ (fill(x) − x)
// with λ = 1 − target / deficit. The fill of that is fill(x) again, so the deficit becomes
// exactly the target. A plane at or under the target is left as it is.
void impose_enclosed_deficit(Plane& ink, double target);

}  // namespace lw::synth
