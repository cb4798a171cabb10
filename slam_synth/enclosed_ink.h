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
// identical dots came out with 10–19 hollow elements over their 17 levels on seeds 1–6,
// and more iterations did not remove them. Whether paper is enclosed is a property of the
// whole element that no band or pixel statistic sees. The deficit is the mean over the
// texture of fill(x) − x; the exemplar's is a statistic like the others, and the last
// iteration moves the image toward its fill until its deficit is no more than the
// exemplar's. Exemplars with enclosed paper of their own (a lattice's cells, spatter, a
// scribble's loops, the paper between two lines that run the whole length) keep as much;
// dots and dashes lose their hollow centres.
//
// fill is grey-level hole filling (morphological reconstruction by erosion from the first
// and last rows), computed by priority flood (Vincent 1993; Barnes, Lehman & Mulla 2014): a
// texel's fill is the least, over paths from those rows, of the largest ink on the path.
// Paper flows 4-connected and ink joins 8-connected, as slam_fidelity counts holes (which,
// unlike the fill, leaves out paper that runs the whole length). The fill commutes with
// shifts along the length, and it moves no texel by more than the input's largest change;
// the step as a whole is not smooth in the mean square (a basin's fill follows its lowest
// rim texel, and λ differs from level to level), which is why only the last iteration
// takes it (texture_synthesis.h). The exemplar is measured periodic, as the pyramid
// analysis sees it. Input ink must be finite (the flood orders texels by value).
#pragma once

#include "fft.h"

namespace lw::synth {

[[nodiscard]] Plane fill_enclosed(const Plane& ink);

// Mean of fill_enclosed(ink) − ink over the plane.
[[nodiscard]] double enclosed_deficit(const Plane& ink);

// Moves the plane toward its fill until its deficit is at most `target`: x + λ (fill(x) − x)
// with λ = 1 − target / deficit. The result lies between x and fill(x), so its fill is
// fill(x) again and its deficit is the target (to rounding). A plane at or under the
// target, or with non-finite ink, is left as it is.
void impose_enclosed_deficit(Plane& ink, double target);

}  // namespace lw::synth
